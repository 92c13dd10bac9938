// texfilter/ewa.glsl — elliptical weighted average (EWA): a Gaussian over the pixel's elliptical footprint,
// on two MIP levels blended by the fractional LOD. Correct zoomed in and zoomed out.
//
// Use:     vec4 tf_ewa(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
//          vec4 tf_ewa_hw(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha,
//                         float maxAniso); // the same weights, read as hardware bilinear taps on 2x2 blocks
//          Every resource kind and a TF_SOURCE (common.glsl) have the same overloads, extras such as
//          `int layer` right after uv: the prototype list near the end of this file.
// Math:    J = [dUVdx dUVdy]·size in level-0 texels; the footprint ellipse J·Jᵀ, its minor axis grown to
//          major/maxAniso. On level l (texels scaled by S = size_l/size_0, s² = det S) the filter uses
//          M = S·J·Jᵀ·S + c·I. Texels whose centres have r² = xᵀM⁻¹x < R² = 2 weigh exp(−alpha·r²) −
//          exp(−alpha·R²), zero at the support's edge (no texel pops in or out); their covariance is v·M, v the
//          weight's variance in units of M (0.21 at alpha 2). The aim is a Gaussian pixel over level 0
//          reconstructed bilinearly: v·J·Jᵀ (the truth's ¼·J·Jᵀ less the support's cut at alpha 2) plus the
//          tent's 1/6 level-0 texel². A level-l texel already averages a box of 1/s² level-0 texels ((1 − s²)/12
//          level-l texel²), so the level adds c₀ = (s²/6 − (1 − s²)/12)/v = (3s² − 1)/(12v) (0.79 on level 0 at
//          alpha 2, down to −0.40), raised to what makes M's smaller eigenvalue TFI_EWA_SMALLEST = 2.5 (a
//          Gaussian sampled finely enough that a level's Nyquist-rate patterns and step edges are not passed
//          on) and at most 1: M = S·J·Jᵀ·S + I where the footprint is under 1.5 texels² (zoom-in works), the
//          loop cap's bound.
//          A level's value is the weighted least-squares line through the texels read, at uv (exact on a
//          linear texture, where a weighted mean sits on the weights' centroid), clamped to their range.
//          λ = max(log2 minor − ½, log2 major − log2((K−3)/(4R))) + lodBias, clamped: the minor semi-axis spans
//          √2..2√2 texels of level floor(λ) (S·J·Jᵀ·S's smaller eigenvalue 2..8, where M needs little lift),
//          unless the major one would exceed the loop cap; floor(λ) and floor(λ)+1 blended by frac(λ).
//          Magnification: where trilinear's λ < 1, level 0's trilinear share 1 − clamp(λ, 0, 1) goes to the
//          magnification filter (bilinear, or TF_MAGNIFY's cubic) averaged over the footprint: the mean of 4 of
//          its lookups at uv ± k·(dUVdx ± dUVdy), k² the weight's variance, so their spread is the ellipse's.
//          tf_ewa_hw: one bilinear tap per 2x2 block (blocks anchored to even texels of the level), at the
//          block's weight centroid, all shifted so that the taps average to uv: a positive-weighted mean of
//          taps, exact on a linear texture. One tap gives a block separable weights; a block twisted more than
//          that allows (tfi_ewa_block_twisted) gets two, one a texel pair, which give its weights exactly.
// Options: alpha (2, as pbrt): the Gaussian's sharpness, clamped to [0, 64]; NaN or negative → 0 (weight 1 − r²/R²).
//          maxAniso (e.g. 16): the largest major/minor ratio; below 1 or NaN → 1. Larger: sharper at grazing
//          angles, more reads. s.wrap, s.lodBias, s.lodMin, s.lodMax as every filter; TF_MAGNIFY (common.glsl).
//          TF_EWA_MAX_TEXELS K, defined before the include (odd, >= 7; default 95): the loop cap below.
// Needs:   a full MIP chain. tf_ewa: texelFetch only. tf_ewa_hw: the sampler bound with the texture filters
//          linearly (min and mag; any mipmapMode) with the wrap mode s.wrap, no LOD bias, no LOD clamp
//          narrower than the levels (the sampler's bias and clamps apply to textureLod too).
// Cost:    tf_ewa reads each texel of the support once on each of 2 levels: about 41 for an isotropic footprint,
//          340 at 16:1, 89.3 on the plane; at most K² a level whatever the input. tf_ewa_hw: one lookup per 2x2
//          block that meets the support, two for a twisted one: about 0.4 of those reads (its weights are
//          evaluated twice), 33.0 on the plane; at most 2(K/2+1)² a level.
//          Where λ < 1, 4 lookups of the magnification filter more (bilinear: 16 fetches or 4 taps).
// Degenerate input: zero gradients → the magnification filter alone on level 0 (with lodMin >= 1: lodMin's
//          level with M = I); huge gradients → the coarsest level the clamps allow (normally the 1x1 mean);
//          NaN or ±Inf in a gradient, or a footprint past float range → that level with M = I. Non-finite uv →
//          vec4(0); huge finite uv is first moved by whole periods (tf_reduce_uv). Where lodMax or lodBias leave
//          a support wider than K texels, it is shrunk to fit, same shape (it then aliases, like any LOD clamp).
//          A 1x1 level is read once.
// Example: vec4 c = tf_ewa(tex, uv, dFdxFine(uv), dFdyFine(uv), tf_sampler(TF_WRAP_REPEAT), 2.0, 16.0);
#ifndef TF_EWA_MAX_TEXELS
#define TF_EWA_MAX_TEXELS 95
#endif

