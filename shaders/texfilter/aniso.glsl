// texfilter/aniso.glsl — anisotropic filtering: N trilinear probes along the footprint's major axis.
//
// Use:     vec4 tf_aniso(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
//          vec4 tf_aniso_hw(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes,
//                           int shape); // the same probes as hardware trilinear lookups
//          Every resource kind (access.glsl, docs/API.md "Resources"): the manual form also with texture2D,
//          u/isampler2D, u/itexture2D, sampler2DArray / texture2DArray + `int layer` after uv, or a depth
//          sampler2D / texture2D + `tf_Compare cmp` after uv (percentage-closer filtering over the footprint);
//          the _hw form also with texture2D + sampler, sampler2DArray, texture2DArray + sampler (+ `int layer`),
//          sampler2DShadow or texture2D + samplerShadow + `float dref` after uv (each tap a hardware
//          comparison), e.g.
//          tf_aniso_hw(texture2D tex, sampler smp, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes,
//                      int shape).
// Options: s.wrap, s.lodBias, s.lodMin, s.lodMax as in lod.glsl; maxProbes N_max, clamped to
//          [1, TF_ANISO_MAX_PROBES = 16]; shape TF_ANISO_GPU or TF_ANISO_FELINE (any other value: TF_ANISO_GPU).
//          TF_ANISO_RATIO_SLACK: define before including (default 1.0 / 64.0): the slack s_r in N below,
//          which keeps near-isotropic footprints at one probe instead of flipping between 1 and 2.
//          TF_MAGNIFY (common.glsl): probes reconstruct level 0 with a cubic (bicubic.glsl): 16 fetches, or
//          4 (B-spline) / 9 (Catmull-Rom) taps plus one of level 1 for the _hw form's probes with lod < 1.
//          J = [dUVdx dUVdy] in level-0 texels (DESIGN.md §3).
//   TF_ANISO_GPU (the Vulkan / EXT_texture_filter_anisotropic model): Px = |J e_x|, Py = |J e_y|,
//          N = min(ceil(Pmax/Pmin − s_r), N_max), λ = log2(Pmax/N) + lodBias, then lodMin/lodMax and the
//          levels clamp it as in tf_lod. The major column A (dUVdx if Px >= Py, else dUVdy) is cut into N equal
//          pieces, one probe at the centre of each: uv + ((k + ½)/N − ½)·A, k = 0..N−1, weights 1/N.
//          N = 1 is tf_trilinear, bit for bit.
//   TF_ANISO_FELINE (after McCormack et al., "Feline", 1999): the pixel's pre-image as the ellipse
//          J·(disk of radius ½), whose full axes are the singular values σ1 >= σ2 of J = U diag(σ1, σ2) Vᵀ
//          (a closed-form 2x2 SVD: no atan, no iteration). The probes lie on the true major axis
//          A = σ1·u1 (u1 = U e_x) at the same places as above, uv + t_k·A, t_k = (k + ½)/N − ½, with
//          N = min(ceil(σ1/σ2 − s_r), N_max) and λ = log2(max(σ2, σ1/N)) + lodBias: the minor axis's LOD,
//          coarser only where N_max runs out. Weights: a Gaussian along the axis, w_k ∝ exp(−2 x_k²) with
//          x_k = 2 t_k in (−1, 1) the place in half major axes (α = 2, tf_ewa's default), i.e.
//          σ = σ1/4 texels: a quarter pixel along the major axis, about what each probe's own trilinear
//          footprint gives across it, so the filter is roughly round in screen space. Weights sum to 1.
//          N = 1 is one trilinear probe at λ = log2(σ1): tf_trilinear where J's columns are orthogonal
//          (then σ1 = max(Px, Py)), a little blurrier where they are not.
// Needs:   tex with a full MIP chain. tf_aniso: any sampler2D (every probe from texelFetch, two bilinear
//          levels, like tf_trilinear). tf_aniso_hw: each probe is one textureLod(tex, uv_k, λ) through the
//          sampler bound with the texture, which must filter linearly in both (min/mag and mipmapMode)
//          with the wrap mode in s.wrap, and apply no bias (λ already holds it) and no LOD clamp narrower
//          than the levels. It differs from tf_aniso only by the sampler's precision
//          (subTexelPrecisionBits, mipmapPrecisionBits).
// Cost:    tf_aniso 8N texel fetches (4N where λ sits on a level or is clamped to the last one),
//          tf_aniso_hw N hardware lookups; N <= 16 for every input, the loop never runs more than 16 times.
//          Plane scene, N_max 16 (docs/FILTERS.md): 31.5 fetches on average (max 128); hardware taps 4.9.
// Degenerate input: zero gradients give one probe on the finest level (λ clamped from −∞); NaN or ±Inf
//          gradients (or a J entry past float range, |dUVdx|·size >= 2^128) give one probe on the
//          coarsest level, as tf_lod does; a zero minor axis (one column zero, parallel columns) gives
//          N = N_max; non-finite uv gives vec4(0); huge uv (and probes far outside [0, 1]) is moved by whole
//          periods before each lookup (tf_reduce_uv), in both forms.
// Example: vec4 c = tf_aniso(tex, uv, dFdxFine(uv), dFdyFine(uv), tf_sampler(TF_WRAP_REPEAT), 16, TF_ANISO_GPU);
#ifndef TF_ANISO_GLSL
#define TF_ANISO_GLSL

