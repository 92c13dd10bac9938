// texfilter/build_sat.glsl — the two summed-area tables tf_sat reads, built on the GPU by three compute
// dispatches you record: bit for bit the tables of tf::build_sat (texture/sat.h).
//
// Use:     define, before the include, how level 0 is read and the tables and the range words are
//          accessed, then call one pass function a dispatch (local size TF_SAT_GROUP_SIZE, 1, 1):
//              #define TF_SAT_LOAD(p)            texelFetch(level0, p, 0)          // vec4, linear values
//              #define TF_SAT_LOAD_LOW(e)        imageLoad(satLow, e)              // uvec4 (RGBA32UI)
//              #define TF_SAT_STORE_LOW(e, v)    imageStore(satLow, e, v)
//              #define TF_SAT_STORE_HIGH(e, v)   imageStore(satHigh, e, uvec4(v))  // R32UI
//              #define TF_SAT_RANGE              range.words    // a buffer uint[9]
//              #include "texfilter/build_sat.glsl"
//              // 1. range:   tf_sat_range_pass(size);     groups: tf_sat_range_groups(size), 1
//              // 2. rows:    tf_sat_rows_pass(size);      groups: size.y + 1, 1
//              // 3. columns: tf_sat_columns_pass(size);   groups: (size.x + 1 + 15) / 16, 1
//          with a compute -> compute barrier (shader writes -> shader reads) between them. Then
//          tf_sat_offset(TF_SAT_RANGE) and tf_sat_scale(TF_SAT_RANGE) are tf_sat's offset and scale in any
//          later shader (or read the 9 words back: tf::sat_range_offset_scale). Also: uint tf_sat_key(float),
//          float tf_sat_unkey(uint), the range words' order-preserving keys.
// Math:    per channel q = round((v − offset)/scale · 65535), half away from zero, in double (offset the
//          smallest texel, scale largest − smallest rounded up to float); entry (i, j) = Σ q over texels
//          [0, i) x [0, j), modulo 2^40 in two words (no 64-bit integers).
// Options: TF_SAT_NO_FP64, defined before the include, on a device without shaderFloat64: float quantisation,
//          within one level of the host's (not bit for bit).
// Needs:   size.x, size.y in 1..4096 (the bit budget); satLow RGBA32UI and satHigh R32UI storage images of
//          (size.x + 1) x (size.y + 1); TF_SAT_RANGE cleared before pass 1 to { 0xFFFFFFFF x 4, 0 x 4,
//          0xFFFFFFFF } (tf::sat_range_initial; vkCmdUpdateBuffer); shaderFloat64 unless TF_SAT_NO_FP64.
// Cost:    2 reads of level 0 (passes 1 and 2), 1 read and 2 writes of the tables (passes 2 and 3).
// Degenerate input: a NaN or ±Inf texel makes the tables meaningless; range word 8 then names the first one
//          ((index << 4) | (kind << 2) | channel, index = y·width + x, kind 1 NaN, 2 +Inf, 3 −Inf), else it stays
//          0xFFFFFFFF: check it (tf::build_sat refuses such textures). Without the macros: an #error.
// Example: layout(local_size_x = TF_SAT_GROUP_SIZE) in;
//          void main() { tf_sat_rows_pass(pc.size); } // the second dispatch
#ifndef TF_BUILD_SAT_GLSL
#define TF_BUILD_SAT_GLSL

// The range words: 0..3 the smallest texel of R, G, B, A and 4..7 the largest, as order-preserving keys
// (tf_sat_key); word 8 the first non-finite texel (see above). Quantisation as sat.glsl states it.
// Row pass: one group a row; each invocation sums a run of ≤ 16 texels of the row (256 runs cover 4096), the
// group scans the runs, and the row's inclusive prefix sums (below 2^28) go to satLow (x + 1, y + 1), column 0
// zero. Column pass: each group 16 columns x 16 runs of rows; a run's sum, a scan over the 16 runs, then the
// running 40-bit sums (two words, uaddCarry: no 64-bit integers) go to satLow and satHigh; row 0 zero.

#ifndef TF_SAT_LOAD
#error "texfilter/build_sat.glsl: define TF_SAT_LOAD(p), TF_SAT_LOAD_LOW, TF_SAT_STORE_LOW, TF_SAT_STORE_HIGH and TF_SAT_RANGE before including it"
#endif
#define TF_SAT_GROUP_SIZE 256
#define TF_SAT_RANGE_TEXELS 16 // texels an invocation reads in the range pass, and the most in a row's run (4096 / 256)

// Order-preserving float key: a < b  <=>  tf_sat_key(a) < tf_sat_key(b) (for non-NaN floats).
uint tf_sat_key(float v)
{
    uint u = floatBitsToUint(v);
    return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}
float tf_sat_unkey(uint k)
{
    return uintBitsToFloat((k & 0x80000000u) != 0u ? k & 0x7FFFFFFFu : ~k);
}

