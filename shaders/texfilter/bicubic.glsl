// texfilter/bicubic.glsl — bicubic magnification: the cubic B-spline and Catmull-Rom reconstructions of one
// level, from 16 texelFetch reads or a few hardware bilinear taps; also TF_MAGNIFY's level-0 reconstruction.
//
// Use:     vec4 tf_bspline(sampler2D tex, vec2 uv, tf_Sampler s);        // level 0
//          vec4 tf_catmull_rom(sampler2D tex, vec2 uv, tf_Sampler s);    // level 0
//          vec4 tf_bspline_hw(sampler2D tex, vec2 uv, tf_Sampler s);     // level 0, hardware taps
//          vec4 tf_catmull_rom_hw(sampler2D tex, vec2 uv, tf_Sampler s); // level 0, hardware taps
//          vec4 tf_cubic_level(sampler2D tex, vec2 uv, int level, int wrapMode, int kernel);    // any level
//          vec4 tf_cubic_level_hw(sampler2D tex, vec2 uv, int level, int wrapMode, int kernel); // any level
//          Every resource kind (docs/API.md "Resources") has the same overloads, the texture replaced (manual:
//          texture2D, u/isampler2D, arrays + `int layer`, depth + `tf_Compare cmp`; _hw: texture2D + sampler,
//          arrays, shadow samplers + `float dref`), and a TF_SOURCE texel source (common.glsl) the manual ones.
//          The prototype list below.
// Math:    per axis on the level's grid: x = u·w_l − ½, i0 = floor(x), t = x − i0; texels i0−1 .. i0+2 weighted
//          by k(1+t), k(t), k(1−t), k(2−t). B-spline: k(d) = (4 − 6d² + 3|d|³)/6 for |d| < 1, (2 − |d|)³/6 for
//          |d| < 2 (C², positive, smooths: does not interpolate). Catmull-Rom (Keys, a = −½): 1.5|d|³ − 2.5d² + 1
//          for |d| < 1, −0.5|d|³ + 2.5d² − 4|d| + 2 for |d| < 2 (C¹, interpolates; negative lobes ring: results
//          may leave the texels' range by up to ~1/8 of a step).
// Options: s.wrap; kernel TF_RECONSTRUCT_BSPLINE, TF_RECONSTRUCT_CATMULL_ROM or TF_RECONSTRUCT_BILINEAR (the
//          bilinear lookup). TF_MAGNIFY (common.glsl) selects one of these kernels for level 0 in trilinear,
//          aniso and ewa. The level-0 forms are magnification filters: under minification they alias as
//          bilinear does.
// Needs:   manual: any sampler2D (texelFetch). _hw: a LINEAR sampler with the wrap mode s.wrap bound with the
//          texture; taps are rounded to its subTexelPrecisionBits (weights then differ from the manual form's
//          by up to 2^-bits a tap).
// Cost:    manual 16 texel fetches; _hw B-spline 4 hardware lookups, Catmull-Rom 9.
// Degenerate input: non-finite uv gives vec4(0); huge uv is moved by whole periods first (tf_reduce_uv).
// Example: vec4 c = tf_catmull_rom(tex, uv, tf_sampler(TF_WRAP_CLAMP));
//          #define TF_MAGNIFY TF_RECONSTRUCT_BSPLINE   // before the first include: smooth magnification
#ifndef TF_BICUBIC_GLSL
#define TF_BICUBIC_GLSL

// Hardware taps (_hw): texels whose weights have one sign merge into one bilinear tap placed between them by
// their weight ratio. B-spline: 2x2 taps (all weights positive; Sigg and Hadwiger's form). Catmull-Rom: 3x3
// taps, the middle two texels of each axis merged (both weights >= 0), the outer ones read at their centres:
// exact, where the common 2x2 form is an approximation.
// TF_MAGNIFY in the MIP filters: trilinear and each aniso probe blend (1 − f)·cubic(level 0) + f·bilinear(level 1)
// for λ in [0, 1) and read the cubic alone for λ <= 0; ewa (whose own Gaussian reconstructs every level) blends
// towards the cubic by the same share, 1 − clamp(λ, 0, 1) with λ trilinear's LOD. Level 0's share vanishes at
// λ = 1: no seam. Coarser levels stay bilinear: they are prefiltered, so the cubic's sharpness buys nothing.

#include "common.glsl"
#include "bilinear.glsl"

