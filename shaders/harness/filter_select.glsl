// Harness only: runs the filter chosen at run time (push constant) through the texfilter includes,
// or the hardware sampler through textureGrad with the same gradients.
#ifndef TF_HARNESS_FILTER_SELECT_GLSL
#define TF_HARNESS_FILTER_SELECT_GLSL

#include "config.h"
#include "texfilter/texfilter.glsl"

layout(set = 0, binding = TF_BINDING_TEXTURE) uniform sampler2D u_texture;

layout(push_constant) uniform tf_PushConstants {
    int filterId;
    int wrapMode;
    float lodBias;
    float lodMin;
    float lodMax;
    uint count; // sample: number of lookups
} pc;

vec4 tf_harness_filter(vec2 uv, vec2 dUVdx, vec2 dUVdy)
{
    tf_Sampler s = tf_Sampler(pc.wrapMode, pc.lodBias, pc.lodMin, pc.lodMax);
    switch (pc.filterId) {
    case TF_FILTER_NEAREST: return tf_nearest(u_texture, uv, s);
    case TF_FILTER_BILINEAR: return tf_bilinear(u_texture, uv, s);
    case TF_FILTER_TRILINEAR: return tf_trilinear(u_texture, uv, dUVdx, dUVdy, s);
    case TF_FILTER_NEAREST_MIP: return tf_nearest_mip(u_texture, uv, dUVdx, dUVdy, s);
    case TF_FILTER_BILINEAR_MIP: return tf_bilinear_mip(u_texture, uv, dUVdx, dUVdy, s);
    default: return textureGrad(u_texture, uv, dUVdx, dUVdy); // hw-*: sampler state set by the host
    }
}

#endif
