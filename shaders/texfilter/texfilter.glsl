// texfilter/texfilter.glsl — umbrella include: every texfilter include at once (version, common,
// derivatives, lod, nearest, bilinear, bicubic, trilinear, brilinear, aniso, ewa, ewa_fast, sat, cube,
// latlong, stochastic).
//
// Use:     #extension GL_GOOGLE_include_directive : require
//          #include "texfilter/texfilter.glsl"   // compile with -I<dir holding texfilter/>
//          Every function of the individual includes: each file's header and prototype list, docs/API.md.
//          Any stage (fragment, compute, ray tracing; #version 450 or 460, ray tracing 460): only
//          tf_quad_gradients_* need the fragment stage, tf_compute_quad_gradients TF_COMPUTE_QUADS.
//          Every filter takes the textures a renderer binds (docs/API.md "Resources"): sampler2D; texture2D
//          (+ sampler for _hw); sampler2DArray, texture2DArray (+ sampler) with `int layer` after uv;
//          u/isampler2D, u/itexture2D; depth maps with `tf_Compare cmp` after uv (PCF) or, for _hw,
//          sampler2DShadow / texture2D + samplerShadow with `float dref`; bindless arrays with TF_NONUNIFORM;
//          and, for the manual 2D families, your own texel source (TF_SOURCE, common.glsl).
// Options: the individual includes', defined before this include: TF_COUNT_FETCHES(n), TF_COUNT_HW_LOOKUPS(n),
//          TF_NONUNIFORM, TF_RESOURCES, TF_SOURCE, TF_MAGNIFY (common.glsl), TF_COMPUTE_QUADS (derivatives.glsl),
//          TF_ANISO_RATIO_SLACK (aniso.glsl), TF_EWA_MAX_TEXELS (ewa.glsl); per call: tf_Sampler (and
//          tf_Compare for depth maps).
// Needs:   what each called filter needs (its header). Nothing is declared here: no bindings, no push constants.
// Cost:    texel fetches a lookup: nearest 1, bilinear 4, bspline / catmull-rom 16 (_hw: 4 / 9 lookups),
//          trilinear 8 (4 on a level), brilinear 4 or 8, aniso 8 a probe (N <= 16), ewa_fast 1 to 9 lookups, ewa the texels in the
//          ellipse on 2 levels (capped by TF_EWA_MAX_TEXELS), sat 32 (<= 128), stochastic forms 1. Unused
//          functions cost nothing: compilers drop them.
// Degenerate input: each family's header; in short, non-finite uv or dir gives vec4(0), NaN/±Inf gradients
//          the coarsest level, zero gradients the finest, huge uv is moved by whole periods; no input makes a
//          loop run unbounded.
// Example: vec4 c = tf_trilinear(tex, uv, dFdxFine(uv), dFdyFine(uv), tf_sampler(TF_WRAP_REPEAT));
#ifndef TF_TEXFILTER_GLSL
#define TF_TEXFILTER_GLSL

#include "common.glsl"
#include "derivatives.glsl"
#include "lod.glsl"
#include "nearest.glsl"
#include "bilinear.glsl"
#include "bicubic.glsl"
#include "trilinear.glsl"
#include "brilinear.glsl"
#include "aniso.glsl"
#include "ewa.glsl"
#include "ewa_fast.glsl"
#include "sat.glsl"
#include "cube.glsl"
#include "latlong.glsl"
#include "stochastic.glsl"

#endif
