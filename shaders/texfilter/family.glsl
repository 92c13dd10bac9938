// texfilter/family.glsl — internal: includes the family file that TFI_FAMILY names, for instantiate.glsl
// (an #include cannot take its file name from a macro). No include guard on purpose.
//
// Use:     only through instantiate.glsl. Options, cost: none. Example: see instantiate.glsl.
#if !defined(TFI_FAMILY) || !defined(TFI_KIND)
#error "texfilter/family.glsl is internal: include a family (e.g. texfilter/trilinear.glsl)"
#elif TFI_FAMILY == TFI_FAMILY_COMMON
#include "common.glsl"
#elif TFI_FAMILY == TFI_FAMILY_LOD
#include "lod.glsl"
#elif TFI_FAMILY == TFI_FAMILY_NEAREST
#include "nearest.glsl"
#elif TFI_FAMILY == TFI_FAMILY_BILINEAR
#include "bilinear.glsl"
#elif TFI_FAMILY == TFI_FAMILY_TRILINEAR
#include "trilinear.glsl"
#elif TFI_FAMILY == TFI_FAMILY_BRILINEAR
#include "brilinear.glsl"
#elif TFI_FAMILY == TFI_FAMILY_ANISO
#include "aniso.glsl"
#elif TFI_FAMILY == TFI_FAMILY_EWA
#include "ewa.glsl"
#elif TFI_FAMILY == TFI_FAMILY_SAT
#include "sat.glsl"
#elif TFI_FAMILY == TFI_FAMILY_CUBE
#include "cube.glsl"
#elif TFI_FAMILY == TFI_FAMILY_LATLONG
#include "latlong.glsl"
#elif TFI_FAMILY == TFI_FAMILY_BICUBIC
#include "bicubic.glsl"
#elif TFI_FAMILY == TFI_FAMILY_STOCHASTIC
#include "stochastic.glsl"
#else
#error "texfilter/family.glsl: unknown TFI_FAMILY"
#endif
