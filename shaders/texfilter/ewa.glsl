// texfilter/ewa.glsl — elliptical weighted average (EWA): a Gaussian over the pixel's elliptical
// footprint, on two MIP levels blended by the fractional LOD. Correct zoomed in and zoomed out.
//
// Use:     vec4 tf_ewa(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso);
//          vec4 tf_ewa_hw(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha,
//                         float maxAniso); // the same weights from hardware bilinear taps on 2x2 blocks
// Options: s.wrap, s.lodBias, s.lodMin, s.lodMax as everywhere (common.glsl, lod.glsl).
//          alpha (2, as pbrt, is the usual choice): weight exp(-alpha r²), clamped to [0, 64]; NaN or
//            negative -> 0 (a flat disc). Smaller alpha = a wider Gaussian = blurrier.
//          maxAniso (e.g. 16): largest major/minor axis ratio; a thinner ellipse has its minor axis
//            grown to major/maxAniso (below 1 or NaN: 1). Larger = sharper at grazing angles, more reads.
//          TF_EWA_MAX_TEXELS: define before including (odd, >= 7; default 67): the loop cap K below.
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
//   centre x (relative to uv·w_l) has r² = xᵀM⁻¹x <= 1 weighs exp(-alpha r²) (computed with exp(),
//   no LUT); the sum is divided by the sum of the weights, which is >= exp(-alpha/2) > 0 since the
//   nearest texel has r² <= ½. The weight steps from exp(-alpha) to 0 at the ellipse's edge (the
//   truncated Gaussian of the spec; pbrt subtracts exp(-alpha) to make it continuous, we do not).
// Width: r = 1 is one pixel from the pixel's centre, so alpha = 2 is a Gaussian of sigma 0.5 px cut
//   at 1 px (0.41 px per axis after the cut): about one pixel wide. Against a box-pixel ideal it looks
//   blurrier than box-shaped filters; against a Gaussian-pixel ideal it is the best (DESIGN.md §4).
// Level rule: lambda = max(log2(minor), log2(major / ((K-3)/4))) + lodBias (semi-axes after the
//   eccentricity clamp, level-0 texels), clamped to [lodMin, lodMax] and the existing levels. On the
//   continuous level lambda the minor axis spans 2 texels (semi-axis 1, as pbrt); the two levels read,
//   floor(lambda) and floor(lambda)+1, see it span 2..4 and 1..2 texels and are blended by
//   frac(lambda), so there are no seams. The second term moves to a coarser level only when the major
//   semi-axis would pass (K-3)/4 = 16 texels, i.e. never for maxAniso <= 16 at the default K.
//   An isotropic footprint gets trilinear's lambda. lodBias -1: twice the texels across (4x the reads).
// Hard cap (every input; a shader never hangs): per level at most K rows of at most K texels
//   (tf_ewa_hw: K/2+1 rows of K/2+1 2x2 blocks). Where the LOD clamps (lodMax, lodBias) leave an
//   ellipse whose bounding box is wider than K texels, it is shrunk, same shape, to fit (so it then
//   aliases, like any LOD clamp). A 1x1 level is read once, whatever the ellipse.
//   Gradients: zero -> lodMin's level (0 by default) with M = I, a one-texel Gaussian around uv;
//   huge (1e30, 3e38) -> the coarsest level the clamps allow (normally the last, 1x1: the texture's
//   mean); NaN or ±Inf in any component -> that same level with M = I (normally: the mean).
//   Non-finite uv returns vec4(0).
// Hardware taps (tf_ewa_hw): the same weights, read through textureLod(tex, uv, level) on the sampler
//   bound with the texture, which must filter linearly with the same wrap mode. Texels are paired in
//   2x2 blocks anchored to even texel indices of the level (a fixed grid; one that followed the
//   ellipse's bounding box made blotches near the horizon); one bilinear lookup per block, at the
//   block's weight centroid, returns the block's weighted mean. Exact only where the four weights are
//   separable (w00·w11 = w10·w01): for the Gaussian that is inside an axis-aligned ellipse. Otherwise,
//   and where the edge cuts a block, a block is off by (w10·w01 - w00·w11)/W · (t00 - t10 - t01 + t11),
//   at most ¼ of the texture's mixed difference (none on t = f(x) + g(y)); the sampler also rounds the
//   tap position to its sub-texel precision (Vulkan allows 8 bits). Measured (alpha 2, 256² noise):
//   RMS 0.007, max 0.09 vs manual.
// Cost (measured, 256² noise, alpha 2, maxAniso 16): tf_ewa reads each texel inside the ellipse once
//   on each level: isotropic footprints ~15 texels (at most ~24), 16:1 footprints ~175 (at most ~300);
//   at most K² = 4489 per level whatever the input. tf_ewa_hw: one lookup per 2x2 block touching the
//   ellipse, ~0.4-0.5 of those reads (isotropic ~7, 16:1 ~66): the thin ellipses' edge blocks are half
//   empty. No early out for isotropic footprints: it is the same formula. Plane scene (docs/FILTERS.md):
//   tf_ewa 36.8 fetches on average (max 300), tf_ewa_hw 14.6 lookups (max 110).
#ifndef TF_EWA_MAX_TEXELS
#define TF_EWA_MAX_TEXELS 67
#endif

