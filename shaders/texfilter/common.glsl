// texfilter/common.glsl — what every texfilter include shares: the sampler options (tf_Sampler), wrap modes,
// a wrapped texel fetch, the cost hooks, the resource kinds (TF_RESOURCES), the user's texel source
// (TF_SOURCE), the depth comparison (tf_Compare) and the bindless hook (TF_NONUNIFORM). Pulls in version.glsl.
//
// Use:     #include "texfilter/common.glsl"   (every other include pulls it in itself)
//          tf_Sampler tf_sampler(int wrap);    // wrap, lodBias 0, lodMin 0, lodMax 1000 (all levels)
//          tf_Sampler(int wrap, float lodBias, float lodMin, float lodMax) // the struct; needs lodMin <= lodMax
//          tf_Compare tf_compare(int op, float dref); // depth kinds: a texel D passes (1) when `dref op D`
//          vec4  tf_fetch(sampler2D tex, ivec2 texel, int level, int wrapMode); // wrapped texelFetch
//          ivec2 tf_level_size(sampler2D tex, int level);  // max(1, textureSize(tex, 0) >> level)
//          int   tf_wrap(float i, int size, int wrapMode); // integer-valued texel coordinate → [0, size)
//          bool  tf_finite(vec2 v);                         // neither NaN nor ±Inf
//          vec2  tf_reduce_uv(vec2 uv, int wrapMode);       // uv by whole periods into [-1, 1] (clamp: [-1, 2])
//          tf_fetch and tf_level_size have an overload for every resource kind and a TF_SOURCE texel source
//          (the prototype list below), e.g. tf_fetch(sampler2DArray tex, ivec2 texel, int layer, int level,
//          int wrapMode), tf_fetch(sampler2D depth, ivec2 texel, tf_Compare cmp, int level, int wrapMode) (0/1).
// Constants: TF_WRAP_REPEAT, TF_WRAP_CLAMP (clamp to edge), TF_WRAP_MIRROR (mirrored repeat; any other value
//          acts as repeat). TF_MAX_TEXEL_COORD = 2^24. TF_TAPS_MANUAL, TF_TAPS_HARDWARE: names for a run-time
//          choice of tf_X or tf_X_hw. TF_COMPARE_NEVER 0, _LESS 1, _EQUAL 2, _LESS_OR_EQUAL 3, _GREATER 4,
//          _NOT_EQUAL 5, _GREATER_OR_EQUAL 6, _ALWAYS 7: VkCompareOp's values.
// Options: define before the first include:
//          TF_COUNT_FETCHES(n)     invoked with each number of texelFetch reads (default: nothing);
//          TF_COUNT_HW_LOOKUPS(n)  invoked with each number of hardware filtered lookups (default: nothing);
//          TF_NONUNIFORM           bindless: `#define TF_NONUNIFORM nonuniformEXT` (and enable
//                                  GL_EXT_nonuniform_qualifier) when the texture is indexed divergently,
//                                  e.g. tf_trilinear(texs[nonuniformEXT(i)], ...); default: nothing. Under
//                                  Slang leave it undefined (its nonuniformEXT takes the index, and slangc
//                                  then marks the loads itself).
//          TF_MAGNIFY              how trilinear, aniso and ewa reconstruct level 0 (bicubic.glsl):
//                                  TF_RECONSTRUCT_BILINEAR (default), _BSPLINE or _CATMULL_ROM; an int
//                                  expression (e.g. a specialization constant) chooses at run time.
//          TF_RESOURCES            the resource kinds to instantiate, a mask (default: all; under Slang the
//                                  kinds it compiles): TF_RESOURCE_SAMPLER_2D 1, TF_RESOURCE_TEXTURE_2D 2
//                                  (texture2D; + sampler for _hw), TF_RESOURCE_SAMPLER_2D_ARRAY 4,
//                                  TF_RESOURCE_TEXTURE_2D_ARRAY 8, TF_RESOURCE_INTEGER 16 (u/isampler2D,
//                                  u/itexture2D), TF_RESOURCE_SHADOW 32 (depth maps; sampler2DShadow for _hw),
//                                  TF_RESOURCE_CUBE 64, TF_RESOURCE_CUBE_ARRAY 128 (cube.glsl),
//                                  TF_RESOURCE_LATLONG 256 (latlong.glsl). A kind left out: "no matching function".
//          TF_SOURCE               your own texel source (an atlas tile, a virtual texture, ...): `#define
//                                  TF_SOURCE T` (any type) and declare, before the include,
//                                      ivec2 tf_source_size(T src, int level);  // the level's size in texels
//                                      int   tf_source_levels(T src);           // its MIP level count
//                                      vec4  tf_source_fetch(T src, ivec2 texel, int level);
//                                  (texel already wrapped into [0, size) by the wrap mode). Every manual 2D
//                                  family then takes `T src` where it takes a sampler2D; no _hw, SAT or
//                                  environment forms. TF_RESOURCES 0 leaves only T's. docs/API.md "Texel sources".
// Needs:   nothing bound: every function takes the texture. Texel space (DESIGN.md §3): u = s·w_l,
//          w_l = max(1, w >> l); wraps act on integer texel coordinates before texelFetch, so the sampler's own
//          filter and address modes are unused and any sampler2D works. The includes enable
//          GL_EXT_samplerless_texture_functions where a kind needs it.
// Cost:    tf_fetch: 1 texel fetch; the others none.
// Degenerate input: texel coordinates are clamped to ±TF_MAX_TEXEL_COORD before wrapping (pass finite ones);
//          tf_fetch's level must be in [0, levels − 1]; a NaN depth or dref passes only _ALWAYS and _NOT_EQUAL;
//          tf_reduce_uv's result means nothing for a non-finite uv (the filters return vec4(0) for one first).
// Example: tf_Sampler s = tf_sampler(TF_WRAP_REPEAT);
//          vec4 c = tf_fetch(tex, ivec2(-1, 3), 0, s.wrap); // texel (w-1, 3) of level 0
#ifndef TF_COMMON_GLSL
#define TF_COMMON_GLSL

