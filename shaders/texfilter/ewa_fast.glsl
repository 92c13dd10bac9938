// texfilter/ewa_fast.glsl — a fast elliptical filter: at most 9 hardware trilinear lookups placed so that their
// weighted sum has the covariance of tf_ewa's Gaussian (Feline, McCormack et al. 1999, with the LOD and the
// probes' spread matched to the pixel's covariance instead of to the ellipse's axes).
//
// Use:     vec4 tf_ewa_fast(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
//          Every resource kind with a sampler has the same overload (texture2D + sampler, arrays + `int layer`
//          after uv, sampler2DShadow / texture2D + samplerShadow + `float dref` after uv, cube faces, lat-long):
//          the prototype list near the end of this file. No manual (texelFetch) form: use tf_ewa.
// Math:    J = [dUVdx dUVdy]·size in level-0 texels, σ1² >= σ2² the eigenvalues of J·Jᵀ, u1 the major axis.
//          Target: the pixel's Gaussian (σ = ½ pixel, k² = ¼ pixel², tf_ewa's alpha 2) over the bilinear level 0,
//          in level-0 texels C = k²·J·Jᵀ + I/6 (1/6: the tent's variance). A hardware trilinear lookup at LOD λ
//          has P(λ) = 4^λ/4 − 1/12 a axis (level l's tent 4^l/6 plus the MIP box's (4^l − 1)/12; 1/6 on
//          level 0), so the probes' positions must carry S = C − P(λ)·I = ¼·(4k²·J·Jᵀ + (1 − 4^λ)·I): along
//          u1 s1² = (A − 4^λ)/4, across s2² = (B − 4^λ)/4, A = 4k²σ1² + 1, B = 4k²σ2² + 1. Two layouts:
//          triangle (A < ROW_FROM·B, near-isotropic, no axis needed): 3 equal-weight probes at uv + √2·√S·e_k,
//            e_k at 90°, 210°, 330° (their covariance √S·(2·½I)·√S = S; √S in closed form, continuous in J);
//            pairwise √6·s apart, at most c texels of the level: 4^λ = A/(1 + 2c²/3).
//          row (otherwise): 2h + 1 probes, t = −h..h, at uv + t·Δ·u1 + ((−1)^t − m)·d·u2, weights
//            w_t = exp(−t²/(2ρ²)), ρ = h/1.5, V(h) = Σw·t²/Σw (0.394, 1.300, 2.693, 4.577 for h = 1..4),
//            m = Σw·(−1)^t/Σw: variance Δ²·V(h) along u1, d²·(1 − m²) across (the zigzag), no cross term (the
//            weights are symmetric); Δ = s1/√V(h) <= c texels (tents one texel apart sum flat: no ripple),
//            d = s2/√(1 − m²) <= c/2; h = ceil(2·s1/(c·2^λ) − 0.3) <= 4; 4^λ = max(B/(1 + c²), A/(1 + 4·V(4)·c²),
//            g·A/(1 + 2c²/3)): past what 9 probes reach (about 4.4:1) the LOD rises, so the probes widen instead of
//            leaving gaps; g = clamp(2 − A/(ROW_FROM·B), 0, 1) starts the row on the triangle's LOD where the
//            layouts meet (ROW_FROM = 1.5), so λ is continuous in the footprint.
//          c = 1 texel. λ + lodBias clamped as tf_lod; a clamp that holds λ lower keeps the spacing at c (the
//          footprint shrinks: it aliases, like any LOD clamp). So the sum has C's second moments wherever the
//          clamps allow; one probe where the triangle's (tr √S)² < 1e-6 texels² (a zero footprint).
// Options: s.wrap, s.lodBias, s.lodMin, s.lodMax as every filter. None of its own: the probe cap (9), the
//          pixel's Gaussian (σ = ½ pixel) and the spacing are the filter's definition.
// Needs:   a full MIP chain; the sampler bound with the texture filters linearly (min, mag, mipmapMode LINEAR)
//          with the wrap mode s.wrap, no LOD bias, no LOD clamp narrower than the levels (as tf_aniso_hw).
// Cost:    hardware trilinear lookups (textureLod), no texel fetch: 3 for near-isotropic footprints (the
//          triangle), 2h + 1 <= min(9, 2·ceil(σ1/2^λ − 0.3) + 1) along the row (s1 <= σ1/2), 1 for a zero or
//          non-finite footprint; at most 9 whatever the input (docs/BENCHMARKS.md: the bench scenes average 3-8).
// Degenerate input: zero gradients → one lookup on level 0 (the finest level the clamps allow); NaN or ±Inf
//          in a gradient, or a footprint past float range → one lookup on the coarsest level allowed; a zero
//          minor axis → a row whose LOD the major axis sets. Non-finite uv → vec4(0); huge uv: the probes'
//          centre is moved by whole periods (clamp: to [−1 − h, 2 + h], h half the layout's extent) and each
//          probe reduced again before its lookup (tf_reduce_uv), as tf_aniso_hw.
// Example: vec4 c = tf_ewa_fast(tex, uv, dFdxFine(uv), dFdyFine(uv), tf_sampler(TF_WRAP_REPEAT));
#ifndef TF_EWA_FAST_GLSL
#define TF_EWA_FAST_GLSL

