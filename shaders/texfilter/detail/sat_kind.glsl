// texfilter/detail/sat_kind.glsl — internal: sat.glsl's functions for one resource kind. detail/instantiate.glsl
// includes it once per kind (no include guard on purpose), with detail/access.glsl's macros for that kind.
#if !defined(TFI_KIND)
#error "texfilter/detail/sat_kind.glsl is internal: include texfilter/sat.glsl"
#endif
#if TFI_SAT

tfi_SatInt tfi_sat_entry(TFI_SAT_T, ivec2 t TFI_SAT_X)
{
    TF_COUNT_FETCHES(2);
    uint h = TFI_SAT_HIGH(t).r;
    return tfi_SatInt(TFI_SAT_LOW(t), uvec4(h, h >> 8, h >> 16, h >> 24) & 0xFFu);
}

// Mean over the box [lo, hi) in texel units (corners within a few texture sizes of it), in the units of the
// texture. The 16 corners' extended entries E(x, y) = ax·ay·S(rx, ry) + ax·by·S(rx, n) + bx·ay·S(n, ry) +
// bx·by·S(n, n) are summed one kind of term a turn, 16 table entries each: the S(rx, ry) turn always, a turn for
// the terms with by (the box crosses a horizontal border), one with bx, and the S(n, n) turn when it crosses
// both. A loop because SIMD devices run every side of an `if` (lavapipe read all 64 entries of every box) but
// leave a loop once no lane needs another turn: a batch of boxes inside the texture reads 16 entries. Sums
// modulo 2^40 do not depend on their order, so every block sum, and the result, is what it was, bit for bit.
vec4 tfi_sat_box(TFI_SAT_T, vec2 lo, vec2 hi TFI_SAT_X, ivec2 size, int wrapMode, vec4 offset, vec4 scale)
{
    ivec4 px, py;
    vec3 wx, wy;
    tfi_sat_edges(lo.x, hi.x, px, wx);
    tfi_sat_edges(lo.y, hi.y, py, wy);
    tfi_SatAxis ax[4], ay[4];
    bool crossesX = false, crossesY = false; // some corner outside [0, n] on that axis: b != 0 somewhere
    for (int k = 0; k < 4; ++k) {
        ax[k] = tfi_sat_axis(px[k], size.x, wrapMode);
        ay[k] = tfi_sat_axis(py[k], size.y, wrapMode);
        crossesX = crossesX || ax[k].b != 0;
        crossesY = crossesY || ay[k].b != 0;
    }
    int turns = 1 + (crossesX ? 1 : 0) + (crossesY ? 1 : 0) + (crossesX && crossesY ? 1 : 0);
    const tfi_SatInt zero = tfi_SatInt(uvec4(0u), uvec4(0u)); // initialisers: every entry is written before it is read,
    tfi_SatInt e[16] = tfi_SatInt[16](zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero,
                                      zero, zero, zero); // which Slang cannot see. E at corner (px[k], py[l]): e[4l + k]
    int turn = 0;
    do {
        // The turn's term: 0 S(rx, ry), 1 S(rx, n) (by), 2 S(n, ry) (bx), 3 S(n, n); a box crossing one axis only
        // takes that axis's term on its second turn.
        int term = turn == 0 ? 0 : turn == 3 ? 3 : crossesY ? turn : 2;
        bool fullX = term >= 2, fullY = term == 1 || term == 3;
        for (int s = 0; s < 16; ++s) {
            tfi_SatAxis x = ax[s & 3], y = ay[s >> 2];
            int k = (fullX ? x.b : x.a) * (fullY ? y.b : y.a);
            tfi_SatInt t = tfi_sat_entry(TFI_SAT_A, ivec2(fullX ? size.x : x.r, fullY ? size.y : y.r) TFI_SAT_XA);
            t = tfi_sat_mul(t, k);
            e[s] = turn == 0 ? t : tfi_sat_add(e[s], t);
        }
    } while (++turn < turns);
    vec4 sum = vec4(0.0);
    tfi_SatInt previous[3] = tfi_SatInt[3](zero, zero, zero); // x differences E(px[k+1], y) − E(px[k], y) of the previous corner row
    // Unrolled (common.glsl TFI_UNROLL): e[] and previous[] then live in registers. Rolled, lavapipe indexed them
    // through memory a lane at a time, a third of tf_sat's time (docs/BENCHMARKS.md); +270 SPIR-V instructions.
    TFI_UNROLL for (int l = 0; l < 4; ++l) {
        TFI_UNROLL for (int k = 0; k < 3; ++k) {
            tfi_SatInt d = tfi_sat_sub(e[4 * l + k + 1], e[4 * l + k]);
            if (l > 0) // block [px[k], px[k+1]) x [py[l-1], py[l]): exact, then weighted in float
                sum += (wx[k] * wy[l - 1]) * tfi_sat_to_float(tfi_sat_sub(d, previous[k]));
            previous[k] = d;
        }
    }
    return offset + sum * (scale / 65535.0);
}