#include "version.glsl"

// Resource kinds (access.glsl). The separate-texture, integer and shadow kinds read textures without a sampler.
#define TF_RESOURCE_SAMPLER_2D 1
#define TF_RESOURCE_TEXTURE_2D 2
#define TF_RESOURCE_SAMPLER_2D_ARRAY 4
#define TF_RESOURCE_TEXTURE_2D_ARRAY 8
#define TF_RESOURCE_INTEGER 16
#define TF_RESOURCE_SHADOW 32
#define TF_RESOURCE_CUBE 64
#define TF_RESOURCE_CUBE_ARRAY 128
#define TF_RESOURCE_LATLONG 256
#ifndef TF_RESOURCES
#ifdef __SLANG__
// Under Slang (slangc -allow-glsl; docs/API.md "Slang"): sampler2D (its Sampler2D), sampler2DArray, lat-long maps,
// and Texture2D / Texture2DArray (+ SamplerState for _hw), the GLSL names below standing for them. Its GLSL
// mode has none of the integer, shadow or cube texture types the other kinds take.
#define TF_RESOURCES (TF_RESOURCE_SAMPLER_2D | TF_RESOURCE_TEXTURE_2D | TF_RESOURCE_SAMPLER_2D_ARRAY | \
                      TF_RESOURCE_TEXTURE_2D_ARRAY | TF_RESOURCE_LATLONG)
