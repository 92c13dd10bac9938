// texfilter/brilinear.glsl — "brilinear": trilinear only in a band around each MIP level transition, one
// bilinear lookup everywhere else.
//
// Use:     vec4  tf_brilinear(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float band);
//          float tf_brilinear_weight(float f, float band); // the coarser level's weight for LOD fraction f
//          Every resource kind (docs/API.md "Resources": texture2D, u/isampler2D, u/itexture2D, arrays with
//          `int layer` after uv, depth maps with `tf_Compare cmp` after uv) and a TF_SOURCE texel source
//          (common.glsl) have the same tf_brilinear overload, the texture replaced: the prototype list below.
// Math:    λ = tf_lod(...), levels lo = floor(λ) and lo + 1, f = frac(λ); band B; level lo + 1 weighs
//              w = clamp((f − (1 − B)/2) / B, 0, 1)
//          (continuous in λ for B > 0). B = 1: w = f, tf_trilinear bit for bit. B = 0: w = step(f > ½), the
//          level of mipmapMode NEAREST with ties to the finer, tf_bilinear_mip bit for bit.
// Options: band B in [0, 1] (above 1: 1; NaN or below 0: 0). Suggested 0.25 (tf::SamplerOptions's
//          default): on a smooth LOD ramp 5 fetches a lookup on average, no seam; the finer level is used up
//          to f = 3/8 (mild under-filtering), the coarser from f = 5/8. s.wrap, s.lodBias, s.lodMin, s.lodMax
//          as in lod.glsl. No defines.
// Needs:   any sampler2D with a full MIP chain (texelFetch only).
// Cost:    4 texel fetches where w is 0 or 1 (outside the band, on a level, clamped to the last level), 8
//          inside the band: the level that weighs 0 is never fetched.
// Degenerate input: non-finite uv gives vec4(0); huge uv is moved by whole periods first (tf_reduce_uv);
//          NaN/±Inf gradients give the coarsest level (4 fetches), zero gradients the finest.
// Example: vec4 c = tf_brilinear(tex, uv, dFdxFine(uv), dFdyFine(uv), tf_sampler(TF_WRAP_REPEAT), 0.25);
#ifndef TF_BRILINEAR_GLSL
#define TF_BRILINEAR_GLSL

// B = 0 compares f > ½ exactly, as tf_mip_level_nearest's floor and comparison (lod.glsl) do: the same level
// for every λ, 1.5 + 2^-23 included, where a float λ + ½ would round to the finer one.

#include "bilinear.glsl"
#include "lod.glsl"

// Blend weight of the coarser level for LOD fraction f in [0, 1) and band in [0, 1] (see above).
float tf_brilinear_weight(float f, float band)
{
    float nearest = f > 0.5 ? 1.0 : 0.0; // B <= 0 (or NaN): the nearest level, ties to the finer
    float b = band > 0.0 ? min(band, 1.0) : 1.0;
    // A select, not an early return: SIMD implementations that run both sides pay for the masks.
    return band > 0.0 ? clamp((f - (1.0 - b) * 0.5) / b, 0.0, 1.0) : nearest;
}

// BEGIN prototypes (generated: tests/prototypes.py --write; ctest prototypes.current checks it)
// Every overload below is defined by this file's detail/*_kind.glsl for the kinds its #if names.
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D) != 0
vec4 tf_brilinear(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float band);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D) != 0
vec4 tf_brilinear(texture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float band);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D_ARRAY) != 0
vec4 tf_brilinear(sampler2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float band);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D_ARRAY) != 0
vec4 tf_brilinear(texture2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float band);
#endif
#if (TF_RESOURCES & TF_RESOURCE_INTEGER) != 0
vec4 tf_brilinear(isampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float band);
vec4 tf_brilinear(itexture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float band);
vec4 tf_brilinear(usampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float band);
vec4 tf_brilinear(utexture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float band);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SHADOW) != 0
vec4 tf_brilinear(sampler2D tex, vec2 uv, tf_Compare cmp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float band);
vec4 tf_brilinear(texture2D tex, vec2 uv, tf_Compare cmp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float band);
#endif
#ifdef TF_SOURCE
vec4 tf_brilinear(TF_SOURCE tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float band);
#endif
// END prototypes

#define TFI_FAMILY TFI_FAMILY_BRILINEAR
#include "detail/instantiate.glsl"
#undef TFI_FAMILY

#endif
