// texfilter/common.glsl — shared pieces of every texfilter include: the sampler options (tf_Sampler),
// wrap modes, a wrapped texel fetch, the cost hooks. Pulls in version.glsl.
//
// Use:     #include "texfilter/common.glsl"   (every other include pulls it in itself)
//          tf_Sampler tf_sampler(int wrap);    // wrap, lodBias 0, lodMin 0, lodMax 1000 (all levels)
//          tf_Sampler(int wrap, float lodBias, float lodMin, float lodMax) // the struct; needs lodMin <= lodMax
//          vec4  tf_fetch(sampler2D tex, ivec2 texel, int level, int wrapMode); // wrapped texelFetch
//          int   tf_wrap(float i, int size, int wrapMode); // integer-valued texel coordinate → [0, size)
//          ivec2 tf_level_size(sampler2D tex, int level);  // max(1, textureSize(tex, 0) >> level)
//          bool  tf_finite(vec2 v);                         // neither NaN nor ±Inf
//          vec2  tf_reduce_uv(vec2 uv, int wrapMode);       // uv by whole periods into [-1, 1] (clamp: [-1, 2])
// Constants: TF_WRAP_REPEAT, TF_WRAP_CLAMP (clamp to edge), TF_WRAP_MIRROR (mirrored repeat; any other
//          value acts as repeat). TF_MAX_TEXEL_COORD = 2^24: texel coordinates are clamped to ± that.
//          TF_TAPS_MANUAL, TF_TAPS_HARDWARE: names for a caller's run-time choice of tf_X or tf_X_hw.
// Options: define before the first include, e.g. to count work per lookup (`texfilter sample --stats`):
//          TF_COUNT_FETCHES(n)     invoked with each number of texelFetch reads (default: nothing);
//          TF_COUNT_HW_LOOKUPS(n)  invoked with each number of hardware filtered lookups (default: nothing).
// Needs:   nothing bound: every function takes the sampler2D. Texel space (DESIGN.md §3): u = s·w_l with
//          w_l = max(1, w >> l); wraps act on integer texel coordinates before texelFetch, so the sampler's
//          own filter and address modes are not used and any sampler2D works (e.g. RGBA32F).
// Cost:    tf_fetch: 1 texel fetch; the others none.
// Example: tf_Sampler s = tf_sampler(TF_WRAP_REPEAT);
//          vec4 c = tf_fetch(tex, ivec2(-1, 3), 0, s.wrap); // texel (w-1, 3) of level 0
#ifndef TF_COMMON_GLSL
#define TF_COMMON_GLSL

#include "version.glsl"

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

// Size of a MIP level by the Vulkan floor rule. Derived from level 0 on purpose: textureSize() with a
// level that differs across a SIMD batch returned the wrong lane's size on lavapipe (Mesa 22.3).
ivec2 tf_level_size(sampler2D tex, int level) { return max(textureSize(tex, 0) >> level, ivec2(1)); }

vec4 tf_fetch(sampler2D tex, ivec2 texel, int level, int wrapMode)
{
    ivec2 size = tf_level_size(tex, level);
    TF_COUNT_FETCHES(1);
    return texelFetch(tex, ivec2(tf_wrap(float(texel.x), size.x, wrapMode),
                                 tf_wrap(float(texel.y), size.y, wrapMode)), level);
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

#endif
