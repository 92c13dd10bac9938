// texfilter/bilinear.glsl — manual bilinear lookups from texelFetch (Vulkan LINEAR filtering, one level).
//
// Use:     vec4 tf_bilinear(sampler2D tex, vec2 uv, tf_Sampler s);                             // level 0 only
//          vec4 tf_bilinear_mip(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s); // level by LOD
//          vec4 tf_bilinear_level(sampler2D tex, vec2 uv, int level, int wrapMode); // level in [0, levels−1]
//          Every resource kind (access.glsl, docs/API.md "Resources"): the same call with texture2D,
//          u/isampler2D or u/itexture2D (integer texels as float), sampler2DArray or texture2DArray plus
//          `int layer` right after uv, or a depth sampler2D/texture2D plus `tf_Compare cmp` right after uv
//          (percentage-closer: each texel compared before it is filtered), e.g.
//          tf_bilinear(sampler2D depth, vec2 uv, tf_Compare cmp, tf_Sampler s): bilinear PCF.
// Math:    i0 = floor(u·w_l − ½), α = frac(u·w_l − ½), in full float (hardware samplers round α to
//          subTexelPrecisionBits, often 8). tf_bilinear_mip reads level tf_mip_level_nearest(tf_lod(...))
//          (mipmapMode NEAREST: visible seams where the level changes).
// Options: s.wrap; tf_bilinear_mip also s.lodBias, s.lodMin, s.lodMax as in lod.glsl. No defines.
// Needs:   tex: any sampler2D (texelFetch; tf_bilinear_mip uses its MIP chain).
// Cost:    4 texel fetches.
// Degenerate input: non-finite uv gives vec4(0), huge uv is moved by whole periods first (tf_reduce_uv);
//          NaN/±Inf gradients the coarsest level, zero the finest (docs/API.md, degenerate input).
// Example: vec4 c = tf_bilinear(tex, uv, tf_sampler(TF_WRAP_REPEAT));
#ifndef TF_BILINEAR_GLSL
#define TF_BILINEAR_GLSL

#include "common.glsl"
#include "lod.glsl"

#define TFI_FAMILY TFI_FAMILY_BILINEAR
#include "detail/instantiate.glsl"
#undef TFI_FAMILY

#endif