// Weights of texels i0−1, i0, i0+1, i0+2 at fraction t in [0, 1) (polynomial form of the kernels above;
// they sum to 1 for every t).
vec4 tfi_cubic_weights(float t, int kernel)
{
    float t2 = t * t, t3 = t2 * t, s = 1.0 - t;
    return kernel == TF_RECONSTRUCT_CATMULL_ROM // one return (common.glsl)
               ? 0.5 * vec4(-t * s * s, 2.0 - 5.0 * t2 + 3.0 * t3, t + 4.0 * t2 - 3.0 * t3, -t2 * s)
               : (1.0 / 6.0) * vec4(s * s * s, 4.0 - 6.0 * t2 + 3.0 * t3, 1.0 + 3.0 * (t + t2 - t3), t3);
}

// BEGIN prototypes (generated: tests/prototypes.py --write; ctest prototypes.current checks it)
// Every overload below is defined by this file's detail/*_kind.glsl for the kinds its #if names.
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D) != 0
vec4 tf_bspline(sampler2D tex, vec2 uv, tf_Sampler s);
vec4 tf_bspline_hw(sampler2D tex, vec2 uv, tf_Sampler s);
vec4 tf_catmull_rom(sampler2D tex, vec2 uv, tf_Sampler s);
vec4 tf_catmull_rom_hw(sampler2D tex, vec2 uv, tf_Sampler s);
vec4 tf_cubic_level(sampler2D tex, vec2 uv, int level, int wrapMode, int kernel);
vec4 tf_cubic_level_hw(sampler2D tex, vec2 uv, int level, int wrapMode, int kernel);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D) != 0
vec4 tf_bspline(texture2D tex, vec2 uv, tf_Sampler s);
vec4 tf_bspline_hw(texture2D tex, sampler smp, vec2 uv, tf_Sampler s);
vec4 tf_catmull_rom(texture2D tex, vec2 uv, tf_Sampler s);
vec4 tf_catmull_rom_hw(texture2D tex, sampler smp, vec2 uv, tf_Sampler s);
vec4 tf_cubic_level(texture2D tex, sampler smp, vec2 uv, int level, int wrapMode, int kernel);
vec4 tf_cubic_level(texture2D tex, vec2 uv, int level, int wrapMode, int kernel);
vec4 tf_cubic_level_hw(texture2D tex, sampler smp, vec2 uv, int level, int wrapMode, int kernel);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D_ARRAY) != 0
vec4 tf_bspline(sampler2DArray tex, vec2 uv, int layer, tf_Sampler s);
vec4 tf_bspline_hw(sampler2DArray tex, vec2 uv, int layer, tf_Sampler s);
vec4 tf_catmull_rom(sampler2DArray tex, vec2 uv, int layer, tf_Sampler s);
vec4 tf_catmull_rom_hw(sampler2DArray tex, vec2 uv, int layer, tf_Sampler s);
vec4 tf_cubic_level(sampler2DArray tex, vec2 uv, int layer, int level, int wrapMode, int kernel);
vec4 tf_cubic_level_hw(sampler2DArray tex, vec2 uv, int layer, int level, int wrapMode, int kernel);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D_ARRAY) != 0
vec4 tf_bspline(texture2DArray tex, vec2 uv, int layer, tf_Sampler s);
vec4 tf_bspline_hw(texture2DArray tex, sampler smp, vec2 uv, int layer, tf_Sampler s);
vec4 tf_catmull_rom(texture2DArray tex, vec2 uv, int layer, tf_Sampler s);
vec4 tf_catmull_rom_hw(texture2DArray tex, sampler smp, vec2 uv, int layer, tf_Sampler s);
vec4 tf_cubic_level(texture2DArray tex, sampler smp, vec2 uv, int layer, int level, int wrapMode, int kernel);
vec4 tf_cubic_level(texture2DArray tex, vec2 uv, int layer, int level, int wrapMode, int kernel);
vec4 tf_cubic_level_hw(texture2DArray tex, sampler smp, vec2 uv, int layer, int level, int wrapMode, int kernel);
#endif
#if (TF_RESOURCES & TF_RESOURCE_INTEGER) != 0
vec4 tf_bspline(isampler2D tex, vec2 uv, tf_Sampler s);
vec4 tf_bspline(itexture2D tex, vec2 uv, tf_Sampler s);
vec4 tf_bspline(usampler2D tex, vec2 uv, tf_Sampler s);
vec4 tf_bspline(utexture2D tex, vec2 uv, tf_Sampler s);
vec4 tf_catmull_rom(isampler2D tex, vec2 uv, tf_Sampler s);
vec4 tf_catmull_rom(itexture2D tex, vec2 uv, tf_Sampler s);
vec4 tf_catmull_rom(usampler2D tex, vec2 uv, tf_Sampler s);
vec4 tf_catmull_rom(utexture2D tex, vec2 uv, tf_Sampler s);
vec4 tf_cubic_level(isampler2D tex, vec2 uv, int level, int wrapMode, int kernel);
vec4 tf_cubic_level(itexture2D tex, vec2 uv, int level, int wrapMode, int kernel);
vec4 tf_cubic_level(usampler2D tex, vec2 uv, int level, int wrapMode, int kernel);
vec4 tf_cubic_level(utexture2D tex, vec2 uv, int level, int wrapMode, int kernel);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SHADOW) != 0
vec4 tf_bspline(sampler2D tex, vec2 uv, tf_Compare cmp, tf_Sampler s);
vec4 tf_bspline(texture2D tex, vec2 uv, tf_Compare cmp, tf_Sampler s);
vec4 tf_bspline_hw(sampler2DShadow tex, vec2 uv, float dref, tf_Sampler s);
vec4 tf_bspline_hw(texture2D tex, samplerShadow smp, vec2 uv, float dref, tf_Sampler s);
vec4 tf_catmull_rom(sampler2D tex, vec2 uv, tf_Compare cmp, tf_Sampler s);
vec4 tf_catmull_rom(texture2D tex, vec2 uv, tf_Compare cmp, tf_Sampler s);
vec4 tf_catmull_rom_hw(sampler2DShadow tex, vec2 uv, float dref, tf_Sampler s);
vec4 tf_catmull_rom_hw(texture2D tex, samplerShadow smp, vec2 uv, float dref, tf_Sampler s);
vec4 tf_cubic_level(sampler2D tex, vec2 uv, tf_Compare cmp, int level, int wrapMode, int kernel);
vec4 tf_cubic_level(texture2D tex, vec2 uv, tf_Compare cmp, int level, int wrapMode, int kernel);
vec4 tf_cubic_level_hw(sampler2DShadow tex, vec2 uv, float dref, int level, int wrapMode, int kernel);
vec4 tf_cubic_level_hw(texture2D tex, samplerShadow smp, vec2 uv, float dref, int level, int wrapMode, int kernel);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE) != 0
vec4 tf_cubic_level(samplerCube tex, vec2 uv, int face, int level, int wrapMode, int kernel);
vec4 tf_cubic_level(textureCube tex, sampler smp, vec2 uv, int face, int level, int wrapMode, int kernel);
vec4 tf_cubic_level_hw(samplerCube tex, vec2 uv, int face, int level, int wrapMode, int kernel);
vec4 tf_cubic_level_hw(textureCube tex, sampler smp, vec2 uv, int face, int level, int wrapMode, int kernel);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE_ARRAY) != 0
vec4 tf_cubic_level(samplerCubeArray tex, vec2 uv, int face, int layer, int level, int wrapMode, int kernel);
vec4 tf_cubic_level(textureCubeArray tex, sampler smp, vec2 uv, int face, int layer, int level, int wrapMode, int kernel);
vec4 tf_cubic_level_hw(samplerCubeArray tex, vec2 uv, int face, int layer, int level, int wrapMode, int kernel);
vec4 tf_cubic_level_hw(textureCubeArray tex, sampler smp, vec2 uv, int face, int layer, int level, int wrapMode, int kernel);
#endif
#if (TF_RESOURCES & TF_RESOURCE_LATLONG) != 0
vec4 tf_cubic_level(sampler2D tex, vec2 uv, tf_LatLong latlong, int level, int wrapMode, int kernel);
vec4 tf_cubic_level_hw(sampler2D tex, vec2 uv, tf_LatLong latlong, int level, int wrapMode, int kernel);
#endif
#ifdef TF_SOURCE
vec4 tf_bspline(TF_SOURCE tex, vec2 uv, tf_Sampler s);
vec4 tf_catmull_rom(TF_SOURCE tex, vec2 uv, tf_Sampler s);
vec4 tf_cubic_level(TF_SOURCE tex, vec2 uv, int level, int wrapMode, int kernel);
#endif
// END prototypes

#define TFI_FAMILY TFI_FAMILY_BICUBIC
#include "detail/instantiate.glsl"
#undef TFI_FAMILY

#endif