#else
#define TF_RESOURCES 511
#endif
#endif
#if (TF_RESOURCES & (2 | 4 | 8 | 16 | 32 | 64 | 128)) != 0
#extension GL_EXT_samplerless_texture_functions : require
#endif
#ifdef __SLANG__
// Slang's GLSL mode lacks the separate texture and sampler types and their samplerless functions: the GLSL names
// stand for Slang's types, and access.glsl reads them through these (TFI_SLANG_TEXTURE).
#define texture2D Texture2D
#define texture2DArray Texture2DArray
#define sampler SamplerState
#define utexture2D Texture2D<uint4>
#define utexture2DArray Texture2DArray<uint4>
// Generic over the texel type: float4 images and the SAT's uint4 tables.
T tfi_slang_fetch<T : ITexelElement>(Texture2D<T> t, ivec2 p, int level) { return t.Load(ivec3(p, level)); }
T tfi_slang_fetch<T : ITexelElement>(Texture2DArray<T> t, ivec3 p, int level) { return t.Load(ivec4(p, level)); }
ivec4 tfi_slang_dimensions<T : ITexelElement>(Texture2D<T> t, int level) // (w, h, layers, levels)
{
    uint w, h, levels;
    t.GetDimensions(uint(level), w, h, levels);
    return ivec4(int(w), int(h), 1, int(levels));
}
ivec4 tfi_slang_dimensions<T : ITexelElement>(Texture2DArray<T> t, int level)
{
    uint w, h, layers, levels;
    t.GetDimensions(uint(level), w, h, layers, levels);
    return ivec4(int(w), int(h), int(layers), int(levels));
}
#define tfi_slang_size(t, level) tfi_slang_dimensions(t, level).xyz
#define tfi_slang_levels(t) tfi_slang_dimensions(t, 0).w
vec4 tfi_slang_lookup(Texture2D t, SamplerState s, vec2 uv, float lod) { return t.SampleLevel(s, uv, lod); }
vec4 tfi_slang_lookup(Texture2DArray t, SamplerState s, vec3 uvLayer, float lod) { return t.SampleLevel(s, uvLayer, lod); }
#endif
// TFI_UNROLL before a loop of constant trip count whose body indexes local arrays by the loop counter: unrolled,
// the indices are constants and the arrays registers; left rolled, a SIMD implementation (lavapipe) indexes
// them through memory, one lane at a time (the SAT's corner loops: a third of its time). A hint, no capability.
#extension GL_EXT_control_flow_attributes : enable
#define TFI_UNROLL [[unroll]]

// Bindless: the qualifier every texture and sampled-image operand inside the includes is wrapped in.
#ifndef TF_NONUNIFORM
#define TF_NONUNIFORM
#endif

// The families instantiate.glsl knows (family.glsl maps them to files).
#define TFI_FAMILY_COMMON 1
#define TFI_FAMILY_LOD 2
#define TFI_FAMILY_NEAREST 3
#define TFI_FAMILY_BILINEAR 4
#define TFI_FAMILY_TRILINEAR 5
#define TFI_FAMILY_BRILINEAR 6
#define TFI_FAMILY_ANISO 7
#define TFI_FAMILY_EWA 8
#define TFI_FAMILY_SAT 9
#define TFI_FAMILY_CUBE 10
#define TFI_FAMILY_LATLONG 11
#define TFI_FAMILY_BICUBIC 12
#define TFI_FAMILY_STOCHASTIC 13
#define TFI_FAMILY_EWA_FAST 14

// Cost hooks: define these before the first include to count work (the harness's `sample --stats`
// does); by default they vanish. n texels read with texelFetch / n hardware filtered lookups.
#ifndef TF_COUNT_FETCHES
#define TF_COUNT_FETCHES(n)
#endif
#ifndef TF_COUNT_HW_LOOKUPS
#define TF_COUNT_HW_LOOKUPS(n)
#endif

// Multi-tap filters (aniso, ewa): taps from texelFetch, or hardware bilinear/trilinear lookups through
// the sampler bound with the texture (which must then filter linearly with the same wrap mode).
#define TF_TAPS_MANUAL 0
#define TF_TAPS_HARDWARE 1

// Reconstruction of one level from its texels (bicubic.glsl): bilinear (Vulkan LINEAR), the cubic B-spline
// (smooth, positive weights, blurs a little) or Catmull-Rom (interpolating, sharper, rings a little).
#define TF_RECONSTRUCT_BILINEAR 0
#define TF_RECONSTRUCT_BSPLINE 1
#define TF_RECONSTRUCT_CATMULL_ROM 2
// How trilinear, aniso and ewa reconstruct level 0, where they magnify: TF_RECONSTRUCT_* (bicubic.glsl).
// A constant by default, so the cubic code is compiled away; any int expression the shader can read at
// the includes' point of use (a specialization constant, a uniform) selects it at run time.
#ifndef TF_MAGNIFY
#define TF_MAGNIFY TF_RECONSTRUCT_BILINEAR
#endif