#include "bicubic.glsl" // tfi_mip_level, tfi_magnified_level0: TF_MAGNIFY on level 0
#include "lod.glsl"

#define TF_ANISO_GPU 0
#define TF_ANISO_FELINE 1

const int TF_ANISO_MAX_PROBES = 16; // hard cap on probes (and loop iterations) for any input

// Where the probes go: uv + ((k + ½)/probes − ½)·axis, k = 0..probes−1, all on LOD `lod`.
struct tfi_AnisoFootprint {
    vec2 axis;   // the whole major axis in uv units (zero when probes == 1)
    int probes;  // N in [1, TF_ANISO_MAX_PROBES]
    float lod;   // biased and clamped like tf_lod
};

// ceil(ratio − slack) capped at maxN; +Inf or NaN (0/0, Inf/Inf) gives maxN. The slack keeps isotropic
// footprints (screen-facing surfaces: ratio 1 up to float noise in the quad derivatives) at one probe
// instead of flipping between 1 and 2 from pixel to pixel; a ratio of 1 + 1/64 needs no second probe.
#ifndef TF_ANISO_RATIO_SLACK
#define TF_ANISO_RATIO_SLACK (1.0 / 64.0)
#endif
int tfi_aniso_count(float ratio, int maxN)
{
    return ratio < float(maxN) ? max(1, int(ceil(ratio - TF_ANISO_RATIO_SLACK))) : maxN;
}

// The probes' centre, moved before their offsets are added (each probe is reduced again), so that a large
// uv's rounding does not swallow the offsets (at uv = 1e6 they moved by 1/16) and no probe overflows near
// float's range. Repeat and mirror: by whole periods (as tf_reduce_uv; exact). Clamp: to [−1 − h, 2 + h],
// h = |axis|/2, which leaves every probe past the edge it was past (the same edge texels) and the rest
// where they were; tf_reduce_uv's [−1, 2] would move a long footprint that reaches into the texture.
vec2 tfi_aniso_centre(vec2 uv, vec2 axis, int wrapMode)
{
    vec2 h = 0.5 * abs(axis);
    return wrapMode == TF_WRAP_CLAMP ? clamp(uv, -1.0 - h, 2.0 + h) : tfi_whole_periods(uv);
}

#define TFI_FAMILY TFI_FAMILY_ANISO
#include "instantiate.glsl"
#undef TFI_FAMILY

#elif defined(TFI_FAMILY)
#if TFI_FAMILY == TFI_FAMILY_ANISO && 1 // per resource kind (access.glsl)

#if TFI_OWNS_T
tfi_AnisoFootprint tfi_aniso_footprint(TFI_T, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape)
{
    int maxN = clamp(maxProbes, 1, TF_ANISO_MAX_PROBES);
    tfi_AnisoFootprint fp = tfi_AnisoFootprint(vec2(0.0), 1, 0.0);
    vec2 size0 = vec2(TFI_SIZE0);
    vec2 ax = dUVdx * size0, ay = dUVdy * size0; // the columns of J, in level-0 texels
    float m = max(max(abs(ax.x), abs(ax.y)), max(abs(ay.x), abs(ay.y)));
    if (!(m > 0.0) || isinf(m) || !tf_finite(dUVdx) || !tf_finite(dUVdy)) {
        // Zero gradients: λ = −∞, the finest level. NaN/±Inf (or past float range in texels): +∞, the coarsest.
        fp.lod = tf_lod(TFI_A, dUVdx, dUVdy, s);
        return fp;
    }
    // J scaled by a power of two so that its largest entry is in [½, 1): the scale is exact, and nothing
    // below overflows; a minor axis below ~1e-19 of the major one underflows to zero (N = N_max either way).
    int e;
    frexp(m, e);
    vec2 cx = ldexp(ax, ivec2(-e)), cy = ldexp(ay, ivec2(-e));

    if (shape != TF_ANISO_FELINE) {
        float px2 = dot(cx, cx), py2 = dot(cy, cy);
        fp.probes = tfi_aniso_count(sqrt(max(px2, py2) / min(px2, py2)), maxN);
        tf_Sampler t = s;
        if (fp.probes > 1) { // log2(Pmax/N) + bias = log2(Pmax) + (bias − log2 N); N = 1 stays tf_lod exactly
            t.lodBias -= tfi_log2(float(fp.probes));
            fp.axis = px2 >= py2 ? dUVdx : dUVdy; // ties: dUVdx
        }
        fp.lod = tf_lod(TFI_A, dUVdx, dUVdy, t);
        return fp;
    }

    // Feline. Closed-form 2x2 SVD of J = [a b; c d] (columns cx, cy): with E = (a+d)/2, F = (a−d)/2,
    // G = (c+b)/2, H = (c−b)/2, Q = |(E, H)|, R = |(F, G)|, the singular values are Q + R and |Q − R|, and u1
    // lies at half the angle of the complex product (F + iG)(E + iH).
    float E = 0.5 * (cx.x + cy.y), F = 0.5 * (cx.x - cy.y);
    float G = 0.5 * (cx.y + cy.x), H = 0.5 * (cx.y - cy.x);
    float Q = length(vec2(E, H)), R = length(vec2(F, G));
    float major = Q + R, minor = abs(Q - R); // σ1, σ2 times 2^-e
    fp.probes = tfi_aniso_count(major / minor, maxN);
    float lambda = float(e) + tfi_log2(max(minor, major / float(fp.probes))) + s.lodBias;
    fp.lod = tfi_clamp_lod(lambda, s, TFI_A);
    if (fp.probes > 1) { // then major > minor, so R > 0, Q > 0 and z != 0
        vec2 z = vec2(F * E - G * H, F * H + G * E);
        float r = length(z);
        vec2 u1 = normalize(z.x >= 0.0 ? vec2(r + z.x, z.y) : vec2(z.y, r - z.x)); // half angle, up to sign
        fp.axis = ldexp(major * u1 / size0, ivec2(e));
    }
    return fp;
}
#endif

