// texfilter/sat.glsl — STUB (being written).
#ifndef TF_SAT_GLSL
#define TF_SAT_GLSL
#include "common.glsl"
vec4 tf_sat(usampler2D satLow, usampler2D satHigh, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float scale)
{
    return vec4(texelFetch(satLow, ivec2(0), 0) + texelFetch(satHigh, ivec2(0), 0)) * scale;
}
vec4 tf_sat_assembly(usampler2D satLow, usampler2D satHigh, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s,
                     float scale, int boxes)
{
    return tf_sat(satLow, satHigh, uv, dUVdx, dUVdy, s, scale);
}
#endif
