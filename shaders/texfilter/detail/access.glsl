// texfilter/detail/access.glsl — internal: the texture-access layer: what a "texture" is for one resource kind, and how a
// family reads it. Internal: instantiate.glsl includes it once per kind (no include guard on purpose), and
// every family body reads textures only through the macros below, so each family's math is written once.
//
// Use:     nothing to call: pick the kinds with TF_RESOURCES (common.glsl) and call the families' tf_ overloads.
// Kinds (TFI_KIND; public parameters: the texture first, the extras right after uv / texel):
//   1 sampler2D tex                                manual + _hw
//   2 texture2D tex                                manual        (GL_EXT_samplerless_texture_functions)
//   3 texture2D tex, sampler smp                   _hw only      (sampler2D(tex, smp) at the point of use)
//   4 sampler2DArray tex           + int layer     manual + _hw
//   5 texture2DArray tex           + int layer     manual
//   6 texture2DArray tex, sampler smp + int layer  _hw only
//   7 usampler2D, 8 isampler2D, 9 utexture2D, 10 itexture2D: manual; integer texels converted to float
//   11 sampler2D tex + tf_Compare cmp, 12 texture2D tex + tf_Compare cmp: manual percentage-closer filtering,
//      each depth texel (.r) compared with cmp before it is filtered (tfi_compare_texel)
//   13 sampler2DShadow tex + float dref, 14 texture2D tex, samplerShadow smp + float dref: _hw only, the
//      hardware comparison per tap
//   Environment kinds (cube.glsl, latlong.glsl; docs/ENVIRONMENT.md): the 2D families run on one face / the
//   lat-long texture, with texels past the edges read through the map's own rule (TFI_FETCH) instead of a wrap:
//   15 samplerCube tex, 16 textureCube tex, sampler smp, 17 samplerCubeArray tex, 18 textureCubeArray tex,
//      sampler smp: manual (texels read at their centres through the sampler, which must be NEAREST) + _hw
//      (taps through the sampler, which must be LINEAR); extras `int face` (+ `int layer`, arrays)
//   19 sampler2D tex + tf_LatLong: a lat-long map (the texture is kind 1's; the extra only tells the overloads
//      apart): manual + _hw
//   20 TF_SOURCE tex: the user's texel source (docs/API.md "Texel sources"): tf_source_size, tf_source_levels and
//      tf_source_fetch, declared by the user before the includes, stand for textureSize, textureQueryLevels and
//      texelFetch; manual only
// Macros a body may use (parameter names are fixed: tex, smp, layer, cmp, dref):
//   TFI_T, TFI_A      the texture parameters in a declaration / a call (`sampler2D tex` / `tex`)
//   TFI_X, TFI_XA     the extras, with their leading comma (`, int layer` / `, layer`; empty for 2D)
//   TFI_FETCH(p, l)   texel p (ivec2, in range) of level l as vec4 (decoded, converted or compared)
//   TFI_SIZE0         level 0's size (ivec2), TFI_LEVELS the level count, TFI_LEVEL_SIZE(l) level l's size
//   TFI_LOOKUP(uv, l) a hardware lookup at explicit LOD l (vec4); kinds without a sampler: a stand-in vec4(0)
//                     that no entry point of theirs reaches (their `hardware` flag is always false)
//   TFI_MANUAL, TFI_HW   1 where the kind gets the manual / the _hw entry points
//   TFI_CAN_FETCH        0 for the shadow-sampler kinds (no texelFetch on a sampler2DShadow)
//   TFI_WRAP(i, size, mode), TFI_WRAP_PAIR(i, size, mode): tf_wrap / tfi_wrap_pair; the environment kinds
//                        pass the integer texel coordinate through (TFI_FETCH reads past the edges itself)
//   TFI_ENV, TFI_CUBE, TFI_LATLONG  1 for the environment kinds (15..19), the cube kinds, the lat-long kind
//   TFI_OWNS_T           0 where an earlier kind already defined the functions that take only TFI_T (11, 12
//                        share sampler2D / texture2D with 1, 2: size and level queries are the same)
//   TFI_SAT_T, TFI_SAT_A, TFI_SAT_X, TFI_SAT_XA, TFI_SAT_LOW(p), TFI_SAT_HIGH(p), TFI_SAT_SIZE: the SAT's two
//                        unsigned tables (kinds 1, 2, 4, 5 only; TFI_SAT 1 there)
// Every texture and sampled-image operand is wrapped in TF_NONUNIFORM(...) (bindless: common.glsl).
// Cost:    none by itself. Example: see common.glsl.