#ifndef TF_EWA_GLSL
#define TF_EWA_GLSL

#if TF_EWA_MAX_TEXELS < 7 || (TF_EWA_MAX_TEXELS % 2) == 0
#error "TF_EWA_MAX_TEXELS must be odd and at least 7"
#endif

#include "lod.glsl"
#include "bicubic.glsl" // tfi_magnified_level0: TF_MAGNIFY

// Widens the row/column spans a little so that the r² test, not rounding in the span, decides.
const float TFI_EWA_SPAN_MARGIN = 1.0 / 256.0;

// The weight's support: r² = xᵀM⁻¹x < TF_EWA_SUPPORT (R², in the footprint's own units: r = 1 is one
// pixel from its centre). Below, M is scaled by R² so that the loops test the support ellipse against 1.
const float TF_EWA_SUPPORT = 2.0;

// M's smallest eigenvalue on a level (level texels²), unless the footprint's own is below it by more than 1:
// then M = S·J·Jᵀ·S + I (header, Math).
const float TFI_EWA_SMALLEST = 2.5;

// The ellipse of one lookup before any level: level-0 texel space, scaled by 1/m² (m = the largest
// |gradient component|, so that 1e30 gradients do not overflow).
struct tfi_EwaShape {
    vec3 cov;     // (xx, xy, yy) of the clamped J·Jᵀ / m²
    float major2; // its eigenvalues / m², major2 >= minor2
    float minor2;
    float m;      // 0 for zero or non-finite gradients: then M = I on every level
};

// Per-axis variance of the weight exp(-alpha r²) - exp(-alpha R²) over r² < R², in units of M (0.21 at alpha 2;
// 1/3 as alpha -> 0): E[r²]/2 with u = r², both integrals in closed form.
float tfi_ewa_weight_variance(float alpha)
{
    float a = max(alpha, 1.0 / 64.0), U = TF_EWA_SUPPORT, e = exp(-a * U);
    float mass = (1.0 - e) / a - U * e;
    float moment = (1.0 - e * (1.0 + a * U)) / (a * a) - 0.5 * U * U * e;
    return 0.5 * moment / mass;
}

