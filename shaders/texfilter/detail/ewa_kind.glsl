// texfilter/detail/ewa_kind.glsl — internal: ewa.glsl's functions for one resource kind. detail/instantiate.glsl
// includes it once per kind (no include guard on purpose), with detail/access.glsl's macros for that kind.
#if !defined(TFI_KIND)
#error "texfilter/detail/ewa_kind.glsl is internal: include texfilter/ewa.glsl"
#endif
#if TFI_OWNS_T
// Shape and (biased, clamped) LOD of a lookup.
tfi_EwaShape tfi_ewa_shape(TFI_T, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float maxAniso, out float lambda)
{
    tfi_EwaShape shape = tfi_EwaShape(vec3(0.0), 0.0, 0.0, 0.0);
    vec2 size0 = vec2(TFI_SIZE0);
    // NaN/±Inf, or a footprint entry (gradient · size) past float range: non-finite, as in every family.
    if (!tf_finite(dUVdx * size0) || !tf_finite(dUVdy * size0)) {
        lambda = 1e30; // the coarsest level the clamps allow
    } else {
        vec2 g = max(abs(dUVdx), abs(dUVdy));
        float m = max(g.x, g.y);
        if (!(m > 1e-30)) {
            lambda = -1e30; // zero footprint: the finest level allowed
        } else {
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
            shape = tfi_EwaShape(vec3(minor2, 0.0, minor2) + max(major2 - minor2, 0.0) * p1, major2, minor2, m);
            // The minor semi-axis spans √2 texels of level λ (see the header), unless the support's major
            // semi-axis would then exceed the loop cap.
            const float majorTexels = 0.25 * float(TF_EWA_MAX_TEXELS - 3) / sqrt(TF_EWA_SUPPORT);
            lambda = tfi_log2(m) +
                     max(0.5 * log2(max(minor2, 1e-30)) - 0.5, 0.5 * log2(major2) - log2(majorTexels)) + s.lodBias;
        }
    }
    lambda = tfi_clamp_lod(lambda, s, TFI_A);
    return shape;
}

// The magnification filter's spread (tfi_ewa_magnified): its four points are uv ± a and uv ± b, a and b
// k·(dUVdx ± dUVdy) with k² the weight's variance, so that their covariance k²·J·Jᵀ is the ellipse's own.
// None unless (|dUVdx| + |dUVdy|)·size is finite: NaN, ±Inf or a footprint past float range (that bounds
// |a| and |b| too; one test, where four cost 75 SPIR-V instructions).
void tfi_ewa_spread(TFI_T, vec2 dUVdx, vec2 dUVdy, float alpha, out vec2 a, out vec2 b)
{
    a = dUVdx + dUVdy;
    b = dUVdx - dUVdy;
    if (!tf_finite((abs(dUVdx) + abs(dUVdy)) * vec2(TFI_SIZE0)))
        a = b = vec2(0.0);
    float k = sqrt(tfi_ewa_weight_variance(alpha));
    a *= k;
    b *= k;
}