#if !defined(TFI_KIND) || !defined(TF_RESOURCES)
#error "texfilter/detail/access.glsl is internal: include a family (e.g. texfilter/trilinear.glsl)"
#endif

// The previous kind's macros (none before the first kind; #undef of an undefined name is legal, but Slang warns).
#ifdef TFI_T
#undef TFI_T
#undef TFI_SLANG_TEXTURE
#undef TFI_TEXEL_FETCH
#undef TFI_TEXTURE_SIZE
#undef TFI_TEXTURE_LEVELS
#undef TFI_A
#undef TFI_X
#undef TFI_XA
#undef TFI_FETCH
#undef TFI_SIZE0
#undef TFI_LEVELS
#undef TFI_LEVEL_SIZE
#undef TFI_LOOKUP
#undef TFI_MANUAL
#undef TFI_HW
#undef TFI_CAN_FETCH
#undef TFI_OWNS_T
#undef TFI_SAT
#undef TFI_WRAP
#undef TFI_WRAP_PAIR
#undef TFI_ENV
#undef TFI_CUBE
#undef TFI_LATLONG
#endif
#ifdef TFI_SAT_T
#undef TFI_SAT_T
#undef TFI_SAT_A
#undef TFI_SAT_X
#undef TFI_SAT_XA
#undef TFI_SAT_LOW
#undef TFI_SAT_HIGH
#undef TFI_SAT_SIZE
#endif

// Slang's GLSL mode has no samplerless texelFetch / textureSize / textureQueryLevels and no sampler2D(tex, smp):
// there the separate-texture kinds (texture2D = Texture2D, sampler = SamplerState: common.glsl) read through
// common.glsl's tfi_slang_* wrappers of the texture's own methods.
#if defined(__SLANG__) && (TFI_KIND == 2 || TFI_KIND == 3 || TFI_KIND == 5 || TFI_KIND == 6)
#define TFI_SLANG_TEXTURE 1
#define TFI_TEXEL_FETCH tfi_slang_fetch
#define TFI_TEXTURE_SIZE tfi_slang_size
#define TFI_TEXTURE_LEVELS tfi_slang_levels
#else
#define TFI_SLANG_TEXTURE 0
#define TFI_TEXEL_FETCH texelFetch
#define TFI_TEXTURE_SIZE textureSize
#define TFI_TEXTURE_LEVELS textureQueryLevels
#endif

#if TFI_KIND < 1 || TFI_KIND > 20
#error "texfilter/detail/access.glsl: unknown TFI_KIND"
#endif

