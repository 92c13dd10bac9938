// texfilter/sat.glsl — summed-area-table (SAT) box filter: the exact mean of the texture over the
// footprint's bounding box, with fractional edges, in constant time whatever the footprint's size.
//
// Use:     vec4 tf_sat(usampler2D satLow, usampler2D satHigh, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s,
//                      vec4 offset, vec4 scale);                             // one box
//          vec4 tf_sat_assembly(usampler2D satLow, usampler2D satHigh, vec2 uv, vec2 dUVdx, vec2 dUVdy,
//                               tf_Sampler s, vec4 offset, vec4 scale, int boxes); // K boxes along the major axis
//          The same overloads with the tables as utexture2D, usampler2DArray or utexture2DArray (arrays with
//          `int layer` right after uv: one table pair a layer): the prototype list below. No TF_SOURCE form.
// Math:    texel space x = u·W, y = v·H, J = [dUVdx dUVdy]·exp2(lodBias) in texels; the box around (x, y) with
//          half-extents hx = ½(|J00| + |J01|), hy = ½(|J10| + |J11|) (the bounding box of the pixel's
//          parallelogram uv + J·(a, b), a, b in [−½, ½]); result = ∫∫box f / area, f the box-reconstructed
//          texture. Extents are clamped to W x H (a wider footprint averages one texture-sized box: with
//          repeat one period). tf_sat_assembly cuts the parallelogram along its longer column into K slices
//          and averages their boxes' means with equal weights; K = 1 is tf_sat exactly.
// Options: s.wrap (repeat/clamp/mirror); s.lodBias scales the footprint by exp2(lodBias); s.lodMin/lodMax
//          are ignored (no MIP levels). boxes: 1..16 (clamped). No defines.
// Needs:   satLow RGBA32UI (bits 0..31 of each channel's entry) and satHigh R32UI (bits 32..39 of R, G, B, A
//          as bytes 0..3), both (W+1) x (H+1), W, H <= 4096, read with texelFetch only; offset and scale per
//          channel: all four from tf::build_sat (host/texture/sat.h: SatTable::low, ::high, ::offset, ::scale)
//          or build_sat.glsl, uploaded as is. No MIP chain, no level-0 texture. Accuracy: within
//          0.5/65535·scale of the exact mean of the float texels, plus float32 rounding (16-bit quantisation
//          over each channel's own range; sums exact modulo 2^40).
// Cost:    32 texel fetches (16 table entries, 2 words each) for a box inside the texture, 64 where it
//          crosses a border on one axis, 128 on both; tf_sat_assembly K times that. Constant in the footprint.
// Degenerate input: non-finite uv, or a table smaller than 2 x 2 (none bound), gives vec4(0); NaN/±Inf
//          gradients give the whole texture's mean; zero gradients the texel under uv (nearest) on that axis;
//          gradient components are clamped to ±2^24 texels, so huge finite ones never overflow.
// Example: vec4 c = tf_sat(satLow, satHigh, uv, dFdxFine(uv), dFdyFine(uv), tf_sampler(TF_WRAP_REPEAT),
//                          satOffset, satScale); // SatTable::offset, ::scale, e.g. push constants
#ifndef TF_SAT_GLSL
#define TF_SAT_GLSL

