// texfilter/stochastic.glsl — stochastic texture filtering (filtering after shading): bilinear, trilinear,
// aniso and ewa reading ONE texel (or ONE hardware tap) per lookup, chosen with probability equal to its
// weight in the deterministic filter, from random numbers the caller supplies. Averaged over frames (TAA, a
// path tracer's samples) it converges to the deterministic filter (ewa: see Math) at the rate its variance
// Σ w_i t_i² − mean² / N sets.
//
// Use:     vec4 tf_bilinear_stochastic(sampler2D tex, vec2 uv, tf_Sampler s, vec3 xi);            // level 0
//          vec4 tf_bilinear_stochastic_level(sampler2D tex, vec2 uv, int level, int wrapMode, vec3 xi);
//          vec4 tf_trilinear_stochastic(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi);
//          vec4 tf_aniso_stochastic(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes,
//                                   int shape, vec3 xi);
//          vec4 tf_ewa_stochastic(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha,
//                                 float maxAniso, vec3 xi);
//          and the hardware-tap forms with the same parameters (tf_X_stochastic_hw). Every resource kind and a
//          TF_SOURCE (manual forms) have the same overloads: the prototype list near the end of this file;
//          environment maps: cube.glsl's and latlong.glsl's tf_X_stochastic_cube / _latlong.
// xi:      three numbers in [0, 1) for this lookup (white noise, blue noise, a low-discrepancy sequence). xi.xy
//          pick the texel of a bilinear footprint (ewa: xi.x walks the weights' CDF), xi.z the level (trilinear,
//          ewa) or the probe (aniso; its rest, rescaled, then the probe's level). Clamped into [0, 1); NaN → 0.
// Math:    each form draws one texel (tap) with its deterministic weight as probability, so its expectation E is:
//          bilinear, trilinear, aniso: tf_bilinear_level, tf_trilinear, tf_aniso; _hw: the deterministic _hw form.
//          ewa: the magnification share first (xi.z < 1 − clamp(λ, 0, 1): one bilinear texel at one of tf_ewa's 4
//          footprint points; TF_MAGNIFY's cubics are not sampled, their weights are not probabilities), then a
//          level as trilinear, then one texel of its support with probability w_i / Σw: E per level is the
//          Gaussian-weighted MEAN of the support, not tf_ewa's line fit (no one-texel estimator has a fit as
//          its mean; they differ by the fitted gradient times the weights' centroid offset, < ~0.1 level texel).
//          tf_ewa_stochastic_hw: one 2x2 block with probability its weight / Σ, tapped as tf_ewa_hw taps it:
//          E = tf_ewa_hw exactly.
// Options: the deterministic families' (s.wrap, lodBias, lodMin, lodMax, maxProbes, shape, alpha, maxAniso,
//          TF_ANISO_RATIO_SLACK, TF_EWA_MAX_TEXELS). TF_MAGNIFY is not applied: level 0 is read bilinearly.
// Needs:   as the deterministic form: a full MIP chain for the mip filters; the _hw forms a sampler bound with
//          the texture, LINEAR min/mag/mipmap with the wrap mode s.wrap, no bias, no narrower LOD clamp.
// Cost:    1 texel fetch (manual) or 1 hardware lookup (_hw) for every input. ALU: bilinear, trilinear O(1);
//          aniso up to 16 weights (feline); ewa evaluates its support's weights twice, at most 2·K²
//          (_hw: 2·(K/2+1)²) for K = TF_EWA_MAX_TEXELS: bounded whatever the footprint.
// Degenerate input: the deterministic families' rules: non-finite uv → vec4(0); huge uv moved by whole periods;
//          NaN/±Inf gradients read the coarsest level, zero gradients the finest; NaN xi counts as 0.
// Example: vec3 xi = my_blue_noise(pixel, frame);
//          vec4 c = tf_trilinear_stochastic(tex, uv, dFdxFine(uv), dFdyFine(uv), tf_sampler(TF_WRAP_REPEAT), xi);
#ifndef TF_STOCHASTIC_GLSL
#define TF_STOCHASTIC_GLSL

#include "aniso.glsl"
#include "bilinear.glsl"
#include "ewa.glsl"
#include "lod.glsl"

// xi clamped into [0, 1) (the largest float below 1); NaN becomes 0 (max/min of NaN are undefined: test first).
vec3 tfi_unit3(vec3 xi)
{
    return clamp(mix(xi, vec3(0.0), isnan(xi)), vec3(0.0), vec3(0.99999994));
}