// The texture parameters, and the kinds with a sampler beside the texture.
#if TFI_KIND == 1 || TFI_KIND == 11
#define TFI_T sampler2D tex
#elif TFI_KIND == 2 || TFI_KIND == 12
#define TFI_T texture2D tex
#elif TFI_KIND == 3
#define TFI_T texture2D tex, sampler smp
#elif TFI_KIND == 4
#define TFI_T sampler2DArray tex
#elif TFI_KIND == 5
#define TFI_T texture2DArray tex
#elif TFI_KIND == 6
#define TFI_T texture2DArray tex, sampler smp
#elif TFI_KIND == 7
#define TFI_T usampler2D tex
#elif TFI_KIND == 8
#define TFI_T isampler2D tex
#elif TFI_KIND == 9
#define TFI_T utexture2D tex
#elif TFI_KIND == 10
#define TFI_T itexture2D tex
#elif TFI_KIND == 13
#define TFI_T sampler2DShadow tex
#elif TFI_KIND == 14
#define TFI_T texture2D tex, samplerShadow smp
#elif TFI_KIND == 15
#define TFI_T samplerCube tex
#elif TFI_KIND == 16
#define TFI_T textureCube tex, sampler smp
#elif TFI_KIND == 17
#define TFI_T samplerCubeArray tex
#elif TFI_KIND == 18
#define TFI_T textureCubeArray tex, sampler smp
#elif TFI_KIND == 20
#define TFI_T TF_SOURCE tex
#else
#define TFI_T sampler2D tex
#endif
#define TFI_ENV (TFI_KIND >= 15 && TFI_KIND <= 19)
#define TFI_CUBE (TFI_KIND >= 15 && TFI_KIND <= 18)
#define TFI_LATLONG (TFI_KIND == 19)
#if TFI_KIND == 3 || TFI_KIND == 6 || TFI_KIND == 14 || TFI_KIND == 16 || TFI_KIND == 18
#define TFI_A tex, smp
#else
#define TFI_A tex
#endif

// The extras after uv: a layer (arrays), a comparison (manual shadow) or a reference depth (hardware shadow).
#if TFI_KIND >= 4 && TFI_KIND <= 6
#define TFI_X , int layer
#define TFI_XA , layer
#elif TFI_KIND == 11 || TFI_KIND == 12
#define TFI_X , tf_Compare cmp
#define TFI_XA , cmp
#elif TFI_KIND == 13 || TFI_KIND == 14
#define TFI_X , float dref
#define TFI_XA , dref
#elif TFI_KIND == 15 || TFI_KIND == 16
#define TFI_X , int face
#define TFI_XA , face
#elif TFI_KIND == 17 || TFI_KIND == 18
#define TFI_X , int face, int layer
#define TFI_XA , face, layer
#elif TFI_KIND == 19
#define TFI_X , tf_LatLong latlong
#define TFI_XA , latlong
#else
#define TFI_X
#define TFI_XA
#endif

#if TFI_KIND == 20
#define TFI_SIZE0 tf_source_size(tex, 0)
#define TFI_LEVELS tf_source_levels(tex)
#define TFI_LEVEL_SIZE(l) tf_source_size(tex, l)
#else
#define TFI_SIZE0 TFI_TEXTURE_SIZE(TF_NONUNIFORM(tex), 0).xy
#define TFI_LEVELS TFI_TEXTURE_LEVELS(TF_NONUNIFORM(tex))
// Derived from level 0 on purpose: textureSize() with a level that differs across a SIMD batch returned the
// wrong lane's size on lavapipe (Mesa 22.3).
#define TFI_LEVEL_SIZE(l) max(TFI_SIZE0 >> (l), ivec2(1))
#endif

// A texel. Arrays clamp the layer as Vulkan clamps a sampled array layer (to [0, layers − 1]): texelFetch
// of a layer outside the image is undefined. No texelFetch on a shadow sampler (13, 14): a stand-in that no
// entry point of theirs reaches.
#if TFI_KIND >= 4 && TFI_KIND <= 6
#define TFI_FETCH(p, l) \
    TFI_TEXEL_FETCH(TF_NONUNIFORM(tex), ivec3(p, clamp(layer, 0, TFI_TEXTURE_SIZE(TF_NONUNIFORM(tex), 0).z - 1)), l)
