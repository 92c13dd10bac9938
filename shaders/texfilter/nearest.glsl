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

// BEGIN prototypes (generated: tests/prototypes.py --write; ctest prototypes.current checks it)
// Every overload below is defined by this file's detail/*_kind.glsl for the kinds its #if names.
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D) != 0
vec4 tf_nearest(sampler2D tex, vec2 uv, tf_Sampler s);
vec4 tf_nearest_level(sampler2D tex, vec2 uv, int level, int wrapMode);
vec4 tf_nearest_mip(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D) != 0
vec4 tf_nearest(texture2D tex, vec2 uv, tf_Sampler s);
vec4 tf_nearest_level(texture2D tex, sampler smp, vec2 uv, int level, int wrapMode);
vec4 tf_nearest_level(texture2D tex, vec2 uv, int level, int wrapMode);
vec4 tf_nearest_mip(texture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D_ARRAY) != 0
vec4 tf_nearest(sampler2DArray tex, vec2 uv, int layer, tf_Sampler s);
vec4 tf_nearest_level(sampler2DArray tex, vec2 uv, int layer, int level, int wrapMode);
vec4 tf_nearest_mip(sampler2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D_ARRAY) != 0
vec4 tf_nearest(texture2DArray tex, vec2 uv, int layer, tf_Sampler s);
vec4 tf_nearest_level(texture2DArray tex, sampler smp, vec2 uv, int layer, int level, int wrapMode);
vec4 tf_nearest_level(texture2DArray tex, vec2 uv, int layer, int level, int wrapMode);
vec4 tf_nearest_mip(texture2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_INTEGER) != 0
vec4 tf_nearest(isampler2D tex, vec2 uv, tf_Sampler s);
vec4 tf_nearest(itexture2D tex, vec2 uv, tf_Sampler s);
vec4 tf_nearest(usampler2D tex, vec2 uv, tf_Sampler s);
vec4 tf_nearest(utexture2D tex, vec2 uv, tf_Sampler s);
vec4 tf_nearest_level(isampler2D tex, vec2 uv, int level, int wrapMode);
vec4 tf_nearest_level(itexture2D tex, vec2 uv, int level, int wrapMode);
vec4 tf_nearest_level(usampler2D tex, vec2 uv, int level, int wrapMode);
vec4 tf_nearest_level(utexture2D tex, vec2 uv, int level, int wrapMode);
vec4 tf_nearest_mip(isampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_nearest_mip(itexture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_nearest_mip(usampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_nearest_mip(utexture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SHADOW) != 0
vec4 tf_nearest(sampler2D tex, vec2 uv, tf_Compare cmp, tf_Sampler s);
vec4 tf_nearest(texture2D tex, vec2 uv, tf_Compare cmp, tf_Sampler s);
vec4 tf_nearest_level(sampler2D tex, vec2 uv, tf_Compare cmp, int level, int wrapMode);
vec4 tf_nearest_level(texture2D tex, vec2 uv, tf_Compare cmp, int level, int wrapMode);
vec4 tf_nearest_mip(sampler2D tex, vec2 uv, tf_Compare cmp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_nearest_mip(texture2D tex, vec2 uv, tf_Compare cmp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE) != 0
vec4 tf_nearest(samplerCube tex, vec2 uv, int face, tf_Sampler s);
vec4 tf_nearest(textureCube tex, sampler smp, vec2 uv, int face, tf_Sampler s);
vec4 tf_nearest_level(samplerCube tex, vec2 uv, int face, int level, int wrapMode);
vec4 tf_nearest_level(textureCube tex, sampler smp, vec2 uv, int face, int level, int wrapMode);
vec4 tf_nearest_mip(samplerCube tex, vec2 uv, int face, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_nearest_mip(textureCube tex, sampler smp, vec2 uv, int face, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE_ARRAY) != 0
vec4 tf_nearest(samplerCubeArray tex, vec2 uv, int face, int layer, tf_Sampler s);
vec4 tf_nearest(textureCubeArray tex, sampler smp, vec2 uv, int face, int layer, tf_Sampler s);
vec4 tf_nearest_level(samplerCubeArray tex, vec2 uv, int face, int layer, int level, int wrapMode);
vec4 tf_nearest_level(textureCubeArray tex, sampler smp, vec2 uv, int face, int layer, int level, int wrapMode);
vec4 tf_nearest_mip(samplerCubeArray tex, vec2 uv, int face, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_nearest_mip(textureCubeArray tex, sampler smp, vec2 uv, int face, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_LATLONG) != 0
vec4 tf_nearest(sampler2D tex, vec2 uv, tf_LatLong latlong, tf_Sampler s);
vec4 tf_nearest_level(sampler2D tex, vec2 uv, tf_LatLong latlong, int level, int wrapMode);
vec4 tf_nearest_mip(sampler2D tex, vec2 uv, tf_LatLong latlong, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#ifdef TF_SOURCE
vec4 tf_nearest(TF_SOURCE tex, vec2 uv, tf_Sampler s);
vec4 tf_nearest_level(TF_SOURCE tex, vec2 uv, int level, int wrapMode);
vec4 tf_nearest_mip(TF_SOURCE tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
// END prototypes

#define TFI_FAMILY TFI_FAMILY_NEAREST
#include "detail/instantiate.glsl"
#undef TFI_FAMILY

#endif