#ifndef TF_EWA_GLSL
#define TF_EWA_GLSL

#if TF_EWA_MAX_TEXELS < 7 || (TF_EWA_MAX_TEXELS % 2) == 0
#error "TF_EWA_MAX_TEXELS must be odd and at least 7"
#endif

#include "common.glsl"

// Widens the row/column spans a little so that the r² <= 1 test, not rounding in the span, decides.
const float TF_EWA_SPAN_MARGIN = 1.0 / 256.0;

// The ellipse of one lookup before any level: level-0 texel space, scaled by 1/m² (m = the largest
// |gradient component|, so that 1e30 gradients do not overflow).
struct tf_EwaShape {
    vec3 cov;     // (xx, xy, yy) of the clamped J·Jᵀ / m²
    float major2; // its eigenvalues / m², major2 >= minor2
    float minor2;
    float m;      // 0 for zero or non-finite gradients: then M = I on every level
};

// Shape and (biased, clamped) LOD of a lookup.
tf_EwaShape tf_ewa_shape(sampler2D tex, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float maxAniso, out float lambda)
{
    tf_EwaShape shape = tf_EwaShape(vec3(0.0), 0.0, 0.0, 0.0);
    float top = float(textureQueryLevels(tex) - 1);
    if (!tf_finite(dUVdx) || !tf_finite(dUVdy)) {
        lambda = 1e30; // the coarsest level the clamps allow
    } else {
        vec2 g = max(abs(dUVdx), abs(dUVdy));
        float m = max(g.x, g.y);
        if (!(m > 1e-30)) {
            lambda = -1e30; // zero footprint: the finest level allowed
        } else {
            vec2 size0 = vec2(textureSize(tex, 0));
            vec2 ax = dUVdx / m * size0, ay = dUVdy / m * size0; // columns of J/m, |entries| <= size
            float xx = ax.x * ax.x + ay.x * ay.x, xy = ax.x * ax.y + ay.x * ay.y, yy = ax.y * ax.y + ay.y * ay.y;
            float h = 0.5 * (xx - yy);
            float d = sqrt(h * h + xy * xy);
            float major2 = 0.5 * (xx + yy) + d; // >= 1: the largest |entry| of J/m is >= 1
            float cross = ax.x * ay.y - ax.y * ay.x;
            float minor2 = cross * cross / major2; // det / major2: no cancellation
            float e = maxAniso >= 1.0 ? maxAniso : 1.0;
            minor2 = max(minor2, major2 / (e * e));
            // Clamped covariance = minor2·I + (major2 - minor2)·e1e1ᵀ, e1e1ᵀ the projector on the major axis.
            vec3 p1 = d > 0.0 ? 0.5 * vec3(1.0 + h / d, xy / d, 1.0 - h / d) : vec3(0.5, 0.0, 0.5);
            shape = tf_EwaShape(vec3(minor2, 0.0, minor2) + max(major2 - minor2, 0.0) * p1, major2, minor2, m);
            const float majorTexels = 0.25 * float(TF_EWA_MAX_TEXELS - 3);
            lambda = log2(m) + max(0.5 * log2(max(minor2, 1e-30)), 0.5 * log2(major2) - log2(majorTexels)) +
                     s.lodBias;
        }
    }
    lambda = min(max(lambda, s.lodMin), s.lodMax);
    if (isnan(lambda))
        lambda = top;
    lambda = clamp(lambda, 0.0, top);
    return shape;
}