#elif TFI_KIND >= 7 && TFI_KIND <= 10
#define TFI_FETCH(p, l) vec4(texelFetch(TF_NONUNIFORM(tex), p, l))
#elif TFI_KIND == 11 || TFI_KIND == 12
#define TFI_FETCH(p, l) vec4(tfi_compare_texel(cmp, texelFetch(TF_NONUNIFORM(tex), p, l).r))
#elif TFI_KIND == 13 || TFI_KIND == 14
#define TFI_FETCH(p, l) vec4(0.0)
#elif TFI_CUBE
#define TFI_FETCH(p, l) tfi_cube_texel(TFI_A TFI_XA, p, l) // common.glsl: seamless, any p
#elif TFI_LATLONG
#define TFI_FETCH(p, l) tfi_latlong_texel(TFI_A, p, l) // common.glsl: across the seam and the poles, any p
#elif TFI_KIND == 20
#define TFI_FETCH(p, l) tf_source_fetch(tex, p, l)
#else
#define TFI_FETCH(p, l) TFI_TEXEL_FETCH(TF_NONUNIFORM(tex), p, l)
#endif
#define TFI_CAN_FETCH (TFI_KIND < 13 || TFI_KIND >= 15)

// How a family turns a texel coordinate into the one TFI_FETCH reads: wrapped by the sampler's mode, or, for
// the environment kinds, passed through (their TFI_FETCH reads past the texture's edges by the map's rule).
#if TFI_ENV
#define TFI_WRAP(i, size, mode) int(clamp((i), -TF_MAX_TEXEL_COORD, TF_MAX_TEXEL_COORD))
#define TFI_WRAP_PAIR(i, size, mode) (ivec2(TFI_WRAP(i, size, mode)) + ivec2(0, 1))
#else
#define TFI_WRAP(i, size, mode) tf_wrap(i, size, mode)
#define TFI_WRAP_PAIR(i, size, mode) tfi_wrap_pair(i, size, mode)
#endif

// A hardware lookup at an explicit LOD (the _hw forms); kinds without a sampler: a stand-in vec4(0) that no
// entry point of theirs reaches (their `hardware` flag is always false).
#if TFI_KIND == 1
#define TFI_LOOKUP(uv, l) textureLod(TF_NONUNIFORM(tex), uv, l)
#elif TFI_KIND == 3 && TFI_SLANG_TEXTURE
#define TFI_LOOKUP(uv, l) tfi_slang_lookup(TF_NONUNIFORM(tex), smp, uv, l)
#elif TFI_KIND == 3
#define TFI_LOOKUP(uv, l) textureLod(TF_NONUNIFORM(sampler2D(tex, smp)), uv, l)
#elif TFI_KIND == 4
#define TFI_LOOKUP(uv, l) textureLod(TF_NONUNIFORM(tex), vec3(uv, float(layer)), l)
#elif TFI_KIND == 6 && TFI_SLANG_TEXTURE
#define TFI_LOOKUP(uv, l) tfi_slang_lookup(TF_NONUNIFORM(tex), smp, vec3(uv, float(layer)), l)
#elif TFI_KIND == 6
#define TFI_LOOKUP(uv, l) textureLod(TF_NONUNIFORM(sampler2DArray(tex, smp)), vec3(uv, float(layer)), l)
#elif TFI_KIND == 13
#define TFI_LOOKUP(uv, l) vec4(textureLod(TF_NONUNIFORM(tex), vec3(uv, dref), l))
#elif TFI_KIND == 14
#define TFI_LOOKUP(uv, l) vec4(textureLod(TF_NONUNIFORM(sampler2DShadow(tex, smp)), vec3(uv, dref), l))
#elif TFI_KIND == 15
#define TFI_LOOKUP(uv, l) textureLod(TF_NONUNIFORM(tex), tfi_cube_direction(face, uv), l)
#elif TFI_KIND == 16
#define TFI_LOOKUP(uv, l) textureLod(TF_NONUNIFORM(samplerCube(tex, smp)), tfi_cube_direction(face, uv), l)
#elif TFI_KIND == 17
#define TFI_LOOKUP(uv, l) textureLod(TF_NONUNIFORM(tex), vec4(tfi_cube_direction(face, uv), float(layer)), l)
#elif TFI_KIND == 18
#define TFI_LOOKUP(uv, l) \
    textureLod(TF_NONUNIFORM(samplerCubeArray(tex, smp)), vec4(tfi_cube_direction(face, uv), float(layer)), l)