// The support ellipse on one level: R²·M = R²·(xx, xy, yy) in level texels², its determinant, and the
// centre uv·size split into an integer texel index `base` and `frac` in [0, 1), so that texel offsets
// from it are exact in float. For repeat/mirror, base is moved by a multiple of 2·size into
// [0, 2·size): both modes repeat every 2·size texels, and the parity that anchors tf_ewa_hw's 2x2 grid
// is kept. uv has been through tf_reduce_uv.
void tfi_ewa_level_ellipse(TFI_T, vec2 uv, int level, int wrapMode, tfi_EwaShape shape, float alpha, out vec3 M,
                          out float det, out vec2 base, out vec2 frac)
{
    vec2 size = vec2(tf_level_size(TFI_A, level));
    vec2 sc = size / vec2(TFI_SIZE0); // 2^-level, except along an axis already at 1 texel
    vec3 D = vec3(sc.x * sc.x, sc.x * sc.y, sc.y * sc.y) * shape.cov;
    float k = 0.0;
    if (shape.m > 0.0) {
        // Hard cap: the support's bounding box half-extents sqrt(R²·M.xx), sqrt(R²·M.yy) <= halfBox, so
        // that a row or column holds at most K texels. Shrinking is min(), so it is continuous in the footprint.
        const float halfBox = 0.5 * float(TF_EWA_MAX_TEXELS - 1) - 1.0 / 64.0;
        k = min(shape.m, sqrt((halfBox * halfBox / TF_EWA_SUPPORT - 1.0) / max(D.x, D.z)));
    }
    float k2 = k * k;
    // The level's reconstruction recon·I (header, Math: c): the truth's bilinear tent on level 0 less the box
    // this level already averages, in units of the weight's variance; at least what lifts M's smaller
    // eigenvalue to TFI_EWA_SMALLEST (k²·D's is k²·det(D)/its larger one), at most 1 (the loop cap above
    // assumes 1).
    float detD = (sc.x * sc.x * sc.y * sc.y) * shape.major2 * shape.minor2;
    float majorD = 0.5 * (D.x + D.z) + length(vec2(0.5 * (D.x - D.z), D.y));
    float minorD = majorD > 0.0 ? k2 * detD / majorD : 0.0;
    float recon = min(
        max((3.0 * sc.x * sc.y - 1.0) / (12.0 * tfi_ewa_weight_variance(alpha)), TFI_EWA_SMALLEST - minorD), 1.0);
    M = TF_EWA_SUPPORT * (k2 * D + vec3(recon, 0.0, recon));
    // det(M_unscaled) = k⁴·det(D) + recon·k²·trace(D) + recon²: exact form, >= 1 (both eigenvalues are).
    det = TF_EWA_SUPPORT * TF_EWA_SUPPORT * (k2 * k2 * detD + recon * k2 * (D.x + D.z) + recon * recon);
    vec2 c = clamp(uv * size, -TF_MAX_TEXEL_COORD, TF_MAX_TEXEL_COORD);
    base = floor(c);
    frac = c - base;
    if (wrapMode != TF_WRAP_CLAMP)
        base -= 2.0 * size * floor(base / (2.0 * size));
}
#endif

// The filter on one level: every texel inside the support (texelFetch), fitted (tfi_ewa_fit).
vec4 tfi_ewa_level(TFI_T, vec2 uv TFI_X, int level, int wrapMode, tfi_EwaShape shape, float alpha)
{
    vec3 M;
    float det;
    vec2 base, frac;
    tfi_ewa_level_ellipse(TFI_A, uv, level, wrapMode, shape, alpha, M, det, base, frac);
    ivec2 size = tf_level_size(TFI_A, level);
    vec2 rowSpan = tfi_ewa_rows(M, frac.y);
    int rows = int(clamp(rowSpan.y - rowSpan.x + 1.0, 0.0, float(TF_EWA_MAX_TEXELS)));
    // Moments in whitened coordinates y = R·d, RᵀR = (R²M)⁻¹ (Cholesky, R upper triangular): the support
    // is the unit disc there, so the fit's 2x2 system is well conditioned however thin the ellipse (the
    // fit's value does not depend on the coordinates).
    float r11 = sqrt(M.z / det), r12 = -M.y / (det * r11), r22 = inversesqrt(M.z);
    tfi_EwaMoments s = tfi_EwaMoments(0.0, vec2(0.0), vec3(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0),
                                    vec4(0.0));
    for (int k = 0; k < TF_EWA_MAX_TEXELS; ++k) {
        if (k >= rows)
            break;
        float j = rowSpan.x + float(k), dy = j + 0.5 - frac.y, yy = r22 * dy, cx = r12 * dy;
        vec2 span = tfi_ewa_row_span(M, det, frac.x, dy);
        int cols = int(clamp(span.y - span.x + 1.0, 0.0, float(TF_EWA_MAX_TEXELS)));
        int ty = TFI_WRAP(base.y + j, size.y, wrapMode);
        // One row: y.y is constant, so its sums need only the y.x moments.
        float rw = 0.0, rwx = 0.0, rwxx = 0.0;
        vec4 rt = vec4(0.0), rtx = vec4(0.0);
        for (int n = 0; n < TF_EWA_MAX_TEXELS; ++n) {
            if (n >= cols)
                break;
            float i = span.x + float(n), dx = i + 0.5 - frac.x;
            float r2 = tfi_ewa_r2(M, det, dx, dy);
            if (r2 < 1.0) {
                float w = tfi_ewa_weight(r2, alpha), yx = r11 * dx + cx, wx = w * yx;
                TF_COUNT_FETCHES(1);
                vec4 t = TFI_FETCH(ivec2(TFI_WRAP(base.x + i, size.x, wrapMode), ty), level);
                if (s.w + rw == 0.0) {
                    s.pivot = t; // the first texel (an earlier one of weight 0 added nothing)
                    s.lo = t;
                    s.hi = t;
                }
                s.lo = min(s.lo, t);
                s.hi = max(s.hi, t);
                t -= s.pivot;
                rw += w;
                rwx += wx;
                rwxx += wx * yx;
                rt += w * t;
                rtx += wx * t;
            }
        }
        s.w += rw;
        s.wd += vec2(rwx, yy * rw);
        s.wdd += vec3(rwxx, yy * rwx, yy * yy * rw);
        s.t += rt;
        s.tx += rtx;
        s.ty += yy * rt;
    }
    return tfi_ewa_fit(s);
}

