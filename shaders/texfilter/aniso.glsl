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

// BEGIN prototypes (generated: tests/prototypes.py --write; ctest prototypes.current checks it)
// Every overload below is defined by this file's detail/*_kind.glsl for the kinds its #if names.
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D) != 0
vec4 tf_aniso(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_hw(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D) != 0
vec4 tf_aniso(texture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_hw(texture2D tex, sampler smp, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D_ARRAY) != 0
vec4 tf_aniso(sampler2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_hw(sampler2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D_ARRAY) != 0
vec4 tf_aniso(texture2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_hw(texture2DArray tex, sampler smp, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
#endif
#if (TF_RESOURCES & TF_RESOURCE_INTEGER) != 0
vec4 tf_aniso(isampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso(itexture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso(usampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso(utexture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SHADOW) != 0
vec4 tf_aniso(sampler2D tex, vec2 uv, tf_Compare cmp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso(texture2D tex, vec2 uv, tf_Compare cmp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_hw(sampler2DShadow tex, vec2 uv, float dref, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_hw(texture2D tex, samplerShadow smp, vec2 uv, float dref, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE) != 0
vec4 tf_aniso(samplerCube tex, vec2 uv, int face, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso(textureCube tex, sampler smp, vec2 uv, int face, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_hw(samplerCube tex, vec2 uv, int face, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_hw(textureCube tex, sampler smp, vec2 uv, int face, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE_ARRAY) != 0
vec4 tf_aniso(samplerCubeArray tex, vec2 uv, int face, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso(textureCubeArray tex, sampler smp, vec2 uv, int face, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_hw(samplerCubeArray tex, vec2 uv, int face, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_hw(textureCubeArray tex, sampler smp, vec2 uv, int face, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
#endif
#if (TF_RESOURCES & TF_RESOURCE_LATLONG) != 0
vec4 tf_aniso(sampler2D tex, vec2 uv, tf_LatLong latlong, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_hw(sampler2D tex, vec2 uv, tf_LatLong latlong, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
#endif
#ifdef TF_SOURCE
vec4 tf_aniso(TF_SOURCE tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
#endif
// END prototypes

#define TFI_FAMILY TFI_FAMILY_ANISO
#include "detail/instantiate.glsl"
#undef TFI_FAMILY

#endif