#elif TFI_KIND == 19
#define TFI_LOOKUP(uv, l) textureLod(TF_NONUNIFORM(tex), uv, l)
#else
#define TFI_LOOKUP(uv, l) vec4(0.0)
#endif

// Which entry points a kind gets: the manual forms where texelFetch reads the texture alone, the _hw forms
// where a sampler comes with it.
#define TFI_MANUAL (TFI_KIND != 3 && TFI_KIND != 6 && (TFI_KIND < 13 || TFI_KIND >= 15))
#define TFI_HW (TFI_KIND == 1 || TFI_KIND == 3 || TFI_KIND == 4 || TFI_KIND == 6 || (TFI_KIND >= 13 && TFI_KIND <= 19))

// 11 and 12 (and 19) share sampler2D / texture2D with 1 and 2: the functions that take only the texture (size and
// level queries) are defined once, by whichever of them is instantiated.
#if TFI_KIND == 11
#define TFI_OWNS_T ((TF_RESOURCES & TF_RESOURCE_SAMPLER_2D) == 0)
#elif TFI_KIND == 12
#define TFI_OWNS_T ((TF_RESOURCES & TF_RESOURCE_TEXTURE_2D) == 0)
#elif TFI_KIND == 19 // sampler2D: kind 1's, or kind 11's when only the shadow kinds are instantiated
#define TFI_OWNS_T ((TF_RESOURCES & (TF_RESOURCE_SAMPLER_2D | TF_RESOURCE_SHADOW)) == 0)
#else
#define TFI_OWNS_T 1
#endif

// The SAT's tables: unsigned integer images read with texelFetch only (kinds 1, 2, 4, 5).
#define TFI_SAT (TFI_KIND == 1 || TFI_KIND == 2 || TFI_KIND == 4 || TFI_KIND == 5)
#if TFI_SAT
#if TFI_KIND == 1
#define TFI_SAT_T usampler2D satLow, usampler2D satHigh
#elif TFI_KIND == 2
#define TFI_SAT_T utexture2D satLow, utexture2D satHigh
#elif TFI_KIND == 4
#define TFI_SAT_T usampler2DArray satLow, usampler2DArray satHigh
#else
#define TFI_SAT_T utexture2DArray satLow, utexture2DArray satHigh
#endif
#define TFI_SAT_A satLow, satHigh
#define TFI_SAT_SIZE TFI_TEXTURE_SIZE(TF_NONUNIFORM(satLow), 0).xy
#if TFI_KIND == 1 || TFI_KIND == 2
#define TFI_SAT_X
#define TFI_SAT_XA
#define TFI_SAT_LOW(p) TFI_TEXEL_FETCH(TF_NONUNIFORM(satLow), p, 0)
#define TFI_SAT_HIGH(p) TFI_TEXEL_FETCH(TF_NONUNIFORM(satHigh), p, 0)
#else
#define TFI_SAT_X , int layer
#define TFI_SAT_XA , layer
#define TFI_SAT_LOW(p) \
    TFI_TEXEL_FETCH(TF_NONUNIFORM(satLow), ivec3(p, clamp(layer, 0, TFI_TEXTURE_SIZE(TF_NONUNIFORM(satLow), 0).z - 1)), 0)
#define TFI_SAT_HIGH(p) \
    TFI_TEXEL_FETCH(TF_NONUNIFORM(satHigh), ivec3(p, clamp(layer, 0, TFI_TEXTURE_SIZE(TF_NONUNIFORM(satHigh), 0).z - 1)), 0)
#endif
#endif
