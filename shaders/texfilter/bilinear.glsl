// texfilter/bilinear.glsl — manual bilinear lookups from texelFetch (Vulkan LINEAR filtering, one level).
//
// Use:     vec4 tf_bilinear(sampler2D tex, vec2 uv, tf_Sampler s);                             // level 0
//          vec4 tf_bilinear_mip(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s); // level by LOD
//          vec4 tf_bilinear_level(sampler2D tex, vec2 uv, int level, int wrapMode); // level in [0, levels−1]
//          Every resource kind (docs/API.md "Resources": texture2D, u/isampler2D, u/itexture2D, arrays with
//          `int layer` after uv, depth maps with `tf_Compare cmp` after uv: bilinear PCF, each texel compared
//          before it is filtered) and a TF_SOURCE texel source (common.glsl) have the same overloads, the
//          texture parameter replaced: the prototype list below.
// Math:    i0 = floor(u·w_l − ½), α = frac(u·w_l − ½), in full float (a hardware sampler rounds α to
//          subTexelPrecisionBits). tf_bilinear_mip reads level tf_mip_level_nearest(tf_lod(...)) (mipmapMode
//          NEAREST: seams where the level changes).
// Options: s.wrap; tf_bilinear_mip also s.lodBias, s.lodMin, s.lodMax (lod.glsl). No defines.
// Needs:   any sampler2D (texelFetch only); tf_bilinear_mip reads its MIP chain.
// Cost:    4 texel fetches.
// Degenerate input: non-finite uv gives vec4(0); huge uv is moved by whole periods first (tf_reduce_uv);
//          NaN/±Inf gradients give the coarsest level, zero gradients the finest.
// Example: vec4 c = tf_bilinear(tex, uv, tf_sampler(TF_WRAP_REPEAT));
#ifndef TF_BILINEAR_GLSL
#define TF_BILINEAR_GLSL

#include "common.glsl"
#include "lod.glsl"

#define TFI_FAMILY TFI_FAMILY_BILINEAR
#include "detail/instantiate.glsl"
#undef TFI_FAMILY

#endif