// Footprint (DESIGN.md §3). Texel space x = u·W, y = v·H; J = [dUVdx dUVdy] in level-0 texels,
// times exp2(lodBias). tf_sat averages the box-reconstructed texture (texel (i, j) constant on
// [i, i+1) x [j, j+1)) over the bounding box of the pixel's parallelogram uv + J·(a, b), a, b in [−½, ½]:
// centre (x, y), half-extents hx = ½(|∂x/∂x|+|∂x/∂y|), hy = ½(|∂y/∂x|+|∂y/∂y|), i.e. the box
// [x0, x1) x [y0, y1) = [x − hx, x + hx) x [y − hy, y + hy). Result = ∫∫box f / area.
//   The extent is clamped to at most W x H texels (hx ≤ W/2, hy ≤ H/2): that keeps every sum inside the
//   bit budget. A footprint wider than the texture thus averages one texture-sized box around uv: with
//   repeat that is exactly one period (the mean along that axis); with clamp and mirror it is a window
//   of the extended texture, not the wider footprint's mean.
//   Non-finite uv → vec4(0). Non-finite gradients → the whole texture [0,W) x [0,H) (its mean, any wrap).
//   Zero gradients (a zero-width axis) → the texel under uv on that axis (nearest), no division by zero.
//   Gradient components are clamped to ±2^24 texels first, so huge finite gradients never overflow.
//
// Table and bit budget. Each channel c is quantised to 16 bits over the texture's own range:
// q = round((v − offset_c)/scale_c·65535), offset_c = the channel's smallest texel value, scale_c = its
// largest minus its smallest (rounded up to float; 0 for a constant channel: q = 0). So HDR data keeps
// 16 bits of its own range, texels at the channel's minimum are exact, and a lookup is within
// 0.5/65535·scale_c of the exact mean of the float texels, plus float32 rounding (~2^-22·(|offset_c| +
// scale_c), and box edges are float32 texel coordinates: a sub-texel box at coordinate x has its edges
// within ~2^-24·|x| of the exact ones). The bound is absolute: a texture with one 65504 spike among
// values near 0.3 has steps of ~1.0, so boxes mixing values above the minimum can be off by up to ~0.5.
// NaN and ±Inf texels are refused when the table is built (tf::build_sat throws), as are channels whose
// span overflows float.
// S(i, j) = Σ q over texels [0, i) x [0, j), 0 ≤ i ≤ W, 0 ≤ j ≤ H, stored modulo 2^40 in two words.
// Sums and differences are computed modulo 2^40 (uaddCarry/usubBorrow/umulExtended on two 32-bit words,
// no 64-bit integers: any Vulkan GPU), so a box sum S(x1,y1) − S(x0,y1) − S(x1,y0) + S(x0,y0) is exact
// whenever the box's true sum is below 2^40: every box of at most 2^24 texels (24 + 16 = 40 bits),
// hence every box of at most 4096 x 4096 texels — the box clamp above keeps every box within W x H ≤ 2^24.
//
// Fractional edges without cancellation. Per axis, with i0 = floor(x0), a0 = x0 − i0 and the last
// texel i1 = max(ceil(x1) − 1, i0), a1 = x1 − i1 ∈ (0, 1], the integral of a column function g is
//     ∫[x0,x1) g = (1 − a0)·G[i0, i0+1) + 1·G[i0+1, i1) + a1·G[i1, i1+1)      (i1 > i0)
//                = (x1 − x0)·G[i0, i0+1)                                      (i1 = i0: one texel)
// with G[p, q) the exact integer sum over whole texels [p, q). In 2D the box integral is Σ_k Σ_l
// wx_k·wy_l·B_kl over the 3 x 3 integer blocks B_kl = [px_k, px_k+1) x [py_l, py_l+1) with corners
// px = (i0, i0+1, i1, i1+1), py = (j0, j0+1, j1, j1+1): 16 table entries. Each block sum is formed
// exactly (modulo 2^40, non-negative, so exact) and only then converted to float and weighted; the
// weights are divided by the width per axis, so the result is a mean directly. A one-texel axis gets
// weights (1, 0, 0) (the garbage of the negative-width blocks is multiplied by 0); a zero-width axis
// is the limit, the texel under x (nearest). Mean = offset + Σ·scale/65535 (the weights sum to 1).
//
// Wrap modes. Box corners may lie outside [0, W]; the table is extended to any integer coordinate i
// per axis (G = cumulative sum of the wrapped texture, G(0) = 0), each a sum of ≤ 2 table columns
// with integer coefficients:
//     inside   0 ≤ i ≤ W:        S(i)
//     repeat   i = qW + r:       q·S(W) + S(r)                        (0 ≤ r < W)
//     clamp    i < 0:            i·S(1)                               (texel 0 repeated)
//              i > W:            (1 + i − W)·S(W) − (i − W)·S(W − 1)  (texel W−1 repeated)
//     mirror   i = 2qW + r:      2q·S(W) + S(r)                       (0 ≤ r ≤ W)
//                                (2q + 2)·S(W) − S(2W − r)            (W < r < 2W)
// so an extended 2D entry is ≤ 4 table entries, all in modular arithmetic (exact as long as the box's
// own sum fits, as above). Before that the centre is moved by whole periods (repeat: uv mod 1;
// mirror: uv mod 2; clamp: uv clamped to [−1, 2], beyond which the box only sees edge texels), which
// changes nothing but keeps coordinates small (and float precision in the box edges).
//
// tf_sat_assembly: the parallelogram is cut along its longer column (J·e_x or J·e_y) into K slices;
// each slice's bounding box is averaged as above and the K means are averaged with equal weights. All
// slices are translates of one another, so their boxes have the same size and equal weights are the
// area weights (no slice counts more than another; the overlap of neighbouring boxes is counted in each).
// K = 1 is tf_sat exactly (same float operations).