// Mean over the box of half-extents h (texel units) centred on uv.
vec4 tfi_sat_centred(TFI_SAT_T, vec2 uv TFI_SAT_X, vec2 h, ivec2 size, int wrapMode, vec4 offset, vec4 scale)
{
    vec2 n = vec2(size);
    h = min(h, 0.5 * n); // at most W x H texels: the bit budget
    // Clamp: from −1 or 2 outward a box of at most the texture's size sees only edge texels.
    uv = wrapMode == TF_WRAP_CLAMP ? clamp(uv, -1.0, 2.0) : tfi_sat_period(uv, wrapMode);
    vec2 c = uv * n;
    return tfi_sat_box(TFI_SAT_A, c - h, c + h TFI_SAT_XA, size, wrapMode, offset, scale);
}

vec4 tf_sat(TFI_SAT_T, vec2 uv TFI_SAT_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec4 offset, vec4 scale)
{
    ivec2 size = TFI_SAT_SIZE - 1;
    if (!tf_finite(uv) || any(lessThan(size, ivec2(1)))) // no table bound: nothing to average
        return vec4(0.0);
    vec2 jx, jy;
    if (!tfi_sat_columns(size, dUVdx, dUVdy, s.lodBias, jx, jy))
        return tfi_sat_box(TFI_SAT_A, vec2(0.0), vec2(size) TFI_SAT_XA, size, s.wrap, offset, scale);
    return tfi_sat_centred(TFI_SAT_A, uv TFI_SAT_XA, 0.5 * (abs(jx) + abs(jy)), size, s.wrap, offset, scale);
}

vec4 tf_sat_assembly(TFI_SAT_T, vec2 uv TFI_SAT_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec4 offset, vec4 scale,
                     int boxes)
{
    ivec2 size = TFI_SAT_SIZE - 1;
    if (!tf_finite(uv) || any(lessThan(size, ivec2(1)))) // no table bound: nothing to average
        return vec4(0.0);
    vec2 jx, jy;
    if (!tfi_sat_columns(size, dUVdx, dUVdy, s.lodBias, jx, jy))
        return tfi_sat_box(TFI_SAT_A, vec2(0.0), vec2(size) TFI_SAT_XA, size, s.wrap, offset, scale);
    int k = clamp(boxes, 1, 16);
    float n = float(k);
    bool xMajor = dot(jx, jx) >= dot(jy, jy);
    vec2 major = xMajor ? jx : jy;
    vec2 minor = xMajor ? jy : jx;
    vec2 h = 0.5 * (abs(major) / n + abs(minor)); // every slice's bounding box
    uv = tfi_sat_period(uv, s.wrap); // before adding offsets: keeps float precision in the slice centres
    vec4 sum = vec4(0.0);
    for (int i = 0; i < k; ++i) {
        float a = (float(i) + 0.5) / n - 0.5; // slice centre along the major column, in (−½, ½)
        sum += tfi_sat_centred(TFI_SAT_A, uv + major * a / vec2(size) TFI_SAT_XA, h, size, s.wrap, offset, scale);
    }
    return sum / n;
}

#endif
