// texfilter/nearest.glsl — manual nearest-texel lookups from texelFetch (Vulkan NEAREST filtering).
//
// Use:     vec4 tf_nearest(sampler2D tex, vec2 uv, tf_Sampler s);                             // level 0
//          vec4 tf_nearest_mip(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s); // level by LOD
//          vec4 tf_nearest_level(sampler2D tex, vec2 uv, int level, int wrapMode); // level in [0, levels−1]
//          Every resource kind (docs/API.md "Resources": texture2D, u/isampler2D, u/itexture2D, arrays with
//          `int layer` after uv, depth maps with `tf_Compare cmp` after uv) and a TF_SOURCE texel source
//          (common.glsl) have the same overloads, the texture parameter replaced: the prototype list below.
// Math:    texel i = floor(u·w_l); tf_nearest_mip's level is tf_mip_level_nearest(tf_lod(...)) (lod.glsl).
// Options: s.wrap; tf_nearest_mip also s.lodBias, s.lodMin, s.lodMax (lod.glsl). No defines.
// Needs:   any sampler2D (texelFetch only); tf_nearest_mip reads its MIP chain.
// Cost:    1 texel fetch.
// Degenerate input: non-finite uv gives vec4(0); huge uv is moved by whole periods first (tf_reduce_uv);
//          NaN/±Inf gradients give the coarsest level, zero gradients the finest.
// Example: vec4 c = tf_nearest_mip(tex, uv, dFdxFine(uv), dFdyFine(uv), tf_sampler(TF_WRAP_CLAMP));
#ifndef TF_NEAREST_GLSL
#define TF_NEAREST_GLSL

#include "common.glsl"
#include "lod.glsl"

#define TFI_FAMILY TFI_FAMILY_NEAREST
#include "detail/instantiate.glsl"
#undef TFI_FAMILY

#endif
