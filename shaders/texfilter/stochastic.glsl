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
#include "instantiate.glsl"
#undef TFI_FAMILY

#elif defined(TFI_FAMILY)
#if TFI_FAMILY == TFI_FAMILY_STOCHASTIC // per resource kind (access.glsl); cube.glsl and latlong.glsl wrap the
// environment kinds' face-local forms in their direction forms (tf_trilinear_stochastic_cube, ...)

#if TFI_CAN_FETCH
vec4 tf_bilinear_stochastic_level(TFI_T, vec2 uv TFI_X, int level, int wrapMode, vec3 xi)
{
    if (!tf_finite(uv))
        return vec4(0.0);
    xi = tfi_unit3(xi);
    ivec2 size = tf_level_size(TFI_A, level);
    vec2 x = clamp(tf_reduce_uv(uv, wrapMode) * vec2(size) - 0.5, -TF_MAX_TEXEL_COORD, TF_MAX_TEXEL_COORD);
    vec2 i0 = floor(x);
    vec2 i = i0 + mix(vec2(0.0), vec2(1.0), lessThan(xi.xy, x - i0)); // i0 + 1 with probability frac(x)
    TF_COUNT_FETCHES(1);
    return TFI_FETCH(ivec2(TFI_WRAP(i.x, size.x, wrapMode), TFI_WRAP(i.y, size.y, wrapMode)), level);
}

// One trilinear probe at a clamped lod: its level chosen by xi.z, then one texel.
vec4 tfi_trilinear_stochastic_at(TFI_T, vec2 uv TFI_X, float lod, int wrapMode, vec3 xi)
{
    float rest;
    int level = tfi_stochastic_level(lod, xi.z, rest);
    return tf_bilinear_stochastic_level(TFI_A, uv TFI_XA, level, wrapMode, xi);
}

// ewa: one texel of `level`'s support, with probability weight / total (the CDF walked with u in [0, 1)).
vec4 tfi_ewa_stochastic_level(TFI_T, vec2 uv TFI_X, int level, int wrapMode, tfi_EwaShape shape, float alpha, float u)
{
    ivec2 size = tf_level_size(TFI_A, level);
    if (size == ivec2(1)) {
        TF_COUNT_FETCHES(1);
        return TFI_FETCH(ivec2(0), level);
    }
    vec3 M;
    float det;
    vec2 base, frac;
    tfi_ewa_level_ellipse(TFI_A, uv, level, wrapMode, shape, M, det, base, frac);
    vec2 rowSpan = tfi_ewa_rows(M, frac.y);
    int rows = int(clamp(rowSpan.y - rowSpan.x + 1.0, 0.0, float(TF_EWA_MAX_TEXELS)));
    float total = 0.0, target = 0.0, below = 0.0;
    vec2 chosen = vec2(0.0); // offsets from base: the centre's own texel unless a weight is found
    for (int pass = 0; pass < 2; ++pass) {
        bool found = false;
        for (int k = 0; k < TF_EWA_MAX_TEXELS; ++k) {
            if (k >= rows || found)
                break;
            float j = rowSpan.x + float(k), dy = j + 0.5 - frac.y;
            vec2 span = tfi_ewa_row_span(M, det, frac.x, dy);
            int cols = int(clamp(span.y - span.x + 1.0, 0.0, float(TF_EWA_MAX_TEXELS)));
            for (int n = 0; n < TF_EWA_MAX_TEXELS; ++n) {
                if (n >= cols)
                    break;
                float i = span.x + float(n), r2 = tfi_ewa_r2(M, det, i + 0.5 - frac.x, dy);
                float w = r2 < 1.0 ? tfi_ewa_weight(r2, alpha) : 0.0;
                if (pass == 0) {
                    total += w;
                } else if (w > 0.0) {
                    chosen = vec2(i, j); // the last texel of positive weight, should rounding end the walk early
                    if (target < below + w) {
                        found = true;
                        break;
                    }
                    below += w;
                }
            }
        }
        target = u * total;
    }
    TF_COUNT_FETCHES(1);
    return TFI_FETCH(ivec2(TFI_WRAP(base.x + chosen.x, size.x, wrapMode), TFI_WRAP(base.y + chosen.y, size.y, wrapMode)),
                     level);
}
#endif

