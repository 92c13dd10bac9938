// texfilter/detail/family.glsl — internal: includes the per-kind part of the family that TFI_FAMILY names
// (detail/NAME_kind.glsl), for detail/instantiate.glsl (an #include cannot take its file name from a macro).
// No include guard on purpose. The family files never include themselves: their once-only part includes
// instantiate.glsl, and this file includes only the detail/*_kind.glsl bodies, which include nothing.
#if !defined(TFI_FAMILY) || !defined(TFI_KIND)
#error "texfilter/detail/family.glsl is internal: include a family (e.g. texfilter/trilinear.glsl)"
#elif TFI_FAMILY == TFI_FAMILY_COMMON
#include "common_kind.glsl"
#elif TFI_FAMILY == TFI_FAMILY_LOD
#include "lod_kind.glsl"
#elif TFI_FAMILY == TFI_FAMILY_NEAREST
#include "nearest_kind.glsl"
#elif TFI_FAMILY == TFI_FAMILY_BILINEAR
#include "bilinear_kind.glsl"
#elif TFI_FAMILY == TFI_FAMILY_TRILINEAR
#include "trilinear_kind.glsl"
#elif TFI_FAMILY == TFI_FAMILY_BRILINEAR
#include "brilinear_kind.glsl"
#elif TFI_FAMILY == TFI_FAMILY_ANISO
#include "aniso_kind.glsl"
#elif TFI_FAMILY == TFI_FAMILY_EWA
#include "ewa_kind.glsl"
#elif TFI_FAMILY == TFI_FAMILY_EWA_FAST
#include "ewa_fast_kind.glsl"
#elif TFI_FAMILY == TFI_FAMILY_SAT
#include "sat_kind.glsl"
#elif TFI_FAMILY == TFI_FAMILY_CUBE
#include "cube_kind.glsl"
#elif TFI_FAMILY == TFI_FAMILY_LATLONG
#include "latlong_kind.glsl"
#elif TFI_FAMILY == TFI_FAMILY_BICUBIC
#include "bicubic_kind.glsl"
#elif TFI_FAMILY == TFI_FAMILY_STOCHASTIC
#include "stochastic_kind.glsl"
#else
#error "texfilter/detail/family.glsl: unknown TFI_FAMILY"
#endif
