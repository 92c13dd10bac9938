// texfilter/aniso.glsl — STUB (being written).
#ifndef TF_ANISO_GLSL
#define TF_ANISO_GLSL
#include "trilinear.glsl"
#define TF_ANISO_GPU 0
#define TF_ANISO_FELINE 1
vec4 tf_aniso(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape)
{
    return tf_trilinear(tex, uv, dUVdx, dUVdy, s);
}
vec4 tf_aniso_hw(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape)
{
    return tf_trilinear(tex, uv, dUVdx, dUVdy, s);
}
#endif
