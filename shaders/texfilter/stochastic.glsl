// texfilter/stochastic.glsl — stochastic texture filtering (filtering after shading): bilinear, trilinear,
// aniso and ewa reading ONE texel (or ONE hardware tap) per lookup, chosen with probability equal to its
// weight in the deterministic filter, from a random number the caller supplies. The expected value over xi
// is the deterministic filter (ewa: see below); averaging frames (TAA, a path tracer's samples) converges
// to it at the rate the estimator's variance sets: sum_i w_i t_i² − mean², over N frames divided by N.
//
// Use:     vec4 tf_bilinear_stochastic(sampler2D tex, vec2 uv, tf_Sampler s, vec3 xi);            // level 0
//          vec4 tf_bilinear_stochastic_level(sampler2D tex, vec2 uv, int level, int wrapMode, vec3 xi);
//          vec4 tf_trilinear_stochastic(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi);
//          vec4 tf_aniso_stochastic(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes,
//                                   int shape, vec3 xi);
//          vec4 tf_ewa_stochastic(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha,
//                                 float maxAniso, vec3 xi);
//          and the hardware-tap forms, the same parameters: tf_bilinear_stochastic_hw, tf_trilinear_stochastic_hw,
//          tf_aniso_stochastic_hw, tf_ewa_stochastic_hw (one textureLod through the sampler bound with the
//          texture, LINEAR min/mag/mipmap with the wrap mode s.wrap, no bias, no narrower LOD clamp).
//          Every 2D resource kind (access.glsl): manual forms with texture2D, u/isampler2D, u/itexture2D,
//          sampler2DArray / texture2DArray + `int layer` after uv, depth + `tf_Compare cmp` after uv; _hw forms
//          with sampler2D, texture2D + sampler, the arrays, sampler2DShadow / texture2D + samplerShadow +
//          `float dref`. The environment maps: cube.glsl's and latlong.glsl's tf_X_stochastic_cube / _latlong
//          (and _hw), by direction, every texel read by the map's own rule as their deterministic forms read it.
// xi:      three numbers in [0, 1) for this lookup (white noise, a blue-noise texture, a low-discrepancy
//          sequence; the caller's choice, e.g. the harness's hash of pixel, frame and lookup). xi.x and xi.y
//          choose the texel of a bilinear footprint along x and y (ewa: xi.x alone, through the weights' CDF),
//          xi.z the level (trilinear, ewa) or the probe (aniso), whose unused part, rescaled to [0, 1), then
//          chooses the probe's level. Values outside [0, 1) are clamped into it.
// Math:    bilinear on level l: x = u·w_l − ½, i0 = floor(x), a = frac(x); texel i0 + 1 when xi.x < a.x, else
//          i0 (y alike): P = the bilinear weights, E = tf_bilinear_level. trilinear: λ = tf_lod, the coarser
//          level when xi.z < frac(λ): E = tf_trilinear. aniso: probe k with probability w_k / Σw (gpu: 1/N,
//          feline: its Gaussian), then the probe's trilinear as above: E = tf_aniso. _hw: the level (trilinear),
//          or the probe (aniso), chosen the same way, then one bilinear (trilinear: on the chosen level) or
//          trilinear (aniso: the probe's) tap: E = the deterministic _hw form; bilinear's _hw form is the
//          hardware bilinear tap itself, which needs no random number.
//          ewa: first its magnification (ewa.glsl): xi.z < 1 − clamp(λ, 0, 1) (λ trilinear's LOD) reads the
//          bilinear magnification filter's one texel of level 0 (_hw: its one tap) at one of its 4 footprint
//          points (tfi_ewa_spread; xi.z picks it, a quarter of the share each), and the rest of xi.z, rescaled,
//          goes on; TF_MAGNIFY's cubics are not sampled (Catmull-Rom's weights are not probabilities). Then
//          the ellipse's level as trilinear (xi.z < frac(λ): the coarser), then ONE texel of that level's support
//          with probability w_i / Σw (its Gaussian weights exp(−αr²) − exp(−αR²), ewa.glsl), found by walking
//          the CDF with xi.x. E = per level the Gaussian-weighted MEAN Σw_i t_i / Σw of the support's texels,
//          blended by frac(λ) (and the magnification share as in tf_ewa): NOT tf_ewa, whose least-squares line fit (not a convex combination of texels,
//          so no one-texel estimator has it as its mean) moves the mean to uv; the two differ by the fitted
//          gradient times the weights' centroid offset (at most ~0.1 level texel) and by the fit's range clamp.
//          tf_ewa_stochastic_hw: one 2x2 block of the level chosen with probability (its total weight) / Σ,
//          one bilinear tap at its weight centroid less the taps' common centroid offset: E = tf_ewa_hw
//          exactly (a positive-weighted mean of taps). host/reference/stochastic.cpp has the same expectations.
// Options: as the deterministic families (s.wrap, lodBias, lodMin, lodMax, maxProbes, shape, alpha, maxAniso,
//          TF_ANISO_RATIO_SLACK, TF_EWA_MAX_TEXELS). TF_MAGNIFY is not applied: level 0 is read bilinearly.
// Cost:    1 texel fetch (manual) or 1 hardware lookup (_hw) for every input. ALU: bilinear, trilinear O(1);
//          aniso up to 16 weights (feline); ewa evaluates its support's weights twice (no fetches), at most
//          2·K² (_hw: 2·(K/2+1)²) for K = TF_EWA_MAX_TEXELS: bounded whatever the footprint.
// Degenerate input (the deterministic families' rules, docs/API.md): non-finite uv gives vec4(0); huge uv is
//          moved by whole periods (tf_reduce_uv); NaN/±Inf gradients read the coarsest level, zero gradients the
//          finest; NaN xi counts as 0.
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

#define TFI_FAMILY TFI_FAMILY_STOCHASTIC
#include "detail/instantiate.glsl"
#undef TFI_FAMILY

#endif
