// texfilter/brilinear.glsl — STUB (being written).
#ifndef TF_BRILINEAR_GLSL
#define TF_BRILINEAR_GLSL
#include "trilinear.glsl"
vec4 tf_brilinear(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float band)
{
    return tf_trilinear(tex, uv, dUVdx, dUVdy, s);
}
#endif
