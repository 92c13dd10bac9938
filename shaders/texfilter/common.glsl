// texfilter/common.glsl — shared pieces of every texfilter include: the sampler options (tf_Sampler),
// wrap modes, a wrapped texel fetch, the cost hooks, the resource kinds (TF_RESOURCES), the depth comparison
// of the shadow kinds (tf_Compare) and the bindless hook (TF_NONUNIFORM). Pulls in version.glsl.
//
// Use:     #include "texfilter/common.glsl"   (every other include pulls it in itself)
//          tf_Sampler tf_sampler(int wrap);    // wrap, lodBias 0, lodMin 0, lodMax 1000 (all levels)
//          tf_Sampler(int wrap, float lodBias, float lodMin, float lodMax) // the struct; needs lodMin <= lodMax
//          tf_Compare tf_compare(int op, float dref); // shadow kinds: a texel passes (1) when `dref op D`
//          vec4  tf_fetch(sampler2D tex, ivec2 texel, int level, int wrapMode); // wrapped texelFetch
//          int   tf_wrap(float i, int size, int wrapMode); // integer-valued texel coordinate → [0, size)
//          ivec2 tf_level_size(sampler2D tex, int level);  // max(1, textureSize(tex, 0) >> level)
//          bool  tf_finite(vec2 v);                         // neither NaN nor ±Inf
//          vec2  tf_reduce_uv(vec2 uv, int wrapMode);       // uv by whole periods into [-1, 1] (clamp: [-1, 2])
//          tf_fetch and tf_level_size exist for every resource kind (access.glsl): e.g.
//          tf_fetch(sampler2DArray tex, ivec2 texel, int layer, int level, int wrapMode),
//          tf_fetch(sampler2D depth, ivec2 texel, tf_Compare cmp, int level, int wrapMode) (0 or 1),
//          tf_level_size(texture2D tex, int level).
// Constants: TF_WRAP_REPEAT, TF_WRAP_CLAMP (clamp to edge), TF_WRAP_MIRROR (mirrored repeat; any other
//          value acts as repeat). TF_MAX_TEXEL_COORD = 2^24: texel coordinates are clamped to ± that.
//          TF_TAPS_MANUAL, TF_TAPS_HARDWARE: names for a caller's run-time choice of tf_X or tf_X_hw.
//          TF_COMPARE_NEVER 0, _LESS 1, _EQUAL 2, _LESS_OR_EQUAL 3, _GREATER 4, _NOT_EQUAL 5, _GREATER_OR_EQUAL 6,
//          _ALWAYS 7: VkCompareOp's values.
// Options: define before the first include:
//          TF_COUNT_FETCHES(n)     invoked with each number of texelFetch reads (default: nothing);
//          TF_COUNT_HW_LOOKUPS(n)  invoked with each number of hardware filtered lookups (default: nothing);
//          TF_NONUNIFORM           bindless: `#define TF_NONUNIFORM nonuniformEXT` (and enable
//                                  GL_EXT_nonuniform_qualifier) when the texture you pass is indexed
//                                  divergently, e.g. tf_trilinear(texs[nonuniformEXT(i)], ...): every image
//                                  instruction inside the includes then takes a NonUniform operand. Default: none.
//          TF_RESOURCES            the resource kinds to instantiate (compile time; default: all), a mask of
//                                  TF_RESOURCE_SAMPLER_2D 1 (sampler2D), TF_RESOURCE_TEXTURE_2D 2 (texture2D, and
//                                  texture2D + sampler for _hw), TF_RESOURCE_SAMPLER_2D_ARRAY 4, TF_RESOURCE_
//                                  TEXTURE_2D_ARRAY 8, TF_RESOURCE_INTEGER 16 (u/isampler2D, u/itexture2D),
//                                  TF_RESOURCE_SHADOW 32 (percentage-closer filtering; sampler2DShadow for _hw).
//                                  A family called with a kind left out fails to compile ("no matching function").
// Needs:   nothing bound: every function takes the texture. Texel space (DESIGN.md §3): u = s·w_l with
//          w_l = max(1, w >> l); wraps act on integer texel coordinates before texelFetch, so the sampler's
//          own filter and address modes are not used and any sampler2D works (e.g. RGBA32F). The includes
//          enable GL_EXT_samplerless_texture_functions (texelFetch on texture2D) where a kind needs it.
// Cost:    tf_fetch: 1 texel fetch; the others none.
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
#ifndef TF_RESOURCES
#define TF_RESOURCES 63
#endif
#if (TF_RESOURCES & 62) != 0
#extension GL_EXT_samplerless_texture_functions : require
#endif

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