// r²/R² = xᵀ(R²M)⁻¹x for x = (dx, dy): below 1 inside the support.
float tfi_ewa_r2(vec3 M, float det, float dx, float dy)
{
    return (M.z * dx * dx - 2.0 * M.y * dx * dy + M.x * dy * dy) / det;
}

// The weight exp(-alpha r²) - exp(-alpha R²) (r2 = r²/R² here), continuous at the support's edge, divided
// by alpha R² (the sums are normalised, so that alpha 0 has a limit: 1 - r²/R²). Near the edge, where
// the difference would cancel (q < ½), exp(-alpha R²)·expm1(q)/(alpha R²) as a series, q = alpha R² (1 - r²/R²).
float tfi_ewa_weight(float r2, float alpha)
{
    float t = 1.0 - r2, aR2 = alpha * TF_EWA_SUPPORT, q = aR2 * t, edge = exp(-aR2);
    if (q >= 0.5)
        return (exp(-aR2 * r2) - edge) / aR2; // cancels by at most 1/(1 - exp(-1/2)) = 2.5
    // expm1(q)/q to q^7/8!: the next term is below 1e-8 relative for q < 1/2.
    float p = 1.0 + q * (1.0 / 2.0 + q * (1.0 / 6.0 + q * (1.0 / 24.0 + q * (1.0 / 120.0 + q * (1.0 / 720.0 +
              q * (1.0 / 5040.0 + q * (1.0 / 40320.0)))))));
    return edge * t * p;
}

// Texel offsets [lo, hi] (from base) of the row at dy from the centre whose centres lie in the
// ellipse (lo > hi: none); fx = frac.x.
vec2 tfi_ewa_row_span(vec3 M, float det, float fx, float dy)
{
    float disc = M.z - dy * dy;
    if (disc < 0.0)
        return vec2(1.0, 0.0);
    float xc = fx + M.y / M.z * dy, halfWidth = sqrt(det * disc) / M.z;
    return vec2(ceil(xc - halfWidth - 0.5 - TFI_EWA_SPAN_MARGIN), floor(xc + halfWidth - 0.5 + TFI_EWA_SPAN_MARGIN));
}

// Texel row offsets [lo, hi] (from base) that the ellipse can reach; fy = frac.y.
vec2 tfi_ewa_rows(vec3 M, float fy)
{
    float hy = sqrt(M.z);
    return vec2(ceil(fy - hy - 0.5 - TFI_EWA_SPAN_MARGIN), floor(fy + hy - 0.5 + TFI_EWA_SPAN_MARGIN));
}

// The 2x2 blocks of the hardware-tap forms (tfi_ewa_blocks_hw): blocks start at even offsets from the level's
// texel grid (parity), rows of blocks from firstRow, `rows` of them (K texels touch at most K/2 + 1 blocks).
const int TFI_EWA_MAX_BLOCKS = TF_EWA_MAX_TEXELS / 2 + 1;
struct tfi_EwaBlocks {
    vec2 parity;
    float firstRow;
    int rows;
};

tfi_EwaBlocks tfi_ewa_blocks(vec3 M, vec2 base, vec2 frac)
{
    vec2 parity = base - 2.0 * floor(0.5 * base); // blocks start at offsets o with base + o even
    vec2 rowSpan = tfi_ewa_rows(M, frac.y);
    float firstRow = 2.0 * floor(0.5 * (rowSpan.x + parity.y)) - parity.y;
    int rows = int(clamp(floor(0.5 * (rowSpan.y - firstRow)) + 1.0, 0.0, float(TFI_EWA_MAX_BLOCKS)));
    return tfi_EwaBlocks(parity, firstRow, rows);
}