// One trilinear probe at a given LOD in [0, levels−1], from texelFetch: tf_trilinear's blend.
vec4 tfi_aniso_probe(TFI_T, vec2 uv TFI_X, float lod, int wrapMode)
{
#if !TFI_CAN_FETCH
    return vec4(0.0); // no texelFetch on this kind: it has only the _hw entry points, which never come here
#else
    float f;
    int lo = tfi_split_lod(lod, f);
#define TFI_PROBE_LEVEL(level) tfi_mip_level(TFI_A, uv TFI_XA, level, wrapMode)
    vec4 color;
    TFI_BLEND_LEVELS_ONCE(color, TFI_PROBE_LEVEL, lo, f); // each level's fetches issued once (lod.glsl)
    return color;
#undef TFI_PROBE_LEVEL
#endif
}

// One trilinear probe through the hardware sampler, at uv moved by whole periods as the manual form's
// bilinear lookups do (a sampler given |uv| >= ~1e37 returns NaN on lavapipe: uv·size overflows).
// With TF_MAGNIFY, a probe that reads level 0 (lod < 1) takes TF_MAGNIFY's taps there and one bilinear tap
// of level 1, blended as trilinear blends them.
vec4 tfi_aniso_probe_hw(TFI_T, vec2 uv TFI_X, float lod, int wrapMode)
{
    uv = tf_reduce_uv(uv, wrapMode);
    vec4 color; // one return (common.glsl): TF_MAGNIFY is a constant
    if (TF_MAGNIFY != TF_RECONSTRUCT_BILINEAR && lod < 1.0) {
        color = tfi_magnified_level0(TFI_A, uv TFI_XA, wrapMode, true);
        if (lod > 0.0) {
            TF_COUNT_HW_LOOKUPS(1);
            color = mix(color, TFI_LOOKUP(uv, 1.0), lod);
        }
    } else {
        TF_COUNT_HW_LOOKUPS(1);
        color = TFI_LOOKUP(uv, lod);
    }
    return color;
}

vec4 tfi_aniso_filter(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape,
                     bool hardware)
{
    if (!tf_finite(uv))
        return vec4(0.0);
    tfi_AnisoFootprint fp = tfi_aniso_footprint(TFI_A, dUVdx, dUVdy, s, maxProbes, shape);
    uv = tfi_aniso_centre(uv, fp.axis, s.wrap);
    if (fp.probes == 1)
        return hardware ? tfi_aniso_probe_hw(TFI_A, uv TFI_XA, fp.lod, s.wrap) : tfi_aniso_probe(TFI_A, uv TFI_XA, fp.lod, s.wrap);
    vec4 sum = vec4(0.0);
    float weights = 0.0;
    for (int k = 0; k < TF_ANISO_MAX_PROBES; ++k) {
        if (k >= fp.probes)
            break;
        float t = (float(k) + 0.5) / float(fp.probes) - 0.5;
        float w = shape == TF_ANISO_FELINE ? exp(-8.0 * t * t) : 1.0;
        vec2 p = uv + t * fp.axis;
        sum += w * (hardware ? tfi_aniso_probe_hw(TFI_A, p TFI_XA, fp.lod, s.wrap) : tfi_aniso_probe(TFI_A, p TFI_XA, fp.lod, s.wrap));
        weights += w;
    }
    return sum / weights;
}

#if TFI_MANUAL
vec4 tf_aniso(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape)
{
    return tfi_aniso_filter(TFI_A, uv TFI_XA, dUVdx, dUVdy, s, maxProbes, shape, false);
}
#endif

#if TFI_HW
vec4 tf_aniso_hw(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape)
{
    return tfi_aniso_filter(TFI_A, uv TFI_XA, dUVdx, dUVdy, s, maxProbes, shape, true);
}
#endif

#endif
#endif