#include "common.glsl"

// Integers modulo 2^40, one per channel: bits 0..31 in lo, bits 32.. in hi. Arithmetic runs modulo 2^64
// (2^40 divides 2^64) and only the low 8 bits of hi are kept when converting.
struct tfi_SatInt {
    uvec4 lo;
    uvec4 hi;
};

tfi_SatInt tfi_sat_add(tfi_SatInt a, tfi_SatInt b)
{
    uvec4 carry;
    uvec4 lo = uaddCarry(a.lo, b.lo, carry);
    return tfi_SatInt(lo, a.hi + b.hi + carry);
}

tfi_SatInt tfi_sat_sub(tfi_SatInt a, tfi_SatInt b)
{
    uvec4 borrow;
    uvec4 lo = usubBorrow(a.lo, b.lo, borrow);
    return tfi_SatInt(lo, a.hi - b.hi - borrow);
}

// a·k for a small signed integer k.
tfi_SatInt tfi_sat_mul(tfi_SatInt a, int k)
{
    uint m = uint(abs(k));
    uvec4 msb, lsb;
    umulExtended(a.lo, uvec4(m), msb, lsb);
    tfi_SatInt p = tfi_SatInt(lsb, a.hi * m + msb);
    return k < 0 ? tfi_sat_sub(tfi_SatInt(uvec4(0u), uvec4(0u)), p) : p;
}

// The value modulo 2^40 as a float (used only on exact, non-negative block sums).
vec4 tfi_sat_to_float(tfi_SatInt a) { return vec4(a.hi & 0xFFu) * 4294967296.0 + vec4(a.lo); }

// One integer coordinate i of the extended table along an axis of n texels: E(i) = a·S(r) + b·S(n), 0 <= r <= n
// (see the header for the formulas): the texel column r, and the whole-texture column n with b = 0 inside.
struct tfi_SatAxis {
    int r;
    int a;
    int b;
};

// The quotient is taken in float, as tf_wrap does (SIMD devices without a vector integer divide, lavapipe, ran
// int / one lane at a time) and put right by one integer step: exact, since the box corners here lie within a
// few texture sizes of it (uv moved by whole periods, the box at most W x H texels, W, H <= 4096).
tfi_SatAxis tfi_sat_axis(int i, int n, int wrapMode)
{
    tfi_SatAxis axis = tfi_SatAxis(i, 1, 0); // inside [0, n]; one return (common.glsl)
    if (i < 0 || i > n) {
        if (wrapMode == TF_WRAP_CLAMP) { // texel 0 repeated below, texel n - 1 above
            axis = i < 0 ? tfi_SatAxis(1, i, 0) : tfi_SatAxis(n - 1, n - i, 1 + i - n);
        } else {
            int period = wrapMode == TF_WRAP_MIRROR ? 2 * n : n;
            int q = int(floor(float(i) / float(period)));
            int r = i - q * period;
            q += r < 0 ? -1 : (r >= period ? 1 : 0);
            r = i - q * period;
            if (wrapMode != TF_WRAP_MIRROR)
                axis = tfi_SatAxis(r, 1, q);
            else
                axis = r <= n ? tfi_SatAxis(r, 1, 2 * q) : tfi_SatAxis(period - r, -1, 2 * q + 2);
        }
    }
    return axis;
}

