// texfilter/detail/instantiate.glsl — internal: instantiates the family named by TFI_FAMILY once per resource
// kind that TF_RESOURCES selects (common.glsl), and once more for the user's texel source when TF_SOURCE is
// defined: for each, access.glsl defines how that kind is read, then family.glsl includes the family's
// per-kind part (detail/NAME_kind.glsl), compiled with those macros. No include guard: included once by
// every family file.
//
// Use:     in a family file, after its once-only part:
//              #define TFI_FAMILY TFI_FAMILY_TRILINEAR
//              #include "detail/instantiate.glsl"
//              #undef TFI_FAMILY
// Cost:    compile time only (each kind's functions are compiled; compilers drop the ones never called).
#if !defined(TFI_FAMILY) || !defined(TF_RESOURCES)
#error "texfilter/detail/instantiate.glsl is internal: include a family (e.g. texfilter/trilinear.glsl)"
#endif

#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D) != 0
#define TFI_KIND 1
#include "access.glsl"
#include "family.glsl"
#undef TFI_KIND
#endif

#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D) != 0
#define TFI_KIND 2
#include "access.glsl"
#include "family.glsl"
#undef TFI_KIND
#endif

#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D) != 0
#define TFI_KIND 3
#include "access.glsl"
#include "family.glsl"
#undef TFI_KIND
#endif

#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D_ARRAY) != 0
#define TFI_KIND 4
#include "access.glsl"
#include "family.glsl"
#undef TFI_KIND
#endif

#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D_ARRAY) != 0
#define TFI_KIND 5
#include "access.glsl"
#include "family.glsl"
#undef TFI_KIND
#endif

#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D_ARRAY) != 0
#define TFI_KIND 6
#include "access.glsl"
#include "family.glsl"
#undef TFI_KIND
#endif

#if (TF_RESOURCES & TF_RESOURCE_INTEGER) != 0
#define TFI_KIND 7
#include "access.glsl"
#include "family.glsl"
#undef TFI_KIND
#endif

#if (TF_RESOURCES & TF_RESOURCE_INTEGER) != 0
#define TFI_KIND 8
#include "access.glsl"
#include "family.glsl"
#undef TFI_KIND
#endif

#if (TF_RESOURCES & TF_RESOURCE_INTEGER) != 0
#define TFI_KIND 9
#include "access.glsl"
#include "family.glsl"
#undef TFI_KIND
#endif

#if (TF_RESOURCES & TF_RESOURCE_INTEGER) != 0
#define TFI_KIND 10
#include "access.glsl"
#include "family.glsl"
#undef TFI_KIND
#endif

#if (TF_RESOURCES & TF_RESOURCE_SHADOW) != 0
#define TFI_KIND 11
#include "access.glsl"
#include "family.glsl"
#undef TFI_KIND
#endif

#if (TF_RESOURCES & TF_RESOURCE_SHADOW) != 0
#define TFI_KIND 12
#include "access.glsl"
#include "family.glsl"
#undef TFI_KIND
#endif

#if (TF_RESOURCES & TF_RESOURCE_SHADOW) != 0
#define TFI_KIND 13
#include "access.glsl"
#include "family.glsl"
#undef TFI_KIND
#endif

#if (TF_RESOURCES & TF_RESOURCE_SHADOW) != 0
#define TFI_KIND 14
#include "access.glsl"
#include "family.glsl"
#undef TFI_KIND
#endif

#if (TF_RESOURCES & TF_RESOURCE_CUBE) != 0
#define TFI_KIND 15
#include "access.glsl"
#include "family.glsl"
#undef TFI_KIND
#endif

#if (TF_RESOURCES & TF_RESOURCE_CUBE) != 0
#define TFI_KIND 16
#include "access.glsl"
#include "family.glsl"
#undef TFI_KIND
#endif

#if (TF_RESOURCES & TF_RESOURCE_CUBE_ARRAY) != 0
#define TFI_KIND 17
#include "access.glsl"
#include "family.glsl"
#undef TFI_KIND
#endif

#if (TF_RESOURCES & TF_RESOURCE_CUBE_ARRAY) != 0
#define TFI_KIND 18
#include "access.glsl"
#include "family.glsl"
#undef TFI_KIND
#endif

#if (TF_RESOURCES & TF_RESOURCE_LATLONG) != 0
#define TFI_KIND 19
#include "access.glsl"
#include "family.glsl"
#undef TFI_KIND
#endif

#ifdef TF_SOURCE
#define TFI_KIND 20
#include "access.glsl"
#include "family.glsl"
#undef TFI_KIND
#endif