uint tf_sat_range_groups(ivec2 size)
{
    const uint texels = uint(size.x) * uint(size.y);
    const uint perGroup = uint(TF_SAT_GROUP_SIZE * TF_SAT_RANGE_TEXELS);
    return (texels + perGroup - 1u) / perGroup;
}

// Per channel: the value of quantisation level 0.
vec4 tf_sat_offset(uint range[9])
{
    return vec4(tf_sat_unkey(range[0]), tf_sat_unkey(range[1]), tf_sat_unkey(range[2]), tf_sat_unkey(range[3]));
}

#ifndef TF_SAT_NO_FP64
// The smallest float at or above d (d ≥ 0, finite as a float): the host's span, whatever the rounding of
// the device's double -> float conversion.
float tfi_sat_float_at_or_above(double d)
{
    float f = float(d);
    if (double(f) < d)
        f = uintBitsToFloat(floatBitsToUint(f) + 1u);
    else if (f > 0.0 && double(uintBitsToFloat(floatBitsToUint(f) - 1u)) >= d)
        f = uintBitsToFloat(floatBitsToUint(f) - 1u);
    return f;
}
#endif

// Per channel: largest − smallest, rounded up to float (0 for a constant channel).
vec4 tf_sat_scale(uint range[9])
{
    vec4 s;
    for (int c = 0; c < 4; ++c) {
        const float lo = tf_sat_unkey(range[c]), hi = tf_sat_unkey(range[4 + c]);
#ifndef TF_SAT_NO_FP64
        s[c] = tfi_sat_float_at_or_above(double(hi) - double(lo));
#else
        s[c] = hi - lo;
#endif
    }
    return s;
}

// The 16-bit level of one channel value.
uint tfi_sat_quantise(float v, float offset, float scale)
{
    if (!(scale > 0.0))
        return 0u;
#ifndef TF_SAT_NO_FP64
    precise double x = (double(v) - double(offset)) / double(scale) * 65535.0LF;
    precise double r = floor(x); // std::round: half away from zero (x ≥ 0 here; x − floor(x) is exact)
    if (x - r >= 0.5LF)
        r += 1.0LF;
    return uint(clamp(r, 0.0LF, 65535.0LF));
#else
    return uint(clamp(floor((v - offset) / scale * 65535.0 + 0.5), 0.0, 65535.0));
#endif
}

uvec4 tfi_sat_quantise4(vec4 v, vec4 offset, vec4 scale)
{
    return uvec4(tfi_sat_quantise(v.x, offset.x, scale.x), tfi_sat_quantise(v.y, offset.y, scale.y),
                 tfi_sat_quantise(v.z, offset.z, scale.z), tfi_sat_quantise(v.w, offset.w, scale.w));
}

shared uint tfi_sat_keys[8];
shared uvec4 tfi_sat_runs[TF_SAT_GROUP_SIZE];

// Pass 1: the per-channel range and the first non-finite texel.
void tf_sat_range_pass(ivec2 size)
{
    const uint lid = gl_LocalInvocationIndex;
    if (lid < 4u) {
        tfi_sat_keys[lid] = 0xFFFFFFFFu;
        tfi_sat_keys[4u + lid] = 0u;
    }
    barrier();
    uvec4 lo = uvec4(0xFFFFFFFFu), hi = uvec4(0u);
    const uint texels = uint(size.x) * uint(size.y);
    const uint base = gl_WorkGroupID.x * uint(TF_SAT_GROUP_SIZE * TF_SAT_RANGE_TEXELS);
    for (uint k = 0u; k < uint(TF_SAT_RANGE_TEXELS); ++k) {
        const uint index = base + k * uint(TF_SAT_GROUP_SIZE) + lid;
        if (index >= texels)
            break;
        const vec4 v = TF_SAT_LOAD(ivec2(index % uint(size.x), index / uint(size.x)));
        for (int c = 0; c < 4; ++c) {
            if (isnan(v[c]) || isinf(v[c])) {
                const uint kind = isnan(v[c]) ? 1u : v[c] > 0.0 ? 2u : 3u;
                atomicMin(TF_SAT_RANGE[8], (index << 4) | (kind << 2) | uint(c));
                continue;
            }
            lo[c] = min(lo[c], tf_sat_key(v[c]));
            hi[c] = max(hi[c], tf_sat_key(v[c]));
        }
    }
    for (int c = 0; c < 4; ++c) {
        atomicMin(tfi_sat_keys[c], lo[c]);
        atomicMax(tfi_sat_keys[4 + c], hi[c]);
    }
    barrier();
    if (lid < 4u) {
        atomicMin(TF_SAT_RANGE[lid], tfi_sat_keys[lid]);
        atomicMax(TF_SAT_RANGE[4u + lid], tfi_sat_keys[4u + lid]);
    }
}

