// texfilter/brilinear.glsl — "brilinear": trilinear only in a band around each MIP level transition,
// a single bilinear lookup (4 fetches) everywhere else.
//
// Use:     vec4  tf_brilinear(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float band);
//          float tf_brilinear_weight(float f, float band); // the coarser level's weight for LOD fraction f
//          Every resource kind (access.glsl, docs/API.md "Resources"): the same call with texture2D,
//          u/isampler2D or u/itexture2D (integer texels as float), sampler2DArray or texture2DArray plus
//          `int layer` right after uv, or a depth sampler2D/texture2D plus `tf_Compare cmp` right after uv
//          (percentage-closer: each texel compared before it is filtered), e.g.
//          tf_brilinear(usampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float band).
// Options: s.wrap, s.lodBias, s.lodMin, s.lodMax as in lod.glsl. No defines.
//          band B in [0, 1] (above 1: 1; NaN or below 0: 0): the width, in LOD units, of the trilinear
//          band centred on each transition (LOD fraction f = 1/2 between levels lo = floor(λ) and lo + 1).
//          The blend weight of level lo + 1 is
//              w = clamp((f − (1 − B)/2) / B, 0, 1),
//          continuous in λ for B > 0: 0 for f <= (1 − B)/2, a ramp of slope 1/B across the band, 1 for
//          f >= (1 + B)/2.
//          B = 1: w = f exactly, i.e. tf_trilinear, bit for bit.
//          B = 0: w = step(f > 1/2), the nearest level with ties (f = 1/2) to the finer one: the level
//                 ceil(λ + 1/2) − 1 of Vulkan mipmapMode NEAREST, i.e. tf_bilinear_mip. (f > 1/2 is exact,
//                 as tf_mip_level_nearest's floor and comparison (lod.glsl): the same level for every λ,
//                 1.5 + 2^-23 included, where a float λ + 1/2 would round to the finer one.)
//          Suggested band: 0.25 (tf::SamplerOptions's default). On a smooth LOD ramp a quarter of the
//          LOD range pays 8 fetches and the rest 4, so 5 fetches a lookup on average (trilinear: 8),
//          and the level blend stays continuous (no seam, unlike B = 0); outside the band the finer
//          level is used up to f = 3/8 (at most 2^0.375 = 1.3 texels a pixel: mild under-filtering) and
//          the coarser from f = 5/8 (slightly blurrier than trilinear).
// Needs:   tex: any sampler2D with a full MIP chain (texelFetch only).
// Cost:    4 texel fetches where w is 0 or 1 (outside the band, on a level, or clamped to the last
//          level), 8 inside the band. The level that weighs 0 is never fetched (plane scene, band 0.25:
//          4.6 on average, docs/FILTERS.md).
// Degenerate input: NaN/±Inf gradients give the coarsest level (4 fetches), zero gradients the finest
//          (lod.glsl); non-finite uv gives vec4(0).
// Example: vec4 c = tf_brilinear(tex, uv, dFdxFine(uv), dFdyFine(uv), tf_sampler(TF_WRAP_REPEAT), 0.25);
#ifndef TF_BRILINEAR_GLSL
#define TF_BRILINEAR_GLSL

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