// The level of a two-level blend at `lod` (clamped): the coarser with probability frac(lod). Also returns
// xi's unused part, rescaled to [0, 1), in `rest`.
int tfi_stochastic_level(float lod, float xi, out float rest)
{
    float f;
    int lo = tfi_split_lod(lod, f);
    bool coarser = xi < f;
    rest = coarser ? xi / f : (xi - f) / (1.0 - f);
    rest = clamp(rest, 0.0, 0.99999994);
    return coarser ? lo + 1 : lo;
}

// aniso's probe k for xi in [0, 1): equal weights (gpu), or Gaussian exp(−8 t_k²) (feline), by their CDF.
// `rest`: xi's unused part, rescaled to [0, 1). Returns t_k, the probe's place along the axis.
float tfi_stochastic_probe(int probes, int shape, float xi, out float rest)
{
    float n = float(probes);
    if (shape != TF_ANISO_FELINE) {
        float k = min(floor(xi * n), n - 1.0);
        rest = clamp(xi * n - k, 0.0, 0.99999994);
        return (k + 0.5) / n - 0.5;
    }
    float total = 0.0;
    for (int k = 0; k < TF_ANISO_MAX_PROBES; ++k) {
        if (k >= probes)
            break;
        float t = (float(k) + 0.5) / n - 0.5;
        total += exp(-8.0 * t * t);
    }
    float target = xi * total, below = 0.0, chosen = 0.5 / n - 0.5;
    rest = 0.0;
    for (int k = 0; k < TF_ANISO_MAX_PROBES; ++k) {
        if (k >= probes)
            break;
        float t = (float(k) + 0.5) / n - 0.5, w = exp(-8.0 * t * t);
        chosen = t;
        rest = clamp((target - below) / w, 0.0, 0.99999994);
        if (target < below + w)
            break;
        below += w;
    }
    return chosen;
}