#define TF_WRAP_REPEAT 0
#define TF_WRAP_CLAMP 1  // clamp to edge
#define TF_WRAP_MIRROR 2 // mirrored repeat

// Everything that selects how a lookup is filtered, apart from the filter itself.
struct tf_Sampler {
    int wrap;      // TF_WRAP_*
    float lodBias; // added to log2(rho)
    float lodMin;  // the biased LOD is clamped to [lodMin, lodMax], then to [0, levels-1]
    float lodMax;
};

tf_Sampler tf_sampler(int wrap) { return tf_Sampler(wrap, 0.0, 0.0, 1000.0); }

// The shadow kinds' depth comparison, VkCompareOp's values: a depth texel D passes when `dref op D`
// (Vulkan: reference op test). Vulkan clamps Dref to [0, 1] for UNORM depth formats; tf_compare does not
// (pass clamp(dref, 0.0, 1.0) for those).
#define TF_COMPARE_NEVER 0
#define TF_COMPARE_LESS 1
#define TF_COMPARE_EQUAL 2
#define TF_COMPARE_LESS_OR_EQUAL 3
#define TF_COMPARE_GREATER 4
#define TF_COMPARE_NOT_EQUAL 5
#define TF_COMPARE_GREATER_OR_EQUAL 6
#define TF_COMPARE_ALWAYS 7

struct tf_Compare {
    int op;     // TF_COMPARE_*
    float dref; // the reference depth
};

tf_Compare tf_compare(int op, float dref) { return tf_Compare(op, dref); }

// 1.0 where the texel passes, else 0.0. Bits of op: LESS 1, EQUAL 2, GREATER 4 (VkCompareOp is built so).
float tfi_compare_texel(tf_Compare c, float d)
{
    int bit = c.dref < d ? 1 : c.dref > d ? 4 : c.dref == d ? 2 : 0; // 0: unordered (a NaN)
    // Unordered: only ALWAYS and NOT_EQUAL pass (IEEE's !=), every ordered comparison fails.
    return (c.op & bit) != 0 || c.op == TF_COMPARE_ALWAYS || (bit == 0 && c.op == TF_COMPARE_NOT_EQUAL) ? 1.0 : 0.0;
}

// One return where a branch tests an argument callers often pass as a constant (wrap mode, kernel, TF_MAGNIFY,
// the tap form): glslc -O (shaderc 2023.2, SPIRV-Tools before 2023.1) crashes in block merging once a constant
// folds an early return's branch away. Early returns on run-time conditions (non-finite input) are fine.
// tests/compile_matrix.py compiles every function that way.

// Texel coordinates past ±2^24 carry no information in float; clamping there keeps int math defined.
const float TF_MAX_TEXEL_COORD = 16777216.0;

// Wraps an integer-valued float texel coordinate into [0, size). In float, without integer division: a
// SIMD implementation (lavapipe) has no vector integer divide and ran % one lane at a time, which made
// manual trilinear twice the hardware's time. t - n·floor(t/n) is exact for |t| < 2^24 - n (integers,
// products below 2^24); a quotient one off from rounding is put right by the single step after it.
int tf_wrap(float i, int size, int wrapMode)
{
    float t = clamp(i, -TF_MAX_TEXEL_COORD, TF_MAX_TEXEL_COORD);
    int wrapped;
    if (wrapMode == TF_WRAP_CLAMP) { // one return (above)
        wrapped = clamp(int(t), 0, size - 1);
    } else {
        float n = float(size);
        float period = wrapMode == TF_WRAP_MIRROR ? 2.0 * n : n;
        float m = t - period * floor(t / period);
        m = m < 0.0 ? m + period : (m >= period ? m - period : m);
        if (wrapMode == TF_WRAP_MIRROR && m >= n)
            m = period - 1.0 - m;
        wrapped = int(m);
    }
    return wrapped;
}