#if TFI_HW
// ewa_hw: one 2x2 block of `level` with probability (its weight) / total, one bilinear tap at its weight centroid
// less the taps' common centroid offset (tfi_ewa_level_hw's taps): pass 0 sums weights and moments, pass 1 walks.
vec4 tfi_ewa_stochastic_level_hw(TFI_T, vec2 uv TFI_X, int level, int wrapMode, tfi_EwaShape shape, float alpha, float u)
{
    if (tf_level_size(TFI_A, level) == ivec2(1)) {
        TF_COUNT_HW_LOOKUPS(1);
        return TFI_LOOKUP(vec2(0.5), float(level));
    }
    vec3 M;
    float det;
    vec2 base, frac;
    tfi_ewa_level_ellipse(TFI_A, uv, level, wrapMode, shape, M, det, base, frac);
    vec2 size = vec2(tf_level_size(TFI_A, level));
    tfi_EwaBlocks blocks = tfi_ewa_blocks(M, base, frac); // ewa.glsl's walk, the hardware taps' blocks
    float weights = 0.0, target = 0.0, below = 0.0;
    vec2 moment = vec2(0.0), tap = base + 0.5; // tap: texel coordinate of the chosen block's centroid
    for (int pass = 0; pass < 2; ++pass) {
        bool found = false;
        for (int k = 0; k < TFI_EWA_MAX_BLOCKS; ++k) {
            if (k >= blocks.rows || found)
                break;
            float j0 = blocks.firstRow + 2.0 * float(k);
            float dy0 = j0 + 0.5 - frac.y;
            float firstCol;
            int cols = tfi_ewa_block_columns(M, det, frac, blocks.parity.x, dy0, firstCol);
            for (int n = 0; n < TFI_EWA_MAX_BLOCKS; ++n) {
                if (n >= cols)
                    break;
                float i0 = firstCol + 2.0 * float(n);
                float dx0 = i0 + 0.5 - frac.x;
                vec2 ab;
                float total = tfi_ewa_block(M, det, alpha, dx0, dy0, ab);
                if (!(total > 0.0))
                    continue;
                if (pass == 0) {
                    moment += total * (vec2(dx0, dy0) + ab);
                    weights += total;
                } else {
                    tap = base + vec2(i0, j0) + 0.5 + ab;
                    if (target < below + total) {
                        found = true;
                        break;
                    }
                    below += total;
                }
            }
        }
        target = u * weights;
    }
    vec2 shift = weights > 0.0 ? moment / weights : vec2(0.0);
    TF_COUNT_HW_LOOKUPS(1);
    return TFI_LOOKUP((tap - shift) / size, float(level));
}
#endif

// The families' shared body: `hardware` picks the tap form (a constant at every call: folded away).
vec4 tfi_trilinear_stochastic_impl(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi, bool hardware)
{
    if (!tf_finite(uv))
        return vec4(0.0);
    xi = tfi_unit3(xi);
    float lod = tf_lod(TFI_A, dUVdx, dUVdy, s);
    vec4 color = vec4(0.0); // one return from here on (common.glsl); a shadow sampler has only the _hw forms
#if TFI_HW
    if (hardware) {
        float rest;
        int level = tfi_stochastic_level(lod, xi.z, rest);
        TF_COUNT_HW_LOOKUPS(1);
        color = TFI_LOOKUP(tf_reduce_uv(uv, s.wrap), float(level));
    }
#endif
#if TFI_CAN_FETCH
    if (!hardware)
        color = tfi_trilinear_stochastic_at(TFI_A, uv TFI_XA, lod, s.wrap, xi);
#endif
    return color;
}

vec4 tfi_aniso_stochastic_impl(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape,
                               vec3 xi, bool hardware)
{
    if (!tf_finite(uv))
        return vec4(0.0);
    xi = tfi_unit3(xi);
    tfi_AnisoFootprint fp = tfi_aniso_footprint(TFI_A, dUVdx, dUVdy, s, maxProbes, shape);
    uv = tfi_aniso_centre(uv, fp.axis, s.wrap); // as tf_aniso (aniso.glsl)
    vec2 p = uv;
    if (fp.probes > 1) {
        float rest;
        p = uv + tfi_stochastic_probe(fp.probes, shape, xi.z, rest) * fp.axis;
        xi.z = rest;
    }
    vec4 color = vec4(0.0); // one return from here on (common.glsl)
#if TFI_HW
    if (hardware) {
        TF_COUNT_HW_LOOKUPS(1);
        color = TFI_LOOKUP(tf_reduce_uv(p, s.wrap), fp.lod); // the probe's hardware trilinear tap
    }
#endif
#if TFI_CAN_FETCH
    if (!hardware)
        color = tfi_trilinear_stochastic_at(TFI_A, p TFI_XA, fp.lod, s.wrap, xi);
#endif
    return color;
}