// The ellipse on one level: M = (xx, xy, yy) in level texels², its determinant (>= 1), and the centre
// uv·size split into an integer texel index `base` and `frac` in [0, 1), so that texel offsets from it
// are exact in float. For repeat/mirror, base is moved by a multiple of 2·size into [0, 2·size): both
// modes repeat every 2·size texels, and the parity that anchors tf_ewa_hw's 2x2 grid is kept.
void tf_ewa_level_ellipse(sampler2D tex, vec2 uv, int level, int wrapMode, tf_EwaShape shape, out vec3 M,
                          out float det, out vec2 base, out vec2 frac)
{
    vec2 size = vec2(tf_level_size(tex, level));
    vec2 sc = size / vec2(textureSize(tex, 0)); // 2^-level, except along an axis already at 1 texel
    vec3 D = vec3(sc.x * sc.x, sc.x * sc.y, sc.y * sc.y) * shape.cov;
    float k = 0.0;
    if (shape.m > 0.0) {
        // Hard cap: bounding box half-extents sqrt(M.xx), sqrt(M.yy) <= halfBox, so that a row or
        // column holds at most K texels. Shrinking is min(), so it is continuous in the footprint.
        const float halfBox = 0.5 * float(TF_EWA_MAX_TEXELS - 1) - 1.0 / 64.0;
        k = min(shape.m, sqrt((halfBox * halfBox - 1.0) / max(D.x, D.z)));
    }
    float k2 = k * k;
    M = k2 * D + vec3(1.0, 0.0, 1.0);
    // det = k⁴·det(D) + k²·trace(D) + 1, det(D) = sc.x²·sc.y²·major2·minor2: exact form, >= 1.
    det = k2 * k2 * (sc.x * sc.x * sc.y * sc.y) * shape.major2 * shape.minor2 + k2 * (D.x + D.z) + 1.0;
    vec2 c = clamp(uv * size, -TF_MAX_TEXEL_COORD, TF_MAX_TEXEL_COORD);
    base = floor(c);
    frac = c - base;
    if (wrapMode != TF_WRAP_CLAMP)
        base -= 2.0 * size * floor(base / (2.0 * size));
}

// r² = xᵀM⁻¹x for x = (dx, dy).
float tf_ewa_r2(vec3 M, float det, float dx, float dy)
{
    return (M.z * dx * dx - 2.0 * M.y * dx * dy + M.x * dy * dy) / det;
}

// Texel offsets [lo, hi] (from base) of the row at dy from the centre whose centres lie in the
// ellipse (lo > hi: none); fx = frac.x.
vec2 tf_ewa_row_span(vec3 M, float det, float fx, float dy)
{
    float disc = M.z - dy * dy;
    if (disc < 0.0)
        return vec2(1.0, 0.0);
    float xc = fx + M.y / M.z * dy, halfWidth = sqrt(det * disc) / M.z;
    return vec2(ceil(xc - halfWidth - 0.5 - TF_EWA_SPAN_MARGIN), floor(xc + halfWidth - 0.5 + TF_EWA_SPAN_MARGIN));
}

// Texel row offsets [lo, hi] (from base) that the ellipse can reach; fy = frac.y.
vec2 tf_ewa_rows(vec3 M, float fy)
{
    float hy = sqrt(M.z);
    return vec2(ceil(fy - hy - 0.5 - TF_EWA_SPAN_MARGIN), floor(fy + hy - 0.5 + TF_EWA_SPAN_MARGIN));
}

// The filter on one level: weighted average of every texel inside the ellipse (texelFetch).
vec4 tf_ewa_level(sampler2D tex, vec2 uv, int level, int wrapMode, tf_EwaShape shape, float alpha)
{
    vec3 M;
    float det;
    vec2 base, frac;
    tf_ewa_level_ellipse(tex, uv, level, wrapMode, shape, M, det, base, frac);
    ivec2 size = tf_level_size(tex, level);
    vec2 rowSpan = tf_ewa_rows(M, frac.y);
    int rows = int(clamp(rowSpan.y - rowSpan.x + 1.0, 0.0, float(TF_EWA_MAX_TEXELS)));
    vec4 sum = vec4(0.0);
    float weights = 0.0;
    for (int k = 0; k < TF_EWA_MAX_TEXELS; ++k) {
        if (k >= rows)
            break;
        float j = rowSpan.x + float(k), dy = j + 0.5 - frac.y;
        vec2 span = tf_ewa_row_span(M, det, frac.x, dy);
        int cols = int(clamp(span.y - span.x + 1.0, 0.0, float(TF_EWA_MAX_TEXELS)));
        int ty = tf_wrap(base.y + j, size.y, wrapMode);
        for (int n = 0; n < TF_EWA_MAX_TEXELS; ++n) {
            if (n >= cols)
                break;
            float i = span.x + float(n);
            float r2 = tf_ewa_r2(M, det, i + 0.5 - frac.x, dy);
            if (r2 <= 1.0) {
                float w = exp(-alpha * r2);
                TF_COUNT_FETCHES(1);
                sum += w * texelFetch(tex, ivec2(tf_wrap(base.x + i, size.x, wrapMode), ty), level);
                weights += w;
            }
        }
    }
    return weights > 0.0 ? sum / weights : vec4(0.0);
}

