// texfilter/lod.glsl — level of detail from explicit UV gradients (Vulkan "Scale Factor and LOD").
//
// Use:     float tf_lod(sampler2D tex, vec2 dUVdx, vec2 dUVdy, tf_Sampler s); // biased, clamped: [0, levels−1]
//          float tf_lod_unclamped(sampler2D tex, vec2 dUVdx, vec2 dUVdy, float lodBias); // log2(ρ) + lodBias
//          int   tf_mip_level_nearest(float lod); // mipmapMode NEAREST: ceil(lod + ½) − 1, ties to the finer
//          tf_lod and tf_lod_unclamped have an overload for every resource kind (docs/API.md "Resources") and
//          a TF_SOURCE texel source (common.glsl), the texture alone replaced: no layer or comparison (they do
//          not change the LOD), e.g. tf_lod(texture2DArray tex, dUVdx, dUVdy, s). The prototype list below.
// Math:    ρ = max(|J e_x|, |J e_y|) with J = [dUVdx dUVdy] in level-0 texels, λ = log2(ρ) + s.lodBias,
//          clamped to [s.lodMin, s.lodMax] (needs lodMin <= lodMax, as Vulkan's minLod <= maxLod), then to
//          [0, levels − 1].
// Options: s.lodBias, s.lodMin, s.lodMax. No defines.
// Needs:   only the texture's size and level count are queried.
// Cost:    no texel fetch (one log2).
// Degenerate input: zero gradients give the finest level allowed (λ = −∞ before clamping); NaN or ±Inf
//          gradients, or ρ past float range, the coarsest (λ = +∞). A NaN λ (NaN lodBias) counts as +∞, a NaN
//          lodMin or lodMax as no bound.
// Example: int level = tf_mip_level_nearest(tf_lod(tex, dFdxFine(uv), dFdyFine(uv), s));
#ifndef TF_LOD_GLSL
#define TF_LOD_GLSL

#include "common.glsl"

// The LOD clamps every filter that picks levels shares: λ to [s.lodMin, s.lodMax], then to the levels
// [0, levels − 1]. SPIR-V leaves FClamp, FMin and FMax (GLSL clamp, min, max) undefined for a NaN operand, so
// NaN is decided first, with isnan: a NaN λ counts as +∞ (blur fully, as non-finite gradients do: the
// coarsest level the clamps allow), a NaN lodMin or lodMax as no bound. Finite input: clamp(clamp(λ, lodMin,
// lodMax), 0, levels − 1) exactly. host/reference/reference.cpp clamp_lod follows the same rule.
float tfi_clamp_lod_levels(float lambda, tf_Sampler s, int levels)
{
    // Selects, not ifs: lavapipe runs both sides of an if under a mask anyway, and the masks cost more.
    float lod = isnan(lambda) ? 1.0 / 0.0 : lambda;
    lod = isnan(s.lodMin) ? lod : max(lod, s.lodMin);
    lod = isnan(s.lodMax) ? lod : min(lod, s.lodMax);
    return clamp(lod, 0.0, float(max(levels, 1) - 1)); // lod is not NaN here
}

// log2(x) for x > 0, snapped to the integer it is within GLSL.std.450's error of (3 ULP; 2^-21 absolute in
// [½, 2]): a λ a hair above a level blends in the next one with a weight of ~1e-7 at the price of its fetches
// (TFI_BLEND_LEVELS_ONCE), and on an NVIDIA H200 aniso with ρ = 8 texels over 4 probes read 32 texels, not 16.
// So powers of two give whole levels on every device; the weights the snap drops are below 5e-7.
float tfi_log2(float x)
{
    float l = log2(x);
    float r = round(l);
    return abs(l - r) <= max(4e-7 * abs(r), 5e-7) ? r : l; // ±∞ stays: ∞ − ∞ is NaN, and NaN <= … is false
}

// log2(ρ) from ρ² (one log2 serves both axes: log2(sqrt(x)) = ½ log2(x)); −∞ for ρ² = 0 (zero gradients, or
// squares that underflow): GLSL.std.450 leaves log2(0) undefined, and a NaN there would read as +∞, the
// coarsest level instead of the finest. ρ² = +∞ (overflow) gives +∞: fine.
float tfi_log2_rho(float rho2)
{
    float half_log2 = 0.5 * tfi_log2(rho2); // formed first, so that the choice below is one select, not a branch
    return rho2 > 0.0 ? half_log2 : -1.0 / 0.0;
}

// The two-level blend every filter that blends MIP levels shares (trilinear, brilinear, the aniso probes,
// ewa). tfi_split_lod splits a clamped LOD into the finer level floor(lod), returned, and the coarser
// level's weight frac(lod).
int tfi_split_lod(float lod, out float f)
{
    float lo = floor(lod);
    f = lod - lo;
    return int(lo);
}
// TFI_BLEND_LEVELS(result, LEVEL, lo, w), a statement: the value TFI_BLEND_LEVELS_ONCE gives (the same operations,
// so the same bits) without its loop: the level the weight picks (w == 1: lo + 1, else lo), then, under an `if`
// only where 0 < w < 1, the coarser one mixed in. A SIMD batch with no lane between levels skips the `if`, so
// a lookup on a level reads one level. For levels of a few fetches (trilinear, brilinear) this is the cheaper
// form: the loop cost more than the fetches it saves (docs/BENCHMARKS.md, "Level blends").
#define TFI_BLEND_LEVELS(result, LEVEL, lo, w)                                                         \
    {                                                                                                 \
        result = LEVEL((w) == 1.0 ? (lo) + 1 : (lo));                                                 \
        if ((w) > 0.0 && (w) < 1.0)                                                                   \
            result = mix(result, LEVEL((lo) + 1), (w));                                               \
    }
