// texfilter/nearest.glsl — manual nearest-texel lookups from texelFetch (Vulkan NEAREST filtering).
//
// Use:     vec4 tf_nearest(sampler2D tex, vec2 uv, tf_Sampler s);                             // level 0 only
//          vec4 tf_nearest_mip(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s); // level by LOD
//          vec4 tf_nearest_level(sampler2D tex, vec2 uv, int level, int wrapMode); // level in [0, levels−1]
//          Every resource kind (access.glsl, docs/API.md "Resources"): the same call with texture2D,
//          u/isampler2D or u/itexture2D (integer texels as float), sampler2DArray or texture2DArray plus
//          `int layer` right after uv, or a depth sampler2D/texture2D plus `tf_Compare cmp` right after uv
//          (percentage-closer: each texel compared before it is filtered), e.g.
//          tf_nearest_mip(texture2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s).
// Math:    texel i = floor(u·w_l). tf_nearest_mip reads level tf_mip_level_nearest(tf_lod(...)) (lod.glsl:
//          mipmapMode NEAREST, no blend between levels).
// Options: s.wrap; tf_nearest_mip also s.lodBias, s.lodMin, s.lodMax as in lod.glsl. No defines.
// Needs:   tex: any sampler2D (texelFetch; tf_nearest_mip uses its MIP chain).
// Cost:    1 texel fetch.
// Degenerate input: non-finite uv gives vec4(0), huge uv is moved by whole periods first (tf_reduce_uv);
//          NaN/±Inf gradients the coarsest level, zero the finest (docs/API.md, degenerate input).
// Example: vec4 c = tf_nearest_mip(tex, uv, dFdxFine(uv), dFdyFine(uv), tf_sampler(TF_WRAP_CLAMP));
#ifndef TF_NEAREST_GLSL
#define TF_NEAREST_GLSL

#include "common.glsl"
#include "lod.glsl"

#define TFI_FAMILY TFI_FAMILY_NEAREST
#include "detail/instantiate.glsl"
#undef TFI_FAMILY

#endif