// The same filter from hardware bilinear lookups: one per 2x2 block of texels 2b, 2b+1 on each axis.
vec4 tf_ewa_level_hw(sampler2D tex, vec2 uv, int level, int wrapMode, tf_EwaShape shape, float alpha)
{
    const int maxBlocks = TF_EWA_MAX_TEXELS / 2 + 1; // K texels touch at most K/2+1 blocks
    vec3 M;
    float det;
    vec2 base, frac;
    tf_ewa_level_ellipse(tex, uv, level, wrapMode, shape, M, det, base, frac);
    vec2 size = vec2(tf_level_size(tex, level));
    vec2 parity = base - 2.0 * floor(0.5 * base); // blocks start at offsets o with base + o even
    vec2 rowSpan = tf_ewa_rows(M, frac.y);
    float firstRow = 2.0 * floor(0.5 * (rowSpan.x + parity.y)) - parity.y;
    int blockRows = int(clamp(floor(0.5 * (rowSpan.y - firstRow)) + 1.0, 0.0, float(maxBlocks)));
    vec4 sum = vec4(0.0);
    float weights = 0.0;
    for (int k = 0; k < maxBlocks; ++k) {
        if (k >= blockRows)
            break;
        float j0 = firstRow + 2.0 * float(k);
        float dy0 = j0 + 0.5 - frac.y, dy1 = dy0 + 1.0;
        vec2 span0 = tf_ewa_row_span(M, det, frac.x, dy0), span1 = tf_ewa_row_span(M, det, frac.x, dy1);
        float lo = min(span0.x <= span0.y ? span0.x : 1e30, span1.x <= span1.y ? span1.x : 1e30);
        float hi = max(span0.x <= span0.y ? span0.y : -1e30, span1.x <= span1.y ? span1.y : -1e30);
        if (lo > hi)
            continue;
        float firstCol = 2.0 * floor(0.5 * (lo + parity.x)) - parity.x;
        int cols = int(clamp(floor(0.5 * (hi - firstCol)) + 1.0, 0.0, float(maxBlocks)));
        for (int n = 0; n < maxBlocks; ++n) {
            if (n >= cols)
                break;
            float i0 = firstCol + 2.0 * float(n);
            float dx0 = i0 + 0.5 - frac.x, dx1 = dx0 + 1.0;
            vec4 r2 = vec4(tf_ewa_r2(M, det, dx0, dy0), tf_ewa_r2(M, det, dx1, dy0), tf_ewa_r2(M, det, dx0, dy1),
                           tf_ewa_r2(M, det, dx1, dy1));
            vec4 w = mix(vec4(0.0), exp(-alpha * r2), lessThanEqual(r2, vec4(1.0))); // w00, w10, w01, w11
            float total = w.x + w.y + w.z + w.w;
            if (total > 0.0) {
                // Bilinear weights (1-a)(1-b), a(1-b), (1-a)b, ab reproduce w/total when separable:
                // texel coordinate 2b + ½ + a puts the lookup's first texel at 2b with fraction a.
                vec2 ab = vec2(w.y + w.w, w.z + w.w) / total;
                TF_COUNT_HW_LOOKUPS(1);
                sum += total * textureLod(tex, (base + vec2(i0, j0) + 0.5 + ab) / size, float(level));
                weights += total;
            }
        }
    }
    return weights > 0.0 ? sum / weights : vec4(0.0);
}

// One level: a 1x1 level is its texel whatever the ellipse (saves up to K² reads of it at the horizon).
vec4 tf_ewa_on_level(sampler2D tex, vec2 uv, int level, int wrapMode, tf_EwaShape shape, float alpha, bool hardware)
{
    if (tf_level_size(tex, level) == ivec2(1)) {
        TF_COUNT_FETCHES(1);
        return texelFetch(tex, ivec2(0), level);
    }
    return hardware ? tf_ewa_level_hw(tex, uv, level, wrapMode, shape, alpha)
                    : tf_ewa_level(tex, uv, level, wrapMode, shape, alpha);
}

vec4 tf_ewa_impl(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso,
                 bool hardware)
{
    if (!tf_finite(uv))
        return vec4(0.0);
    float a = alpha >= 0.0 ? min(alpha, 64.0) : 0.0;
    float lambda;
    tf_EwaShape shape = tf_ewa_shape(tex, dUVdx, dUVdy, s, maxAniso, lambda);
    int lo = int(floor(lambda));
    float f = lambda - float(lo);
    vec4 fine = tf_ewa_on_level(tex, uv, lo, s.wrap, shape, a, hardware);
    if (f == 0.0)
        return fine; // on a level, or clamped to the last one: the second level would weigh 0
    return mix(fine, tf_ewa_on_level(tex, uv, lo + 1, s.wrap, shape, a, hardware), f);
}

vec4 tf_ewa(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso)
{
    return tf_ewa_impl(tex, uv, dUVdx, dUVdy, s, alpha, maxAniso, false);
}

vec4 tf_ewa_hw(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso)
{
    return tf_ewa_impl(tex, uv, dUVdx, dUVdy, s, alpha, maxAniso, true);
}

#endif