// Texel coordinates past ±2^24 carry no information in float; clamping there keeps int math defined.
const float TF_MAX_TEXEL_COORD = 16777216.0;

// Wraps an integer-valued float texel coordinate into [0, size). In float, without integer division: a
// SIMD implementation (lavapipe) has no vector integer divide and ran % one lane at a time, which made
// manual trilinear twice the hardware's time. t - n·floor(t/n) is exact for |t| < 2^24 - n (integers,
// products below 2^24); a quotient one off from rounding is put right by the single step after it.
int tf_wrap(float i, int size, int wrapMode)
{
    float t = clamp(i, -TF_MAX_TEXEL_COORD, TF_MAX_TEXEL_COORD);
    if (wrapMode == TF_WRAP_CLAMP)
        return clamp(int(t), 0, size - 1);
    float n = float(size);
    float period = wrapMode == TF_WRAP_MIRROR ? 2.0 * n : n;
    float m = t - period * floor(t / period);
    m = m < 0.0 ? m + period : (m >= period ? m - period : m);
    if (wrapMode == TF_WRAP_MIRROR && m >= n)
        m = period - 1.0 - m;
    return int(m);
}

// The texel pair (i, i + 1) of a linear lookup, wrapped: repeat wraps once and steps (one division, not two).
ivec2 tfi_wrap_pair(float i, int size, int wrapMode)
{
    int first = tf_wrap(i, size, wrapMode);
    if (wrapMode == TF_WRAP_REPEAT)
        return ivec2(first, first + 1 == size ? 0 : first + 1);
    return ivec2(first, tf_wrap(i + 1.0, size, wrapMode));
}

bool tf_finite(vec2 v) { return !any(isnan(v)) && !any(isinf(v)); }

// The same texels from a uv near [0, 1]: repeat and mirrored repeat move uv by whole periods of 2 (both
// repeat every 2 in uv; 2 keeps the parity of texel indices for odd sizes) into [-1, 1], clamp clamps it
// to [-1, 2] (past an edge by a whole texture every texel reads the edge). Exact in float (the result is
// no larger than uv and a multiple of its spacing), and uv in [-1, 1] is unchanged. Every filter does this
// first, so that no finite uv makes a texel coordinate (uv·size) overflow float and the manual and
// hardware-tap forms see the same coordinates (docs/API.md, degenerate input).
vec2 tf_reduce_uv(vec2 uv, int wrapMode)
{
    if (wrapMode == TF_WRAP_CLAMP)
        return clamp(uv, -1.0, 2.0);
    return uv - 2.0 * roundEven(0.5 * uv);
}

#define TFI_FAMILY TFI_FAMILY_COMMON
#include "instantiate.glsl"
#undef TFI_FAMILY

#elif defined(TFI_FAMILY)
#if TFI_FAMILY == TFI_FAMILY_COMMON // per resource kind (access.glsl)

#if TFI_OWNS_T
// Size of a MIP level by the Vulkan floor rule. Derived from level 0 on purpose: textureSize() with a
// level that differs across a SIMD batch returned the wrong lane's size on lavapipe (Mesa 22.3).
ivec2 tf_level_size(TFI_T, int level) { return max(TFI_SIZE0 >> level, ivec2(1)); }
#endif

#if TFI_CAN_FETCH
vec4 tf_fetch(TFI_T, ivec2 texel TFI_X, int level, int wrapMode)
{
    ivec2 size = tf_level_size(TFI_A, level);
    TF_COUNT_FETCHES(1);
    return TFI_FETCH(ivec2(tf_wrap(float(texel.x), size.x, wrapMode), tf_wrap(float(texel.y), size.y, wrapMode)),
                     level);
}
#endif

#endif
#endif