// The block row whose texel rows are at offsets dy0 and dy0 + 1 from the centre: its first block column
// (firstCol) and the number of blocks, 0 where neither texel row meets the ellipse.
int tfi_ewa_block_columns(vec3 M, float det, vec2 frac, float parityX, float dy0, out float firstCol)
{
    vec2 span0 = tfi_ewa_row_span(M, det, frac.x, dy0), span1 = tfi_ewa_row_span(M, det, frac.x, dy0 + 1.0);
    float lo = min(span0.x <= span0.y ? span0.x : 1e30, span1.x <= span1.y ? span1.x : 1e30);
    float hi = max(span0.x <= span0.y ? span0.y : -1e30, span1.x <= span1.y ? span1.y : -1e30);
    firstCol = 2.0 * floor(0.5 * (lo + parityX)) - parityX;
    int cols = int(clamp(floor(0.5 * (hi - firstCol)) + 1.0, 0.0, float(TFI_EWA_MAX_BLOCKS)));
    return lo > hi ? 0 : cols;
}

// The block whose first texel is at offset (dx0, dy0) from the centre: its total weight, its four weights w
// (w00, w10, w01, w11), and in ab the bilinear fraction that reproduces them ((1-a)(1-b), a(1-b), (1-a)b, ab =
// w/total when separable; a lookup at texel coordinate 2b + ½ + a reads the block's first texel at 2b with
// fraction a). ab means nothing where total is 0 (callers skip those blocks).
float tfi_ewa_block(vec3 M, float det, float alpha, float dx0, float dy0, out vec2 ab, out vec4 w)
{
    float dx1 = dx0 + 1.0, dy1 = dy0 + 1.0;
    vec4 r2 = vec4(tfi_ewa_r2(M, det, dx0, dy0), tfi_ewa_r2(M, det, dx1, dy0), tfi_ewa_r2(M, det, dx0, dy1),
                   tfi_ewa_r2(M, det, dx1, dy1));
    w = vec4(tfi_ewa_weight(r2.x, alpha), tfi_ewa_weight(r2.y, alpha), tfi_ewa_weight(r2.z, alpha),
             tfi_ewa_weight(r2.w, alpha));
    w = mix(vec4(0.0), w, lessThan(r2, vec4(1.0)));
    float total = w.x + w.y + w.z + w.w;
    ab = vec2(w.y + w.w, w.z + w.w) / total;
    return total;
}

// One bilinear tap gives a block separable weights: its row and column sums are exact, but the part of the
// block's value that alternates like a checkerboard, (t00 − t10 − t01 + t11)/4, is weighed 4·(w00·w11 −
// w10·w01)/total wrong. A rotated ellipse twists every block the same way, so on texels that alternate at
// the level's Nyquist rate (a checker seen from afar, a zone plate) the errors add up: up to 0.011 RMS off
// the manual form at 64-256 texels. Blocks twisted by more than this share of the level's whole weight
// are read as two exact taps, one a texel pair; the rest keep one. At this limit the hardware-tap form is
// within 0.0006 RMS of the manual one on such textures, at about 1.15x the lookups (docs/BENCHMARKS.md, EWA).
const float TFI_EWA_TWIST_LIMIT = 0.005;

bool tfi_ewa_block_twisted(vec4 w, float total, float levelTotal)
{
    return 4.0 * abs(w.x * w.w - w.y * w.z) / total > TFI_EWA_TWIST_LIMIT * levelTotal;
}

// Weighted moments of one level's texels about the lookup's centre, d = texel centre - centre (in
// tfi_ewa_level's whitened coordinates): w = sum w, wd = sum w·d, wdd = sum w·(dx², dx·dy, dy²),
// t = sum w·(value - pivot), tx, ty = sum w·dx·(value - pivot), sum w·dy·(value - pivot); pivot = the first texel's value (so that the sums
// are small and a constant texture gives exactly its value); lo, hi = the texels' per-channel range.
struct tfi_EwaMoments {
    float w;
    vec2 wd;
    vec3 wdd;
    vec4 t, tx, ty, pivot, lo, hi;
};

