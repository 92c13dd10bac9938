// texfilter/ewa.glsl — STUB (being written).
#ifndef TF_EWA_GLSL
#define TF_EWA_GLSL
#include "trilinear.glsl"
vec4 tf_ewa(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso)
{
    return tf_trilinear(tex, uv, dUVdx, dUVdy, s);
}
vec4 tf_ewa_hw(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso)
{
    return tf_trilinear(tex, uv, dUVdx, dUVdy, s);
}
#endif
