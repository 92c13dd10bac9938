// texfilter/trilinear.glsl — manual trilinear lookups from texelFetch (Vulkan LINEAR, mipmapMode LINEAR).
//
// Use:     vec4 tf_trilinear(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
//          Every resource kind (docs/API.md "Resources": texture2D, u/isampler2D, u/itexture2D, arrays with
//          `int layer` after uv, depth maps with `tf_Compare cmp` after uv) and a TF_SOURCE texel source
//          (common.glsl) have the same overload, the texture parameter replaced: the prototype list below.
// Math:    λ = tf_lod(...) (lod.glsl); bilinear on levels floor(λ) and floor(λ) + 1 blended by frac(λ), in full
//          float (a hardware sampler rounds the blend to mipmapPrecisionBits).
// Options: s.wrap, s.lodBias, s.lodMin, s.lodMax. TF_MAGNIFY (common.glsl): level 0 reconstructed by a cubic
//          (bicubic.glsl) instead of bilinearly.
// Needs:   any sampler2D with a full MIP chain (texelFetch only).
// Cost:    8 texel fetches; 4 where λ sits exactly on a level or is clamped to the last one. TF_MAGNIFY's
//          cubic: 16 on level 0 instead of 4.
// Degenerate input: non-finite uv gives vec4(0); huge uv is moved by whole periods first (tf_reduce_uv);
//          NaN/±Inf gradients give the coarsest level (4 fetches), zero gradients the finest.
// Example: vec4 c = tf_trilinear(tex, uv, dFdxFine(uv), dFdyFine(uv), tf_sampler(TF_WRAP_REPEAT));
#ifndef TF_TRILINEAR_GLSL
#define TF_TRILINEAR_GLSL

#include "bicubic.glsl" // tfi_mip_level: TF_MAGNIFY on level 0
#include "lod.glsl"

// BEGIN prototypes (generated: tests/prototypes.py --write; ctest prototypes.current checks it)
// Every overload below is defined by this file's detail/*_kind.glsl for the kinds its #if names.
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D) != 0
vec4 tf_trilinear(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D) != 0
vec4 tf_trilinear(texture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D_ARRAY) != 0
vec4 tf_trilinear(sampler2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D_ARRAY) != 0
vec4 tf_trilinear(texture2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_INTEGER) != 0
vec4 tf_trilinear(isampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_trilinear(itexture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_trilinear(usampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_trilinear(utexture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SHADOW) != 0
vec4 tf_trilinear(sampler2D tex, vec2 uv, tf_Compare cmp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_trilinear(texture2D tex, vec2 uv, tf_Compare cmp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE) != 0
vec4 tf_trilinear(samplerCube tex, vec2 uv, int face, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_trilinear(textureCube tex, sampler smp, vec2 uv, int face, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE_ARRAY) != 0
vec4 tf_trilinear(samplerCubeArray tex, vec2 uv, int face, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_trilinear(textureCubeArray tex, sampler smp, vec2 uv, int face, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_LATLONG) != 0
vec4 tf_trilinear(sampler2D tex, vec2 uv, tf_LatLong latlong, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#ifdef TF_SOURCE
vec4 tf_trilinear(TF_SOURCE tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
// END prototypes

#define TFI_FAMILY TFI_FAMILY_TRILINEAR
#include "detail/instantiate.glsl"
#undef TFI_FAMILY

#endif