// Inclusive scan of tfi_sat_runs[0 .. TF_SAT_GROUP_SIZE) (Hillis-Steele: log2(256) = 8 steps).
void tfi_sat_scan_runs()
{
    const uint lid = gl_LocalInvocationIndex;
    for (uint step = 1u; step < uint(TF_SAT_GROUP_SIZE); step *= 2u) {
        barrier();
        const uvec4 add = lid >= step ? tfi_sat_runs[lid - step] : uvec4(0u);
        barrier();
        tfi_sat_runs[lid] += add;
    }
    barrier();
}

// Pass 2: group y + 1 writes row y's prefix sums to satLow row y + 1 (group 0 has nothing to do: row 0 is
// the column pass's).
void tf_sat_rows_pass(ivec2 size)
{
    const uint lid = gl_LocalInvocationIndex;
    const int row = int(gl_WorkGroupID.x) - 1;
    if (row < 0)
        return;
    const vec4 offset = tf_sat_offset(TF_SAT_RANGE), scale = tf_sat_scale(TF_SAT_RANGE);
    // Texels an invocation sums: at most 16 (sides up to 4096), kept quantised for the second sweep.
    const int run = (size.x + TF_SAT_GROUP_SIZE - 1) / TF_SAT_GROUP_SIZE;
    const int x0 = int(lid) * run, x1 = min(size.x, x0 + run);
    uvec4 levels[TF_SAT_RANGE_TEXELS];
    uvec4 sum = uvec4(0u);
    for (int k = 0; k < TF_SAT_RANGE_TEXELS && x0 + k < x1; ++k) {
        levels[k] = tfi_sat_quantise4(TF_SAT_LOAD(ivec2(x0 + k, row)), offset, scale);
        sum += levels[k];
    }
    tfi_sat_runs[lid] = sum;
    tfi_sat_scan_runs();
    uvec4 prefix = lid > 0u ? tfi_sat_runs[lid - 1u] : uvec4(0u);
    if (lid == 0u)
        TF_SAT_STORE_LOW(ivec2(0, row + 1), uvec4(0u));
    for (int k = 0; k < TF_SAT_RANGE_TEXELS && x0 + k < x1; ++k) {
        prefix += levels[k];
        TF_SAT_STORE_LOW(ivec2(x0 + k + 1, row + 1), prefix);
    }
}

// (low, high) += v, the high words kept to 8 bits: sums modulo 2^40.
void tfi_sat_add40(inout uvec4 low, inout uvec4 high, uvec4 v)
{
    uvec4 carry;
    low = uaddCarry(low, v, carry);
    high = (high + carry) & 0xFFu;
}

// Pass 3: columns [16 g, 16 g + 16) of the table, each in 16 runs of rows, turned from row sums into the
// table: entry (x, y) = Σ of the row sums (x, 1..y), as two words.
void tf_sat_columns_pass(ivec2 size)
{
    const uint lid = gl_LocalInvocationIndex;
    const int column = int(gl_WorkGroupID.x) * 16 + int(lid % 16u);
    const int part = int(lid / 16u);
    const int rows = (size.y + 15) / 16; // rows of a run
    const int y0 = 1 + part * rows, y1 = min(size.y + 1, y0 + rows);
    const bool inside = column <= size.x;
    uvec4 low = uvec4(0u), high = uvec4(0u);
    if (inside)
        for (int y = y0; y < y1; ++y)
            tfi_sat_add40(low, high, TF_SAT_LOAD_LOW(ivec2(column, y)));
    // This run's start: the 40-bit sum of the column's earlier runs (lows with their carries, then highs).
    tfi_sat_runs[lid] = low;
    barrier();
    uvec4 baseLow = uvec4(0u), baseHigh = uvec4(0u);
    for (int p = 0; p < part; ++p)
        tfi_sat_add40(baseLow, baseHigh, tfi_sat_runs[p * 16 + int(lid % 16u)]);
    barrier();
    tfi_sat_runs[lid] = high;
    barrier();
    for (int p = 0; p < part; ++p)
        baseHigh = (baseHigh + tfi_sat_runs[p * 16 + int(lid % 16u)]) & 0xFFu;
    if (!inside)
        return;
    if (part == 0) {
        TF_SAT_STORE_LOW(ivec2(column, 0), uvec4(0u));
        TF_SAT_STORE_HIGH(ivec2(column, 0), 0u);
    }
    low = baseLow;
    high = baseHigh;
    for (int y = y0; y < y1; ++y) {
        tfi_sat_add40(low, high, TF_SAT_LOAD_LOW(ivec2(column, y)));
        TF_SAT_STORE_LOW(ivec2(column, y), low);
        TF_SAT_STORE_HIGH(ivec2(column, y), high.x | (high.y << 8) | (high.z << 16) | (high.w << 24));
    }
}

#endif // TF_BUILD_SAT_GLSL