vec4 tfi_ewa_stochastic_impl(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso,
                             vec3 xi, bool hardware)
{
    if (!tf_finite(uv))
        return vec4(0.0);
    xi = tfi_unit3(xi);
    uv = tf_reduce_uv(uv, s.wrap);
    float a = alpha >= 0.0 ? min(alpha, 64.0) : 0.0;
    // Magnification (ewa.glsl): with probability level 0's trilinear share, the bilinear magnification filter at
    // one of its four spread points (tfi_ewa_magnified), a quarter of the share each, and there one texel (one
    // tap); the rest of xi.z, rescaled, picks the ellipse's level.
    float magnifyShare = 1.0 - clamp(tf_lod(TFI_A, dUVdx, dUVdy, s), 0.0, 1.0);
    vec4 color = vec4(0.0); // one return from here on (common.glsl)
    if (xi.z < magnifyShare) {
        vec2 spreadA, spreadB;
        tfi_ewa_spread(TFI_A, dUVdx, dUVdy, a, spreadA, spreadB);
        float point = min(floor(xi.z / magnifyShare * 4.0), 3.0); // 0..3: +a, -a, +b, -b as in tfi_ewa_magnified
        vec2 p = tf_reduce_uv(uv + (point < 2.0 ? spreadA : spreadB) * (mod(point, 2.0) == 0.0 ? 1.0 : -1.0), s.wrap);
#if TFI_HW
        if (hardware) {
            TF_COUNT_HW_LOOKUPS(1);
            color = TFI_LOOKUP(p, 0.0);
        }
#endif
#if TFI_CAN_FETCH
        if (!hardware)
            color = tf_bilinear_stochastic_level(TFI_A, p TFI_XA, 0, s.wrap, xi);
#endif
    } else {
        xi.z = clamp((xi.z - magnifyShare) / (1.0 - magnifyShare), 0.0, 0.99999994);
        float lambda, rest;
        tfi_EwaShape shape = tfi_ewa_shape(TFI_A, dUVdx, dUVdy, s, maxAniso, lambda);
        int level = tfi_stochastic_level(lambda, xi.z, rest);
#if TFI_HW
        if (hardware)
            color = tfi_ewa_stochastic_level_hw(TFI_A, uv TFI_XA, level, s.wrap, shape, a, xi.x);
#endif
#if TFI_CAN_FETCH
        if (!hardware)
            color = tfi_ewa_stochastic_level(TFI_A, uv TFI_XA, level, s.wrap, shape, a, xi.x);
#endif
    }
    return color;
}

#if TFI_MANUAL && !TFI_ENV
vec4 tf_bilinear_stochastic(TFI_T, vec2 uv TFI_X, tf_Sampler s, vec3 xi)
{
    return tf_bilinear_stochastic_level(TFI_A, uv TFI_XA, 0, s.wrap, xi);
}
vec4 tf_trilinear_stochastic(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi)
{
    return tfi_trilinear_stochastic_impl(TFI_A, uv TFI_XA, dUVdx, dUVdy, s, xi, false);
}
vec4 tf_aniso_stochastic(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape, vec3 xi)
{
    return tfi_aniso_stochastic_impl(TFI_A, uv TFI_XA, dUVdx, dUVdy, s, maxProbes, shape, xi, false);
}
vec4 tf_ewa_stochastic(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi)
{
    return tfi_ewa_stochastic_impl(TFI_A, uv TFI_XA, dUVdx, dUVdy, s, alpha, maxAniso, xi, false);
}
#endif

#if TFI_HW && !TFI_ENV
vec4 tf_bilinear_stochastic_hw(TFI_T, vec2 uv TFI_X, tf_Sampler s, vec3 xi)
{
    if (!tf_finite(uv))
        return vec4(0.0);
    TF_COUNT_HW_LOOKUPS(1);
    return TFI_LOOKUP(tf_reduce_uv(uv, s.wrap), 0.0); // the hardware's bilinear tap is already one tap
}
vec4 tf_trilinear_stochastic_hw(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi)
{
    return tfi_trilinear_stochastic_impl(TFI_A, uv TFI_XA, dUVdx, dUVdy, s, xi, true);
}
vec4 tf_aniso_stochastic_hw(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape,
                            vec3 xi)
{
    return tfi_aniso_stochastic_impl(TFI_A, uv TFI_XA, dUVdx, dUVdy, s, maxProbes, shape, xi, true);
}
vec4 tf_ewa_stochastic_hw(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso,
                          vec3 xi)
{
    return tfi_ewa_stochastic_impl(TFI_A, uv TFI_XA, dUVdx, dUVdy, s, alpha, maxAniso, xi, true);
}
#endif

#endif
#endif
