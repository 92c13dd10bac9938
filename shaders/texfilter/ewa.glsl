// texfilter/ewa.glsl — elliptical weighted average (EWA): a Gaussian over the pixel's elliptical
// footprint, on two MIP levels blended by the fractional LOD. Correct zoomed in and zoomed out.
//
// Use:     vec4 tf_ewa(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
//          vec4 tf_ewa_hw(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha,
//                         float maxAniso); // the same weights from hardware bilinear taps on 2x2 blocks
//          Every resource kind (access.glsl, docs/API.md "Resources"): the manual form also with texture2D,
//          u/isampler2D, u/itexture2D, sampler2DArray / texture2DArray + `int layer` after uv, or a depth
//          sampler2D / texture2D + `tf_Compare cmp` after uv (percentage-closer filtering over the footprint);
//          the _hw form also with texture2D + sampler, sampler2DArray, texture2DArray + sampler (+ `int layer`),
//          sampler2DShadow or texture2D + samplerShadow + `float dref` after uv (each tap a hardware
//          comparison), e.g.
//          tf_ewa(texture2DArray tex, vec2 uv, int layer, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha,
//                 float maxAniso).
// Options: s.wrap, s.lodBias, s.lodMin, s.lodMax as everywhere (common.glsl, lod.glsl). TF_MAGNIFY
//   (common.glsl, bicubic.glsl): the magnification filter (below).
// Magnification (issue 16): where trilinear would read level 0 (its λ = tf_lod < 1), the result moves towards
//   the magnification filter of level 0 (bilinear, Vulkan's LINEAR magFilter, or TF_MAGNIFY's cubic)
//   by level 0's trilinear share, 1 − clamp(λ, 0, 1): that filter alone at λ <= 0, the ellipse alone from λ = 1.
//   The ellipse's one-texel reconstruction term (M = J·Jᵀ + I) is a Gaussian of σ ½ texel, blurrier than the
//   tent: on the zoom scene it cost 11.4 dB against the Gaussian truth and 3.5x the flicker (lavapipe, 128²).
//   The magnification filter is integrated over the pixel's footprint: the mean of 4 of its lookups at
//   uv ± k·(dUVdx + dUVdy) and uv ± k·(dUVdx − dUVdy), k² the weight's per-axis variance (0.21 at alpha 2),
//   whose spread has the ellipse's own covariance k²·J·Jᵀ. It is the filter itself as the footprint vanishes
//   (zero gradients). One lookup instead aliased like trilinear where the footprint spans about a texel
//   (λ in (0, 1): the plane's near rows). Measured (lavapipe, 2026-12-03, 256², checker 512, Gaussian truth,
//   against one lookup): plane 35.3 -> 36.2 dB and flicker 0.0064 -> 0.0024; zoom 49.8 -> 65.6 dB and
//   0.0034 -> 0.0008; tunnel 38.2 -> 42.2 dB; minify and slanted unchanged.
//          alpha (2, as pbrt, is the usual choice): weight exp(-alpha r²) - exp(-alpha R²), clamped to
//            [0, 64]; NaN or negative -> 0 (then 1 - r²/R²). Smaller alpha = a wider Gaussian = blurrier.
//          maxAniso (e.g. 16): largest major/minor axis ratio; a thinner ellipse has its minor axis
//            grown to major/maxAniso (below 1 or NaN: 1). Larger = sharper at grazing angles, more reads.
//          TF_EWA_MAX_TEXELS: define before including (odd, >= 7; default 95): the loop cap K below.
// Needs:   tex with a full MIP chain. tf_ewa: any sampler2D (texelFetch only). tf_ewa_hw: the sampler
//          bound with the texture must filter linearly (min/mag; any mipmapMode: the level is an integer)
//          with the wrap mode in s.wrap, no LOD bias and no LOD clamp narrower than the levels (the
//          sampler's bias and clamps apply to textureLod too). See "Hardware taps" below.
// Example: vec4 c = tf_ewa(tex, uv, dFdxFine(uv), dFdyFine(uv), tf_sampler(TF_WRAP_REPEAT), 2.0, 16.0);
//
// Math (DESIGN.md section 3). J = [dUV/dx dUV/dy] in level-0 texels; the footprint ellipse J·Jᵀ has
//   semi-axes major >= minor (J's singular values); minor is raised to major/maxAniso. On level l
//   (texel coordinates u·w_l) the filter uses M = S·(J·Jᵀ, clamped)·S + I with S = diag(w_l/w_0,
//   h_l/h_0): the +I is the one-texel reconstruction term that makes zoom-in work. Every texel whose
//   centre x (relative to uv·w_l) has r² = xᵀM⁻¹x < R² (R² = TF_EWA_SUPPORT = 2) weighs
//   exp(-alpha r²) - exp(-alpha R²) (computed with exp(), no LUT): continuous, zero at the support's
//   edge (as pbrt's), so no texel jumps in or out and float and double agree there.
// Support R² = 2, not pbrt's 1, by measurement (docs/DESIGN.md section 4; texfilter bench --quick, manual
//   taps, Gaussian-pixel truth): RMSE plane 0.0231 vs 0.0313, tunnel 0.0172 vs 0.0264, slanted
//   0.0346 vs 0.0412, mesh 0.0381 vs 0.0438, flicker 0.0037 vs 0.0077 (plane); at twice the reads.
//   At alpha 2 it is a Gaussian about one pixel wide (per-axis variance 0.21 in units of M).
// Unbiased (issue 10): per level, a weighted least-squares line fit value + g·d over the texels read,
//   evaluated at uv. A weighted mean of a discrete texel set is centred on its weight centroid, up to
//   ~0.1 level texels off uv (2^l level-0 texels); the fit reproduces any linear texture exactly,
//   whichever texels the support catches. Each level's result is clamped to the range of the texels it
//   read (a line fitted across a step can overshoot it: up to 2 % of the step at alpha 8); linear
//   textures stay exact, since the 4 texel centres around uv lie inside the support.
// Level rule: lambda = max(log2(minor), log2(major / ((K-3)/(4R)))) + lodBias (semi-axes after the
//   eccentricity clamp, level-0 texels), clamped to [lodMin, lodMax] and the existing levels. On the
//   continuous level lambda the minor axis spans 2 texels (semi-axis 1, as pbrt); the two levels read,
//   floor(lambda) and floor(lambda)+1, see it span 2..4 and 1..2 texels and are blended by
//   frac(lambda), so there are no seams. The second term moves to a coarser level only when the major
//   semi-axis would pass (K-3)/(4R) = 16.3 texels, i.e. never for maxAniso <= 16 at the default K.
//   An isotropic footprint gets trilinear's lambda. lodBias -1: twice the texels across (4x the reads).
// Hard cap (every input; a shader never hangs): per level at most K rows of at most K texels
//   (tf_ewa_hw: K/2+1 rows of K/2+1 2x2 blocks). Where the LOD clamps (lodMax, lodBias) leave a
//   support whose bounding box is wider than K texels, it is shrunk, same shape, to fit (so it then
//   aliases, like any LOD clamp). A 1x1 level is read once, whatever the ellipse.
// Degenerate input (docs/API.md): zero gradients -> λ = −∞: the magnification filter on level 0 (with
//   lodMin >= 1: lodMin's level with M = I, a one-texel Gaussian around uv); huge (1e30, 3e38) -> the coarsest level the clamps allow (normally
//   the last, 1x1: the texture's mean); NaN or ±Inf in any component, or a footprint entry
//   (gradient·size) past float range -> that same level with M = I. Non-finite uv returns vec4(0);
//   huge finite uv is first moved by whole periods (tf_reduce_uv), in both forms.
// Hardware taps (tf_ewa_hw): the same weights, read through textureLod(tex, uv, level) on the sampler
//   bound with the texture, which must filter linearly with the same wrap mode. Texels are paired in
//   2x2 blocks anchored to even texel indices of the level (a fixed grid; one that followed the
//   ellipse's bounding box made blotches near the horizon); one bilinear lookup per block, at the
//   block's weight centroid, weighted by the block's total weight. The taps' weighted mean position is
//   their weight centroid, not uv, so a first pass sums the weights' moments and the second moves every
//   tap by the centroid's offset: the taps then average to uv, exact on a linear texture (a bilinear
//   lookup reproduces it wherever it lands). A positive-weighted mean of bilinear taps, so it cannot
//   overshoot. It differs from tf_ewa by how each treats the texture's non-linear part (measured, alpha
//   2, 256² noise: RMS 0.005, max 0.05) and by the sampler's sub-texel rounding (8 bits allowed).
// Cost (texfilter sample --stats, alpha 2, maxAniso 16, 256² noise): tf_ewa reads each texel inside the
//   support once on each level: isotropic footprints of 1..64 texels 29 on average (at most 46), 16:1
//   footprints ~350 (at most ~600); at most K² = 9025 per level whatever the input. tf_ewa_hw: one
//   lookup per 2x2 block touching the support (its weights are evaluated twice), ~0.35-0.4 of those reads as
//   lookups (isotropic 12, 16:1 ~120). No early out for isotropic footprints: it is the same formula.
//   Where λ < 1, the magnification filter adds 4 of its lookups (bilinear: 16 fetches or 4 taps).
//   Plane scene (docs/FILTERS.md): tf_ewa 79.2 fetches on average, tf_ewa_hw 26.8 lookups (one magnification
//   lookup: 73.5, 26.0; R² = 1: 36.8, 14.6).
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