// BEGIN prototypes (generated: tests/prototypes.py --write; ctest prototypes.current checks it)
// Every overload below is defined by this file's detail/*_kind.glsl for the kinds its #if names.
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D) != 0
vec4 tf_aniso_stochastic(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_aniso_stochastic_hw(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_bilinear_stochastic(sampler2D tex, vec2 uv, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic_hw(sampler2D tex, vec2 uv, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic_level(sampler2D tex, vec2 uv, int level, int wrapMode, vec3 xi);
vec4 tf_ewa_stochastic(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_ewa_stochastic_hw(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_trilinear_stochastic(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi);
vec4 tf_trilinear_stochastic_hw(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D) != 0
vec4 tf_aniso_stochastic(texture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_aniso_stochastic_hw(texture2D tex, sampler smp, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_bilinear_stochastic(texture2D tex, vec2 uv, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic_hw(texture2D tex, sampler smp, vec2 uv, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic_level(texture2D tex, sampler smp, vec2 uv, int level, int wrapMode, vec3 xi);
vec4 tf_bilinear_stochastic_level(texture2D tex, vec2 uv, int level, int wrapMode, vec3 xi);
vec4 tf_ewa_stochastic(texture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_ewa_stochastic_hw(texture2D tex, sampler smp, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_trilinear_stochastic(texture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi);
vec4 tf_trilinear_stochastic_hw(texture2D tex, sampler smp, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D_ARRAY) != 0
vec4 tf_aniso_stochastic(sampler2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_aniso_stochastic_hw(sampler2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_bilinear_stochastic(sampler2DArray tex, vec2 uv, int layer, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic_hw(sampler2DArray tex, vec2 uv, int layer, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic_level(sampler2DArray tex, vec2 uv, int layer, int level, int wrapMode, vec3 xi);
vec4 tf_ewa_stochastic(sampler2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_ewa_stochastic_hw(sampler2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_trilinear_stochastic(sampler2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi);
vec4 tf_trilinear_stochastic_hw(sampler2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D_ARRAY) != 0
vec4 tf_aniso_stochastic(texture2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_aniso_stochastic_hw(texture2DArray tex, sampler smp, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_bilinear_stochastic(texture2DArray tex, vec2 uv, int layer, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic_hw(texture2DArray tex, sampler smp, vec2 uv, int layer, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic_level(texture2DArray tex, sampler smp, vec2 uv, int layer, int level, int wrapMode, vec3 xi);
vec4 tf_bilinear_stochastic_level(texture2DArray tex, vec2 uv, int layer, int level, int wrapMode, vec3 xi);
vec4 tf_ewa_stochastic(texture2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_ewa_stochastic_hw(texture2DArray tex, sampler smp, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_trilinear_stochastic(texture2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi);
vec4 tf_trilinear_stochastic_hw(texture2DArray tex, sampler smp, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi);
#endif
#if (TF_RESOURCES & TF_RESOURCE_INTEGER) != 0
vec4 tf_aniso_stochastic(isampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_aniso_stochastic(itexture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_aniso_stochastic(usampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_aniso_stochastic(utexture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_bilinear_stochastic(isampler2D tex, vec2 uv, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic(itexture2D tex, vec2 uv, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic(usampler2D tex, vec2 uv, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic(utexture2D tex, vec2 uv, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic_level(isampler2D tex, vec2 uv, int level, int wrapMode, vec3 xi);
vec4 tf_bilinear_stochastic_level(itexture2D tex, vec2 uv, int level, int wrapMode, vec3 xi);
vec4 tf_bilinear_stochastic_level(usampler2D tex, vec2 uv, int level, int wrapMode, vec3 xi);
vec4 tf_bilinear_stochastic_level(utexture2D tex, vec2 uv, int level, int wrapMode, vec3 xi);
vec4 tf_ewa_stochastic(isampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_ewa_stochastic(itexture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_ewa_stochastic(usampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_ewa_stochastic(utexture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_trilinear_stochastic(isampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi);
vec4 tf_trilinear_stochastic(itexture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi);
vec4 tf_trilinear_stochastic(usampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi);
vec4 tf_trilinear_stochastic(utexture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SHADOW) != 0
vec4 tf_aniso_stochastic(sampler2D tex, vec2 uv, tf_Compare cmp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_aniso_stochastic(texture2D tex, vec2 uv, tf_Compare cmp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_aniso_stochastic_hw(sampler2DShadow tex, vec2 uv, float dref, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_aniso_stochastic_hw(texture2D tex, samplerShadow smp, vec2 uv, float dref, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_bilinear_stochastic(sampler2D tex, vec2 uv, tf_Compare cmp, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic(texture2D tex, vec2 uv, tf_Compare cmp, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic_hw(sampler2DShadow tex, vec2 uv, float dref, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic_hw(texture2D tex, samplerShadow smp, vec2 uv, float dref, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic_level(sampler2D tex, vec2 uv, tf_Compare cmp, int level, int wrapMode, vec3 xi);
vec4 tf_bilinear_stochastic_level(texture2D tex, vec2 uv, tf_Compare cmp, int level, int wrapMode, vec3 xi);
vec4 tf_ewa_stochastic(sampler2D tex, vec2 uv, tf_Compare cmp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_ewa_stochastic(texture2D tex, vec2 uv, tf_Compare cmp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_ewa_stochastic_hw(sampler2DShadow tex, vec2 uv, float dref, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_ewa_stochastic_hw(texture2D tex, samplerShadow smp, vec2 uv, float dref, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_trilinear_stochastic(sampler2D tex, vec2 uv, tf_Compare cmp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi);
vec4 tf_trilinear_stochastic(texture2D tex, vec2 uv, tf_Compare cmp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi);
vec4 tf_trilinear_stochastic_hw(sampler2DShadow tex, vec2 uv, float dref, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi);
vec4 tf_trilinear_stochastic_hw(texture2D tex, samplerShadow smp, vec2 uv, float dref, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE) != 0
vec4 tf_bilinear_stochastic_level(samplerCube tex, vec2 uv, int face, int level, int wrapMode, vec3 xi);
vec4 tf_bilinear_stochastic_level(textureCube tex, sampler smp, vec2 uv, int face, int level, int wrapMode, vec3 xi);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE_ARRAY) != 0
vec4 tf_bilinear_stochastic_level(samplerCubeArray tex, vec2 uv, int face, int layer, int level, int wrapMode, vec3 xi);
vec4 tf_bilinear_stochastic_level(textureCubeArray tex, sampler smp, vec2 uv, int face, int layer, int level, int wrapMode, vec3 xi);
#endif
#if (TF_RESOURCES & TF_RESOURCE_LATLONG) != 0
vec4 tf_bilinear_stochastic_level(sampler2D tex, vec2 uv, tf_LatLong latlong, int level, int wrapMode, vec3 xi);
#endif
#ifdef TF_SOURCE
vec4 tf_aniso_stochastic(TF_SOURCE tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_bilinear_stochastic(TF_SOURCE tex, vec2 uv, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic_level(TF_SOURCE tex, vec2 uv, int level, int wrapMode, vec3 xi);
vec4 tf_ewa_stochastic(TF_SOURCE tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_trilinear_stochastic(TF_SOURCE tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi);
#endif
// END prototypes

#define TFI_FAMILY TFI_FAMILY_STOCHASTIC
#include "detail/instantiate.glsl"
#undef TFI_FAMILY

#endif