// The weighted least-squares fit value + g·d over the samples, evaluated at the centre (d = 0): the
// weighted mean, less the fitted gradient times the samples' centroid offset m. Exact for a linear
// function whatever the discrete sample set (the weighted mean alone is off by m, up to ~0.1 texel of
// the level); where the centroid is at the centre it is the weighted mean. The support holds the disc
// of radius sqrt(R²) = 1.41 texels, so at least 3 of the 4 nearest texel centres, never on one line:
// the 2x2 system is never singular (a single sample, impossible, would return the mean).
vec4 tfi_ewa_fit_unclamped(tfi_EwaMoments s)
{
    if (!(s.w > 0.0))
        return vec4(0.0);
    float inv = 1.0 / s.w;
    vec2 m = s.wd * inv;
    vec4 mean = s.t * inv;
    vec3 C = s.wdd * inv - vec3(m.x * m.x, m.x * m.y, m.y * m.y); // the positions' weighted covariance
    float det = C.x * C.z - C.y * C.y;
    if (!(det > 0.0))
        return s.pivot + mean;
    vec2 q = vec2(C.z * m.x - C.y * m.y, C.x * m.y - C.y * m.x) / det; // C⁻¹·m
    return s.pivot + mean - q.x * (s.tx * inv - m.x * mean) - q.y * (s.ty * inv - m.y * mean);
}

// The fit clamped to the range of the texels read (a line fitted across a step edge can overshoot it). Linear
// textures stay exact: the 4 texel centres around uv lie in the support (the disc of radius 1.41 texels), so uv
// is inside their hull and a linear texture's value there within their range.
vec4 tfi_ewa_fit(tfi_EwaMoments s)
{
    return clamp(tfi_ewa_fit_unclamped(s), s.lo, s.hi);
}
// BEGIN prototypes (generated: tests/prototypes.py --write; ctest prototypes.current checks it)
// Every overload below is defined by this file's detail/*_kind.glsl for the kinds its #if names.
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D) != 0
vec4 tf_ewa(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_hw(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D) != 0
vec4 tf_ewa(texture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_hw(texture2D tex, sampler smp, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SAMPLER_2D_ARRAY) != 0
vec4 tf_ewa(sampler2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_hw(sampler2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
#endif
#if (TF_RESOURCES & TF_RESOURCE_TEXTURE_2D_ARRAY) != 0
vec4 tf_ewa(texture2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_hw(texture2DArray tex, sampler smp, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
#endif
#if (TF_RESOURCES & TF_RESOURCE_INTEGER) != 0
vec4 tf_ewa(isampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa(itexture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa(usampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa(utexture2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
#endif
#if (TF_RESOURCES & TF_RESOURCE_SHADOW) != 0
vec4 tf_ewa(sampler2D tex, vec2 uv, tf_Compare cmp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa(texture2D tex, vec2 uv, tf_Compare cmp, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_hw(sampler2DShadow tex, vec2 uv, float dref, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_hw(texture2D tex, samplerShadow smp, vec2 uv, float dref, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE) != 0
vec4 tf_ewa(samplerCube tex, vec2 uv, int face, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa(textureCube tex, sampler smp, vec2 uv, int face, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_hw(samplerCube tex, vec2 uv, int face, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_hw(textureCube tex, sampler smp, vec2 uv, int face, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE_ARRAY) != 0
vec4 tf_ewa(samplerCubeArray tex, vec2 uv, int face, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa(textureCubeArray tex, sampler smp, vec2 uv, int face, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_hw(samplerCubeArray tex, vec2 uv, int face, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_hw(textureCubeArray tex, sampler smp, vec2 uv, int face, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
#endif
#if (TF_RESOURCES & TF_RESOURCE_LATLONG) != 0
vec4 tf_ewa(sampler2D tex, vec2 uv, tf_LatLong latlong, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_hw(sampler2D tex, vec2 uv, tf_LatLong latlong, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
#endif
#ifdef TF_SOURCE
vec4 tf_ewa(TF_SOURCE tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
#endif
// END prototypes

#define TFI_FAMILY TFI_FAMILY_EWA
#include "detail/instantiate.glsl"
#undef TFI_FAMILY

#endif