// The 2x2-block walk of the hardware-tap forms (tfi_ewa_level_hw, and stochastic.glsl's one-tap EWA, which
// picks one block of the same walk): blocks start at even offsets from the level's texel grid (parity), rows of
// blocks from firstRow, `rows` of them (at most TF_EWA_MAX_TEXELS / 2 + 1: K texels touch at most K/2 + 1 blocks).
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

// The block whose first texel is at offset (dx0, dy0) from the centre: its total weight, and in ab the
// bilinear fraction that reproduces its four weights ((1-a)(1-b), a(1-b), (1-a)b, ab = w/total when separable;
// a lookup at texel coordinate 2b + ½ + a reads the block's first texel at 2b with fraction a). ab means
// nothing where total is 0 (callers skip those blocks).
float tfi_ewa_block(vec3 M, float det, float alpha, float dx0, float dy0, out vec2 ab)
{
    float dx1 = dx0 + 1.0, dy1 = dy0 + 1.0;
    vec4 r2 = vec4(tfi_ewa_r2(M, det, dx0, dy0), tfi_ewa_r2(M, det, dx1, dy0), tfi_ewa_r2(M, det, dx0, dy1),
                   tfi_ewa_r2(M, det, dx1, dy1));
    vec4 w = vec4(tfi_ewa_weight(r2.x, alpha), tfi_ewa_weight(r2.y, alpha), tfi_ewa_weight(r2.z, alpha),
                  tfi_ewa_weight(r2.w, alpha));
    w = mix(vec4(0.0), w, lessThan(r2, vec4(1.0))); // w00, w10, w01, w11
    float total = w.x + w.y + w.z + w.w;
    ab = vec2(w.y + w.w, w.z + w.w) / total;
    return total;
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

// The fit clamped to the range of the texels read: a line fitted across a step edge can overshoot it
// (by up to 2 % of the step at alpha 8 on a checker, none measured at alpha <= 2). The clamp keeps linear
// textures exact: the 4 texel centres around uv lie in the support (the disc of radius 1.41 texels), so
// uv is inside their hull and a linear texture's value there within their range.
vec4 tfi_ewa_fit(tfi_EwaMoments s)
{
    return clamp(tfi_ewa_fit_unclamped(s), s.lo, s.hi);
}
#define TFI_FAMILY TFI_FAMILY_EWA
#include "detail/instantiate.glsl"
#undef TFI_FAMILY

#endif