// One axis of the box [x0, x1): corners (i0, i0+1, i1, i1+1) and the weights of the three intervals
// between them (first texel, whole texels, last texel) divided by the width. Two neighbouring texels have
// no whole texel between them: that interval weighs 0, not 1/width, which a box far narrower than a texel
// across their edge would make +Inf (and Inf times its empty block's 0 a NaN).
void tfi_sat_edges(float x0, float x1, out ivec4 corners, out vec3 weights)
{
    float f0 = floor(x0);
    float l1 = max(ceil(x1) - 1.0, f0);
    int i0 = int(f0), i1 = int(l1);
    corners = ivec4(i0, i0 + 1, i1, i1 + 1);
    if (l1 == f0) // one texel, or a zero-width box: the texel under x0
        weights = vec3(1.0, 0.0, 0.0);
    else
        weights = vec3(f0 + 1.0 - x0, l1 > f0 + 1.0 ? 1.0 : 0.0, x1 - l1) / (x1 - x0);
}

// Moves uv by whole periods into [0, 1) (repeat) or [0, 2) (mirror): changes nothing (and is exact in
// float), keeps coordinates small, and is idempotent. Clamp: unchanged.
vec2 tfi_sat_period(vec2 uv, int wrapMode)
{
    if (wrapMode != TF_WRAP_CLAMP) { // one return (common.glsl)
        float period = wrapMode == TF_WRAP_MIRROR ? 2.0 : 1.0;
        uv -= period * floor(uv / period);
        uv = mix(uv, vec2(0.0), greaterThanEqual(uv, vec2(period))); // -tiny - floor(-tiny) rounds to period
    }
    return uv;
}

// The footprint's columns J·e_x, J·e_y in level-0 texels times exp2(lodBias), components clamped to
// ±2^24. False for non-finite gradients or a footprint entry (gradient · size) past float range, as in
// every family (docs/API.md "Degenerate input"): the caller then takes the whole texture's mean.
bool tfi_sat_columns(ivec2 size, vec2 dUVdx, vec2 dUVdy, float lodBias, out vec2 jx, out vec2 jy)
{
    jx = vec2(0.0);
    jy = vec2(0.0);
    if (!tf_finite(dUVdx * vec2(size)) || !tf_finite(dUVdy * vec2(size))) // NaN and ±Inf gradients too
        return false;
    vec2 m = vec2(size) * exp2(lodBias);
    jx = clamp(dUVdx * m, -TF_MAX_TEXEL_COORD, TF_MAX_TEXEL_COORD);
    jy = clamp(dUVdy * m, -TF_MAX_TEXEL_COORD, TF_MAX_TEXEL_COORD);
    return true;
}

// BEGIN prototypes (generated: tests/prototypes.py --write; ctest prototypes.current checks it)
// Every overload below is defined by this file's detail/*_kind.glsl for the kinds its #if names.
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D) != 0
vec4 tf_sat(usampler2D satLow, usampler2D satHigh, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec4 offset, vec4 scale);
vec4 tf_sat_assembly(usampler2D satLow, usampler2D satHigh, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec4 offset, vec4 scale, int boxes);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D) != 0
vec4 tf_sat(utexture2D satLow, utexture2D satHigh, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec4 offset, vec4 scale);
vec4 tf_sat_assembly(utexture2D satLow, utexture2D satHigh, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec4 offset, vec4 scale, int boxes);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D_ARRAY) != 0
vec4 tf_sat(usampler2DArray satLow, usampler2DArray satHigh, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec4 offset, vec4 scale);
vec4 tf_sat_assembly(usampler2DArray satLow, usampler2DArray satHigh, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec4 offset, vec4 scale, int boxes);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D_ARRAY) != 0
vec4 tf_sat(utexture2DArray satLow, utexture2DArray satHigh, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec4 offset, vec4 scale);
vec4 tf_sat_assembly(utexture2DArray satLow, utexture2DArray satHigh, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec4 offset, vec4 scale, int boxes);
#endif
// END prototypes

#define TFI_FAMILY TFI_FAMILY_SAT
#include "detail/instantiate.glsl"
#undef TFI_FAMILY

#endif