#include "aniso.glsl" // tfi_aniso_centre, tfi_aniso_probe_hw: one hardware trilinear probe
#include "ewa.glsl"   // tfi_ewa_shape: the footprint's eigenvalues and axis, its degenerate cases

const int TFI_EWA_FAST_MAX_HALF = 4;            // h <= 4: at most 9 probes
const float TFI_EWA_FAST_PIXEL_VARIANCE = 0.25; // k²: the pixel's Gaussian, σ = ½ pixel
const float TFI_EWA_FAST_SPACING = 1.0;         // c: the largest probe spacing, in texels of the probes' level
const float TFI_EWA_FAST_PROFILE = 1.5;         // ρ = h/1.5: the outer probes weigh exp(−1.125) = 0.32
const float TFI_EWA_FAST_MAX_VARIANCE = 4.5768; // V(4): the weighted index variance of 9 probes
// How far (in 4^λ, over the target's A or B) each layout reaches at spacing c: the row of 9 along its axis
// (1 + 4·V(4)·c²), its zigzag across (amplitude c/2: 1 + c²), the triangle (pairwise √6·s <= c: 1 + 2c²/3).
const float TFI_EWA_FAST_ROW_REACH = 1.0 + 4.0 * TFI_EWA_FAST_MAX_VARIANCE * TFI_EWA_FAST_SPACING * TFI_EWA_FAST_SPACING;
const float TFI_EWA_FAST_ZIGZAG_REACH = 1.0 + TFI_EWA_FAST_SPACING * TFI_EWA_FAST_SPACING;
const float TFI_EWA_FAST_TRIANGLE_REACH = 1.0 + 2.0 / 3.0 * TFI_EWA_FAST_SPACING * TFI_EWA_FAST_SPACING;
// A/B (σ1²/σ2² for large footprints) from which the row is used; below it the triangle (it needs no axis).
const float TFI_EWA_FAST_ROW_FROM = 1.5;
// u1's sign: dot(u1, side) >= 0. The zigzag is not symmetric under u1 -> −u1, so the sign is fixed, by a
// direction whose perpendicular (126.87°) no axis-aligned or diagonal footprint has.
const vec2 TFI_EWA_FAST_SIDE = vec2(0.8, 0.6);
// The triangle's spread (tr √S)² below this many texels² of its level: one probe does (a zero footprint).
const float TFI_EWA_FAST_ONE_PROBE = 1e-6;

// Probe t's weight of the row t = −h..h: exp(−t²/(2ρ²)), ρ = h/1.5.
float tfi_ewa_fast_weight(int t, int h)
{
    float x = TFI_EWA_FAST_PROFILE * float(t) / float(h);
    return exp(-0.5 * x * x);
}

// The row's weights summed: (Σ w_t, Σ w_t·t², Σ w_t·(−1)^t) over t = −h..h. V(h) = y/x; the zigzag's mean
// offset, in units of its amplitude, z/x.
vec3 tfi_ewa_fast_moments(int h)
{
    vec3 sum = vec3(1.0, 0.0, 1.0);
    for (int t = 1; t <= TFI_EWA_FAST_MAX_HALF; ++t) {
        if (t > h)
            break;
        float w = 2.0 * tfi_ewa_fast_weight(t, h);
        sum += vec3(w, w * float(t * t), (t & 1) == 0 ? w : -w);
    }
    return sum;
}

// BEGIN prototypes (generated: tests/prototypes.py --write; ctest prototypes.current checks it)
// Every overload below is defined by this file's detail/*_kind.glsl for the kinds its #if names.
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D) != 0
vec4 tf_ewa_fast(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D) != 0
vec4 tf_ewa_fast(texture2D tex, sampler smp, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D_ARRAY) != 0
vec4 tf_ewa_fast(sampler2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D_ARRAY) != 0
vec4 tf_ewa_fast(texture2DArray tex, sampler smp, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SHADOW) != 0
vec4 tf_ewa_fast(sampler2DShadow tex, vec2 uv, float dref, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_ewa_fast(texture2D tex, samplerShadow smp, vec2 uv, float dref, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE) != 0
vec4 tf_ewa_fast(samplerCube tex, vec2 uv, int face, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_ewa_fast(textureCube tex, sampler smp, vec2 uv, int face, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE_ARRAY) != 0
vec4 tf_ewa_fast(samplerCubeArray tex, vec2 uv, int face, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
vec4 tf_ewa_fast(textureCubeArray tex, sampler smp, vec2 uv, int face, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
#if (TF_RESOURCES & TF_RESOURCE_LATLONG) != 0
vec4 tf_ewa_fast(sampler2D tex, vec2 uv, tf_LatLong latlong, vec2 dUVdx, vec2 dUVdy, tf_Sampler s);
#endif
// END prototypes

#define TFI_FAMILY TFI_FAMILY_EWA_FAST
#include "detail/instantiate.glsl"
#undef TFI_FAMILY

#endif