// The texel pair (i, i + 1) of a bilinear lookup, wrapped, for an integer-valued i in [-size - 1, size - 1]
// (repeat and mirrored repeat) or any i (clamp to edge): the range a uv reduced by tf_reduce_uv gives. So
// a period is added at most twice instead of a division, a floor and a product (tf_wrap), which cost
// lavapipe ~3 % of a trilinear frame; the same texels as tf_wrap on each of i and i + 1.
ivec2 tfi_wrap_pair(float i, int size, int wrapMode)
{
    ivec2 t = ivec2(int(clamp(i, -TF_MAX_TEXEL_COORD, TF_MAX_TEXEL_COORD))) + ivec2(0, 1);
    ivec2 clamped = clamp(t, 0, size - 1);
    ivec2 m = mix(t, -1 - t, lessThan(t, ivec2(0)));                            // in [0, size]
    ivec2 mirrored = mix(m, 2 * size - 1 - m, greaterThanEqual(m, ivec2(size))); // size -> size - 1
    int first = t.x + (t.x < 0 ? size : 0);
    first += first < 0 ? size : 0;
    ivec2 repeated = ivec2(first, first + 1 == size ? 0 : first + 1);
    // Selects, not early returns: lavapipe runs every side of an if under a mask anyway, and the masks cost.
    return wrapMode == TF_WRAP_CLAMP ? clamped : (wrapMode == TF_WRAP_MIRROR ? mirrored : repeated);
}

bool tf_finite(vec2 v) { return !any(isnan(v)) && !any(isinf(v)); }

// The same texels from a uv near [0, 1]: repeat and mirrored repeat move uv by whole periods of 2 (both
// repeat every 2 in uv; 2 keeps the parity of texel indices for odd sizes) into [-1, 1], clamp clamps it
// to [-1, 2] (past an edge by a whole texture every texel reads the edge). Exact in float (the result is
// no larger than uv and a multiple of its spacing), and uv in [-1, 1] is unchanged. Every filter does this
// first, so that no finite uv makes a texel coordinate (uv·size) overflow float and the manual and
// hardware-tap forms see the same coordinates (docs/API.md, degenerate input).
vec2 tfi_whole_periods(vec2 uv) { return uv - 2.0 * roundEven(0.5 * uv); } // repeat and mirror's part
vec2 tf_reduce_uv(vec2 uv, int wrapMode)
{
    return wrapMode == TF_WRAP_CLAMP ? clamp(uv, -1.0, 2.0) : tfi_whole_periods(uv);
}

// Marks a sampler2D as a lat-long map for the 2D families (latlong.glsl): tf_ewa(tex, uv, tf_LatLong(0), ...)
// filters it in uv, its texels read across the seam and the poles. The member means nothing.
struct tf_LatLong {
    int unused;
};

// A cube face's frame (docs/ENVIRONMENT.md's table, Vulkan "Cube Map Face Selection"): sc = dot(S, d),
// tc = dot(T, d), |ma| = dot(M, d) on face `face` (+X, -X, +Y, -Y, +Z, -Z).
void tfi_cube_frame(int face, out vec3 S, out vec3 T, out vec3 M)
{
    int axis = face >> 1;
    float sgn = (face & 1) == 0 ? 1.0 : -1.0;
    M = vec3(axis == 0 ? sgn : 0.0, axis == 1 ? sgn : 0.0, axis == 2 ? sgn : 0.0);
    S = axis == 0 ? vec3(0.0, 0.0, -sgn) : axis == 1 ? vec3(1.0, 0.0, 0.0) : vec3(sgn, 0.0, 0.0);
    T = axis == 1 ? vec3(0.0, 0.0, sgn) : vec3(0.0, -1.0, 0.0);
}

// The direction through face coordinates st of `face` (|ma| = 1; st outside [0, 1] extends the face's plane).
vec3 tfi_cube_direction(int face, vec2 st)
{
    vec3 S, T, M;
    tfi_cube_frame(face, S, T, M);
    vec2 c = 2.0 * st - 1.0;
    return M + c.x * S + c.y * T;
}

