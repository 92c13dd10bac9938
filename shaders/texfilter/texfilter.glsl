// texfilter/texfilter.glsl — umbrella include: every texfilter filter family at once.
//
// Use:     #extension GL_GOOGLE_include_directive : require
//          #include "texfilter/texfilter.glsl"
// Options: none beyond the individual includes'.
// Example: vec4 c = tf_trilinear(tex, uv, dFdxFine(uv), dFdyFine(uv), tf_sampler(TF_WRAP_REPEAT));
#ifndef TF_TEXFILTER_GLSL
#define TF_TEXFILTER_GLSL

#include "common.glsl"
#include "derivatives.glsl"
#include "lod.glsl"
#include "nearest.glsl"
#include "bilinear.glsl"
#include "trilinear.glsl"
#include "brilinear.glsl"
#include "aniso.glsl"
#include "ewa.glsl"
#include "sat.glsl"

#endif