// The hardware-tap walk over one level's support, written once for tf_ewa_hw and tf_ewa_stochastic_hw: 2x2 blocks
// of texels 2b, 2b+1 on each axis, each tapped by one bilinear lookup at its weight centroid with the block's
// total weight. Pass 0 sums the weights and their moments: the taps' weighted mean sits on the texels' weight
// centroid, not on uv, so pass 1 moves every tap by that offset (then the mean is exact on a linear texture).
// Pass 1 taps every block (pick < 0: the weighted mean, tf_ewa_hw) or, for pick in [0, 1), only the block at
// which the weights' running sum passes pick·Σ (one tap, a block with probability its weight / Σ).
vec4 tfi_ewa_blocks_hw(TFI_T, vec2 uv TFI_X, int level, int wrapMode, tfi_EwaShape shape, float alpha, float pick)
{
    vec3 M;
    float det;
    vec2 base, frac;
    tfi_ewa_level_ellipse(TFI_A, uv, level, wrapMode, shape, alpha, M, det, base, frac);
    vec2 size = vec2(tf_level_size(TFI_A, level));
    tfi_EwaBlocks blocks = tfi_ewa_blocks(M, base, frac);
    bool picking = pick >= 0.0; // a constant at each call
    vec4 sum = vec4(0.0);
    float weights = 0.0, target = 0.0, below = 0.0;
    vec2 moment = vec2(0.0), shift = vec2(0.0), tap = base + 0.5; // tap: the picked block's centroid, texels
    for (int pass = 0; pass < 2; ++pass) {
        bool found = false;
        for (int k = 0; k < TFI_EWA_MAX_BLOCKS; ++k) {
            if (k >= blocks.rows || found)
                break;
            float j0 = blocks.firstRow + 2.0 * float(k);
            float dy0 = j0 + 0.5 - frac.y;
            float firstCol;
            int cols = tfi_ewa_block_columns(M, det, frac, blocks.parity.x, dy0, firstCol);
            for (int n = 0; n < TFI_EWA_MAX_BLOCKS; ++n) {
                if (n >= cols)
                    break;
                float i0 = firstCol + 2.0 * float(n);
                float dx0 = i0 + 0.5 - frac.x;
                vec2 ab;
                vec4 w;
                float total = tfi_ewa_block(M, det, alpha, dx0, dy0, ab, w);
                if (!(total > 0.0))
                    continue;
                if (pass == 0) {
                    moment += total * (vec2(dx0, dy0) + ab);
                    weights += total;
                } else if (picking) {
                    tap = base + vec2(i0, j0) + 0.5 + ab;
                    if (target < below + total) {
                        found = true;
                        break;
                    }
                    below += total;
                } else {
                    // One tap at the block's weight centroid; a twisted block two, each one texel pair (b or a
                    // exactly 0: its two weights exact), the pairs along the ellipse's longer extent, where fewer
                    // are cut by its edge. One lookup in the code either way (tools/spirv_size.sh).
                    bool twisted = tfi_ewa_block_twisted(w, total, weights), columns = M.z > M.x;
                    for (int t = 0; t < (twisted ? 2 : 1); ++t) {
                        vec2 pair = columns ? (t == 0 ? w.xz : w.yw) : (t == 0 ? w.xy : w.zw);
                        float tapWeight = twisted ? pair.x + pair.y : total;
                        vec2 at = !twisted ? ab : columns ? vec2(float(t), pair.y / tapWeight)
                                                          : vec2(pair.y / tapWeight, float(t));
                        if (tapWeight > 0.0) {
                            TF_COUNT_HW_LOOKUPS(1);
                            sum += tapWeight * TFI_LOOKUP((base + vec2(i0, j0) + 0.5 + at - shift) / size, float(level));
                        }
                    }
                }
            }
        }
        if (pass == 0 && !picking && !(weights > 0.0))
            return vec4(0.0);
        shift = weights > 0.0 ? moment / weights : vec2(0.0); // the taps' weighted centroid − the centre, texels
        target = pick * weights;
    }
    if (!picking)
        return sum / weights;
    TF_COUNT_HW_LOOKUPS(1);
    return TFI_LOOKUP((tap - shift) / size, float(level));
}

