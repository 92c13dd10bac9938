// texfilter/trilinear.glsl — manual trilinear lookups from texelFetch (Vulkan LINEAR, mipmapMode LINEAR).
//
// Use:     vec4 tf_trilinear(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
// Math:    λ = tf_lod(...) (lod.glsl); bilinear lookups on levels floor(λ) and floor(λ)+1 blended by frac(λ),
//          in full float (hardware samplers round the blend to mipmapPrecisionBits, often 4 or 8).
// Options: s.wrap, s.lodBias, s.lodMin, s.lodMax (common.glsl, lod.glsl). No defines.
// Needs:   tex: any sampler2D with a full MIP chain (texelFetch only).
// Cost:    8 texel fetches; 4 where λ sits exactly on a level or is clamped to the last one
//          (plane scene: 6.5 on average, docs/FILTERS.md).
// Degenerate input: non-finite uv gives vec4(0); NaN/±Inf gradients the coarsest level (4 fetches), zero
//          gradients the finest.
// Example: vec4 c = tf_trilinear(tex, uv, dFdxFine(uv), dFdyFine(uv), tf_sampler(TF_WRAP_REPEAT));
#ifndef TF_TRILINEAR_GLSL
#define TF_TRILINEAR_GLSL

#include "bilinear.glsl"
#include "lod.glsl"

vec4 tf_trilinear(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s)
{
    float f;
    int lo = tfi_split_lod(tf_lod(tex, dUVdx, dUVdy, s), f);
#define TFI_TRILINEAR_LEVEL(level) tf_bilinear_level(tex, uv, level, s.wrap)
    return TFI_BLEND_LEVELS(TFI_TRILINEAR_LEVEL, lo, f);
#undef TFI_TRILINEAR_LEVEL
}

#endif
