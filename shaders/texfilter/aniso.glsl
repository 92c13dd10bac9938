// texfilter/aniso.glsl — anisotropic filtering: N trilinear probes along the footprint's major axis.
//
// Use:     vec4 tf_aniso(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape);
//          vec4 tf_aniso_hw(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes,
//                           int shape); // the same probes as hardware trilinear lookups
//          Every resource kind (docs/API.md "Resources") has the same overloads, the texture replaced: manual
//          with texture2D, u/isampler2D, u/itexture2D, arrays + `int layer` after uv, depth + `tf_Compare cmp`
//          after uv; _hw with texture2D + sampler, arrays, sampler2DShadow / texture2D + samplerShadow +
//          `float dref` after uv. A TF_SOURCE texel source (common.glsl): tf_aniso only. The prototype list below.
// Math:    J = [dUVdx dUVdy] in level-0 texels. TF_ANISO_GPU (Vulkan / EXT_texture_filter_anisotropic):
//          Px = |J e_x|, Py = |J e_y|, N = min(ceil(Pmax/Pmin − slack), maxProbes), λ = log2(Pmax/N) + lodBias,
//          clamped as tf_lod; probe k at uv + ((k + ½)/N − ½)·A, A the longer column, weights 1/N. N = 1 is
//          tf_trilinear bit for bit. TF_ANISO_FELINE (McCormack et al. 1999): the same placement on the true
//          major axis σ1·u1 of J = U diag(σ1, σ2) Vᵀ, N from σ1/σ2, λ = log2(max(σ2, σ1/N)) + lodBias,
//          Gaussian weights along the axis (σ = σ1/4 texels), summing to 1.
// Options: maxProbes clamped to [1, TF_ANISO_MAX_PROBES = 16]; shape TF_ANISO_GPU or TF_ANISO_FELINE (other
//          values: GPU); s.wrap, s.lodBias, s.lodMin, s.lodMax. TF_ANISO_RATIO_SLACK (define before including;
//          default 1.0 / 64.0): near-isotropic footprints keep one probe. TF_MAGNIFY (common.glsl): probes with
//          λ < 1 reconstruct level 0 with a cubic (bicubic.glsl).
// Needs:   a full MIP chain. tf_aniso: texelFetch only. tf_aniso_hw: each probe is textureLod(tex, uv_k, λ)
//          through the bound sampler, which must be LINEAR (min, mag, mipmapMode) with the wrap mode s.wrap, no
//          LOD bias and no LOD clamp narrower than the levels; it then differs from tf_aniso only by the
//          sampler's subTexelPrecisionBits and mipmapPrecisionBits.
// Cost:    tf_aniso 8N texel fetches (4N where λ sits on a level or is clamped to the last one); tf_aniso_hw
//          N hardware lookups; N <= 16 for every input. TF_MAGNIFY's cubic on level 0: 16 fetches a probe
//          (_hw: 4 B-spline / 9 Catmull-Rom taps plus one of level 1).
// Degenerate input: zero gradients give one probe on the finest level; NaN or ±Inf gradients (or J past
//          float range) one probe on the coarsest level; a zero minor axis (a zero or parallel column) gives
//          N = maxProbes; non-finite uv gives vec4(0); huge uv is moved by whole periods before each lookup.
// Example: vec4 c = tf_aniso(tex, uv, dFdxFine(uv), dFdyFine(uv), tf_sampler(TF_WRAP_REPEAT), 16, TF_ANISO_GPU);
#ifndef TF_ANISO_GLSL
#define TF_ANISO_GLSL

// Feline in full: the pixel's pre-image is the ellipse J·(disk of radius ½), whose full axes are the singular
// values σ1 >= σ2 of J (a closed-form 2x2 SVD: no atan, no iteration). Probes at uv + t_k·σ1·u1 (u1 = U e_x),
// t_k = (k + ½)/N − ½, N = min(ceil(σ1/σ2 − slack), maxProbes); weights w_k ∝ exp(−2 x_k²) with x_k = 2 t_k
// in (−1, 1), the place in half major axes (α = 2, tf_ewa's default): σ = σ1/4 texels, a quarter pixel along
// the major axis, about what each probe's own trilinear footprint gives across it, so the filter is roughly
// round in screen space. The LOD is the minor axis's, coarser only where maxProbes runs out. N = 1 is one
// trilinear probe at λ = log2(σ1): tf_trilinear where J's columns are orthogonal (σ1 = max(Px, Py)), a little
// blurrier where they are not. Both shapes: a J entry past float range (|dUVdx|·size >= 2^128) counts as
// non-finite, as in tf_lod.

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