// One level: a 1x1 level is its texel whatever the ellipse (saves up to K² reads of it at the horizon).
vec4 tfi_ewa_on_level(TFI_T, vec2 uv TFI_X, int level, int wrapMode, tfi_EwaShape shape, float alpha, bool hardware)
{
    vec4 color; // one return (common.glsl): TFI_CAN_FETCH and `hardware` are constants
    if (tf_level_size(TFI_A, level) == ivec2(1)) {
        if (!TFI_CAN_FETCH) { // a shadow sampler: its one texel through the sampler (exact at the centre)
            TF_COUNT_HW_LOOKUPS(1);
            color = TFI_LOOKUP(vec2(0.5), float(level));
        } else {
            TF_COUNT_FETCHES(1);
            color = TFI_FETCH(ivec2(0), level);
        }
    } else {
        color = hardware ? tfi_ewa_blocks_hw(TFI_A, uv TFI_XA, level, wrapMode, shape, alpha, -1.0)
                         : tfi_ewa_level(TFI_A, uv TFI_XA, level, wrapMode, shape, alpha);
    }
    return color;
}

// The magnification filter (bilinear or TF_MAGNIFY's cubic) integrated over the pixel's footprint: the mean of
// four of its lookups at uv ± a, uv ± b (tfi_ewa_spread), whose spread is the ellipse's own covariance. Plain
// magnification as the footprint vanishes; the pixel's blur where it spans about a texel (one lookup aliases there).
vec4 tfi_ewa_magnified(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, int wrapMode, float alpha, bool hardware)
{
    vec2 a, b;
    tfi_ewa_spread(TFI_A, dUVdx, dUVdy, alpha, a, b);
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 4; ++i) // a loop, not 4 calls: the filter's code once (tools/spirv_size.sh)
        sum += tfi_magnified_level0(TFI_A, uv + (i < 2 ? a : b) * ((i & 1) == 0 ? 1.0 : -1.0) TFI_XA, wrapMode,
                                    hardware);
    return 0.25 * sum;
}

// tf_ewa and tf_ewa_hw: level 0's trilinear share goes to the magnification filter, the rest to the ellipse on
// two levels blended by frac(λ).
vec4 tfi_ewa_impl(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso,
                 bool hardware)
{
    if (!tf_finite(uv))
        return vec4(0.0);
    uv = tf_reduce_uv(uv, s.wrap);
    float a = alpha >= 0.0 ? min(alpha, 64.0) : 0.0;
    // Magnification: level 0's share in trilinear (1 − λ, λ trilinear's LOD) is the magnification filter's
    // (TF_MAGNIFY: bilinear, Vulkan's LINEAR magFilter, unless a cubic is asked for) instead of the ellipse.
    float magnifyShare = 1.0 - clamp(tf_lod(TFI_A, dUVdx, dUVdy, s), 0.0, 1.0);
    vec4 magnified = magnifyShare > 0.0 ? tfi_ewa_magnified(TFI_A, uv TFI_XA, dUVdx, dUVdy, s.wrap, a, hardware)
                                        : vec4(0.0);
    if (magnifyShare == 1.0)
        return magnified;
    float lambda;
    tfi_EwaShape shape = tfi_ewa_shape(TFI_A, dUVdx, dUVdy, s, maxAniso, lambda);
    float f;
    int lo = tfi_split_lod(lambda, f);
#define TFI_EWA_LEVEL(level) tfi_ewa_on_level(TFI_A, uv TFI_XA, level, s.wrap, shape, a, hardware)
    vec4 ewa;
    TFI_BLEND_LEVELS_ONCE(ewa, TFI_EWA_LEVEL, lo, f); // each level's support walked once (lod.glsl)
#undef TFI_EWA_LEVEL
    return magnifyShare > 0.0 ? mix(ewa, magnified, magnifyShare) : ewa;
}

#if TFI_MANUAL
vec4 tf_ewa(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso)
{
    return tfi_ewa_impl(TFI_A, uv TFI_XA, dUVdx, dUVdy, s, alpha, maxAniso, false);
}
#endif

#if TFI_HW
vec4 tf_ewa_hw(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso)
{
    return tfi_ewa_impl(TFI_A, uv TFI_XA, dUVdx, dUVdy, s, alpha, maxAniso, true);
}
#endif