// BEGIN prototypes (generated: tests/prototypes.py --write; ctest prototypes.current checks it)
// Every overload below is defined by this file's detail/*_kind.glsl for the kinds its #if names.
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D) != 0
vec4 tf_fetch(sampler2D tex, ivec2 texel, int level, int wrapMode);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D) != 0
ivec2 tf_level_size(texture2D tex, sampler smp, int level);
vec4 tf_fetch(texture2D tex, ivec2 texel, int level, int wrapMode);
vec4 tf_fetch(texture2D tex, sampler smp, ivec2 texel, int level, int wrapMode);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D_ARRAY) != 0
ivec2 tf_level_size(sampler2DArray tex, int level);
vec4 tf_fetch(sampler2DArray tex, ivec2 texel, int layer, int level, int wrapMode);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D_ARRAY) != 0
ivec2 tf_level_size(texture2DArray tex, int level);
ivec2 tf_level_size(texture2DArray tex, sampler smp, int level);
vec4 tf_fetch(texture2DArray tex, ivec2 texel, int layer, int level, int wrapMode);
vec4 tf_fetch(texture2DArray tex, sampler smp, ivec2 texel, int layer, int level, int wrapMode);
#endif
#if (TF_RESOURCES & TF_RESOURCE_INTEGER) != 0
ivec2 tf_level_size(isampler2D tex, int level);
ivec2 tf_level_size(itexture2D tex, int level);
ivec2 tf_level_size(usampler2D tex, int level);
ivec2 tf_level_size(utexture2D tex, int level);
vec4 tf_fetch(isampler2D tex, ivec2 texel, int level, int wrapMode);
vec4 tf_fetch(itexture2D tex, ivec2 texel, int level, int wrapMode);
vec4 tf_fetch(usampler2D tex, ivec2 texel, int level, int wrapMode);
vec4 tf_fetch(utexture2D tex, ivec2 texel, int level, int wrapMode);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SHADOW) != 0
ivec2 tf_level_size(sampler2DShadow tex, int level);
ivec2 tf_level_size(texture2D tex, samplerShadow smp, int level);
vec4 tf_fetch(sampler2D tex, ivec2 texel, tf_Compare cmp, int level, int wrapMode);
vec4 tf_fetch(texture2D tex, ivec2 texel, tf_Compare cmp, int level, int wrapMode);
#endif
#if (TF_RESOURCES & (TF_RESOURCE_TEXTURE_2D | TF_RESOURCE_SHADOW)) != 0
ivec2 tf_level_size(texture2D tex, int level);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE) != 0
ivec2 tf_level_size(samplerCube tex, int level);
ivec2 tf_level_size(textureCube tex, sampler smp, int level);
vec4 tf_fetch(samplerCube tex, ivec2 texel, int face, int level, int wrapMode);
vec4 tf_fetch(textureCube tex, sampler smp, ivec2 texel, int face, int level, int wrapMode);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE_ARRAY) != 0
ivec2 tf_level_size(samplerCubeArray tex, int level);
ivec2 tf_level_size(textureCubeArray tex, sampler smp, int level);
vec4 tf_fetch(samplerCubeArray tex, ivec2 texel, int face, int layer, int level, int wrapMode);
vec4 tf_fetch(textureCubeArray tex, sampler smp, ivec2 texel, int face, int layer, int level, int wrapMode);
#endif
#if (TF_RESOURCES & TF_RESOURCE_LATLONG) != 0
vec4 tf_fetch(sampler2D tex, ivec2 texel, tf_LatLong latlong, int level, int wrapMode);
#endif
#if (TF_RESOURCES & (TF_RESOURCE_SAMPLER_2D | TF_RESOURCE_SHADOW | TF_RESOURCE_LATLONG)) != 0
ivec2 tf_level_size(sampler2D tex, int level);
#endif
#ifdef TF_SOURCE
ivec2 tf_level_size(TF_SOURCE tex, int level);
vec4 tf_fetch(TF_SOURCE tex, ivec2 texel, int level, int wrapMode);
#endif
// END prototypes

#define TFI_FAMILY TFI_FAMILY_COMMON
#include "detail/instantiate.glsl"
#undef TFI_FAMILY

#endif
