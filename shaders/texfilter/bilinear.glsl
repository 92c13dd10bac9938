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

// BEGIN prototypes (generated: tests/prototypes.py --write; ctest prototypes.current checks it)
// Every overload below is defined by this file's detail/*_kind.glsl for the kinds its #if names.
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D) != 0
vec4 tf_bilinear(sampler2D tex, vec2 uv, tf_Sampler s);
vec4 tf_bilinear_level(sampler2D tex, vec2 uv, int level, int wrapMode);
vec4 tf_bilinear_mip(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D) != 0
vec4 tf_bilinear(texture2D tex, vec2 uv, tf_Sampler s);
vec4 tf_bilinear_level(texture2D tex, sampler smp, vec2 uv, int level, int wrapMode);
vec4 tf_bilinear_level(texture2D tex, vec2 uv, int level, int wrapMode);
vec4 tf_bilinear_mip(texture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D_ARRAY) != 0
vec4 tf_bilinear(sampler2DArray tex, vec2 uv, int layer, tf_Sampler s);
vec4 tf_bilinear_level(sampler2DArray tex, vec2 uv, int layer, int level, int wrapMode);
vec4 tf_bilinear_mip(sampler2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D_ARRAY) != 0
vec4 tf_bilinear(texture2DArray tex, vec2 uv, int layer, tf_Sampler s);
vec4 tf_bilinear_level(texture2DArray tex, sampler smp, vec2 uv, int layer, int level, int wrapMode);
vec4 tf_bilinear_level(texture2DArray tex, vec2 uv, int layer, int level, int wrapMode);
vec4 tf_bilinear_mip(texture2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_INTEGER) != 0
vec4 tf_bilinear(isampler2D tex, vec2 uv, tf_Sampler s);
vec4 tf_bilinear(itexture2D tex, vec2 uv, tf_Sampler s);
vec4 tf_bilinear(usampler2D tex, vec2 uv, tf_Sampler s);
vec4 tf_bilinear(utexture2D tex, vec2 uv, tf_Sampler s);
vec4 tf_bilinear_level(isampler2D tex, vec2 uv, int level, int wrapMode);
vec4 tf_bilinear_level(itexture2D tex, vec2 uv, int level, int wrapMode);
vec4 tf_bilinear_level(usampler2D tex, vec2 uv, int level, int wrapMode);
vec4 tf_bilinear_level(utexture2D tex, vec2 uv, int level, int wrapMode);
vec4 tf_bilinear_mip(isampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_bilinear_mip(itexture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_bilinear_mip(usampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_bilinear_mip(utexture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SHADOW) != 0
vec4 tf_bilinear(sampler2D tex, vec2 uv, tf_Compare cmp, tf_Sampler s);
vec4 tf_bilinear(texture2D tex, vec2 uv, tf_Compare cmp, tf_Sampler s);
vec4 tf_bilinear_level(sampler2D tex, vec2 uv, tf_Compare cmp, int level, int wrapMode);
vec4 tf_bilinear_level(texture2D tex, vec2 uv, tf_Compare cmp, int level, int wrapMode);
vec4 tf_bilinear_mip(sampler2D tex, vec2 uv, tf_Compare cmp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_bilinear_mip(texture2D tex, vec2 uv, tf_Compare cmp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE) != 0
vec4 tf_bilinear(samplerCube tex, vec2 uv, int face, tf_Sampler s);
vec4 tf_bilinear(textureCube tex, sampler smp, vec2 uv, int face, tf_Sampler s);
vec4 tf_bilinear_level(samplerCube tex, vec2 uv, int face, int level, int wrapMode);
vec4 tf_bilinear_level(textureCube tex, sampler smp, vec2 uv, int face, int level, int wrapMode);
vec4 tf_bilinear_mip(samplerCube tex, vec2 uv, int face, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_bilinear_mip(textureCube tex, sampler smp, vec2 uv, int face, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE_ARRAY) != 0
vec4 tf_bilinear(samplerCubeArray tex, vec2 uv, int face, int layer, tf_Sampler s);
vec4 tf_bilinear(textureCubeArray tex, sampler smp, vec2 uv, int face, int layer, tf_Sampler s);
vec4 tf_bilinear_level(samplerCubeArray tex, vec2 uv, int face, int layer, int level, int wrapMode);
vec4 tf_bilinear_level(textureCubeArray tex, sampler smp, vec2 uv, int face, int layer, int level, int wrapMode);
vec4 tf_bilinear_mip(samplerCubeArray tex, vec2 uv, int face, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_bilinear_mip(textureCubeArray tex, sampler smp, vec2 uv, int face, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_LATLONG) != 0
vec4 tf_bilinear(sampler2D tex, vec2 uv, tf_LatLong latlong, tf_Sampler s);
vec4 tf_bilinear_level(sampler2D tex, vec2 uv, tf_LatLong latlong, int level, int wrapMode);
vec4 tf_bilinear_mip(sampler2D tex, vec2 uv, tf_LatLong latlong, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#ifdef TF_SOURCE
vec4 tf_bilinear(TF_SOURCE tex, vec2 uv, tf_Sampler s);
vec4 tf_bilinear_level(TF_SOURCE tex, vec2 uv, int level, int wrapMode);
vec4 tf_bilinear_mip(TF_SOURCE tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
// END prototypes

#define TFI_FAMILY TFI_FAMILY_BILINEAR
#include "detail/instantiate.glsl"
#undef TFI_FAMILY

#endif