// TFI_BLEND_LEVELS_ONCE(result, LEVEL, lo, w), a statement: result = mix(LEVEL(lo), LEVEL(lo + 1), w) for a
// function-like macro LEVEL(l), the filter's value on level l; a level that weighs 0 is not evaluated. The form
// aniso's probes and ewa use (for trilinear's cheap levels TFI_BLEND_LEVELS above is faster): a loop, left once
// no lane needs another turn, so a batch on one level pays one level's cost, any other two. The turn test is at the loop's top: with a do-while, lavapipe (Mesa 22.3.6) handed lanes that
// left early a value from their batch's later turns (a workaround; docs/API.md, "Optimisation").
#define TFI_BLEND_LEVELS_ONCE(result, LEVEL, lo, w)                                     \
    {                                                                                    \
        result = vec4(0.0); /* every path assigns it; said once for compilers that check */ \
        int tfi_turns = (w) > 0.0 && (w) < 1.0 ? 2 : 1;                                  \
        int tfi_level = (w) == 1.0 ? (lo) + 1 : (lo);                                    \
        for (int tfi_turn = 0; tfi_turn < tfi_turns; ++tfi_turn) {                       \
            vec4 tfi_value = LEVEL(tfi_level);                                           \
            result = tfi_turn == 0 ? tfi_value : mix(result, tfi_value, (w));            \
            tfi_level = (lo) + 1;                                                        \
        }                                                                                \
    }

// Vulkan mipmapMode NEAREST: ceil(d + 0.5) - 1, so d = 0.5 still picks the finer level. Written with
// floor and a comparison because lod + 0.5 rounds in float (1.50000012 + 0.5 == 2.0 exactly).
int tf_mip_level_nearest(float lod)
{
    float level = floor(lod);
    return int(level) + (lod - level > 0.5 ? 1 : 0);
}

// BEGIN prototypes (generated: tests/prototypes.py --write; ctest prototypes.current checks it)
// Every overload below is defined by this file's detail/*_kind.glsl for the kinds its #if names.
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D) != 0
float tf_lod(texture2D tex, sampler smp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
float tf_lod_unclamped(texture2D tex, sampler smp, vec2 dUVdx, vec2 dUVdy, float lodBias);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D_ARRAY) != 0
float tf_lod(sampler2DArray tex, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
float tf_lod_unclamped(sampler2DArray tex, vec2 dUVdx, vec2 dUVdy, float lodBias);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D_ARRAY) != 0
float tf_lod(texture2DArray tex, sampler smp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
float tf_lod(texture2DArray tex, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
float tf_lod_unclamped(texture2DArray tex, sampler smp, vec2 dUVdx, vec2 dUVdy, float lodBias);
float tf_lod_unclamped(texture2DArray tex, vec2 dUVdx, vec2 dUVdy, float lodBias);
#endif
#if (TF_RESOURCES & TF_RESOURCE_INTEGER) != 0
float tf_lod(isampler2D tex, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
float tf_lod(itexture2D tex, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
float tf_lod(usampler2D tex, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
float tf_lod(utexture2D tex, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
float tf_lod_unclamped(isampler2D tex, vec2 dUVdx, vec2 dUVdy, float lodBias);
float tf_lod_unclamped(itexture2D tex, vec2 dUVdx, vec2 dUVdy, float lodBias);
float tf_lod_unclamped(usampler2D tex, vec2 dUVdx, vec2 dUVdy, float lodBias);
float tf_lod_unclamped(utexture2D tex, vec2 dUVdx, vec2 dUVdy, float lodBias);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SHADOW) != 0
float tf_lod(sampler2DShadow tex, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
float tf_lod(texture2D tex, samplerShadow smp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
float tf_lod_unclamped(sampler2DShadow tex, vec2 dUVdx, vec2 dUVdy, float lodBias);
float tf_lod_unclamped(texture2D tex, samplerShadow smp, vec2 dUVdx, vec2 dUVdy, float lodBias);
#endif
#if (TF_RESOURCES & (TF_RESOURCE_TEXTURE_2D | TF_RESOURCE_SHADOW)) != 0
float tf_lod(texture2D tex, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
float tf_lod_unclamped(texture2D tex, vec2 dUVdx, vec2 dUVdy, float lodBias);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE) != 0
float tf_lod(samplerCube tex, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
float tf_lod(textureCube tex, sampler smp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
float tf_lod_unclamped(samplerCube tex, vec2 dUVdx, vec2 dUVdy, float lodBias);
float tf_lod_unclamped(textureCube tex, sampler smp, vec2 dUVdx, vec2 dUVdy, float lodBias);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE_ARRAY) != 0
float tf_lod(samplerCubeArray tex, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
float tf_lod(textureCubeArray tex, sampler smp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
float tf_lod_unclamped(samplerCubeArray tex, vec2 dUVdx, vec2 dUVdy, float lodBias);
float tf_lod_unclamped(textureCubeArray tex, sampler smp, vec2 dUVdx, vec2 dUVdy, float lodBias);
#endif
#if (TF_RESOURCES & (TF_RESOURCE_SAMPLER_2D | TF_RESOURCE_SHADOW | TF_RESOURCE_LATLONG)) != 0
float tf_lod(sampler2D tex, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
float tf_lod_unclamped(sampler2D tex, vec2 dUVdx, vec2 dUVdy, float lodBias);
#endif
#ifdef TF_SOURCE
float tf_lod(TF_SOURCE tex, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
float tf_lod_unclamped(TF_SOURCE tex, vec2 dUVdx, vec2 dUVdy, float lodBias);
#endif
// END prototypes

#define TFI_FAMILY TFI_FAMILY_LOD
#include "detail/instantiate.glsl"
#undef TFI_FAMILY

#endif
