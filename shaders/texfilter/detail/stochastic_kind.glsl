// texfilter/detail/stochastic_kind.glsl — internal: stochastic.glsl's functions for one resource kind. detail/instantiate.glsl
// includes it once per kind (no include guard on purpose), with detail/access.glsl's macros for that kind.
#if !defined(TFI_KIND)
#error "texfilter/detail/stochastic_kind.glsl is internal: include texfilter/stochastic.glsl"
#endif

#if TFI_CAN_FETCH
vec4 tf_bilinear_stochastic_level(TFI_T, vec2 uv TFI_X, int level, int wrapMode, vec3 xi)
{
    if (!tf_finite(uv))
        return vec4(0.0);
    xi = tfi_unit3(xi);
    ivec2 size = tf_level_size(TFI_A, level);
    vec2 x = clamp(tf_reduce_uv(uv, wrapMode) * vec2(size) - 0.5, -TF_MAX_TEXEL_COORD, TF_MAX_TEXEL_COORD);
    vec2 i0 = floor(x);
    vec2 i = i0 + mix(vec2(0.0), vec2(1.0), lessThan(xi.xy, x - i0)); // i0 + 1 with probability frac(x)
    TF_COUNT_FETCHES(1);
    return TFI_FETCH(ivec2(TFI_WRAP(i.x, size.x, wrapMode), TFI_WRAP(i.y, size.y, wrapMode)), level);
}

// One trilinear probe at a clamped lod: its level chosen by xi.z, then one texel.
vec4 tfi_trilinear_stochastic_at(TFI_T, vec2 uv TFI_X, float lod, int wrapMode, vec3 xi)
{
    float rest;
    int level = tfi_stochastic_level(lod, xi.z, rest);
    return tf_bilinear_stochastic_level(TFI_A, uv TFI_XA, level, wrapMode, xi);
}

// ewa: one texel of `level`'s support, with probability weight / total (the CDF walked with u in [0, 1)).
vec4 tfi_ewa_stochastic_level(TFI_T, vec2 uv TFI_X, int level, int wrapMode, tfi_EwaShape shape, float alpha, float u)
{
    ivec2 size = tf_level_size(TFI_A, level);
    if (size == ivec2(1)) {
        TF_COUNT_FETCHES(1);
        return TFI_FETCH(ivec2(0), level);
    }
    vec3 M;
    float det;
    vec2 base, frac;
    tfi_ewa_level_ellipse(TFI_A, uv, level, wrapMode, shape, alpha, M, det, base, frac);
    vec2 rowSpan = tfi_ewa_rows(M, frac.y);
    int rows = int(clamp(rowSpan.y - rowSpan.x + 1.0, 0.0, float(TF_EWA_MAX_TEXELS)));
    float total = 0.0, target = 0.0, below = 0.0;
    vec2 chosen = vec2(0.0); // offsets from base: the centre's own texel unless a weight is found
    for (int pass = 0; pass < 2; ++pass) {
        bool found = false;
        for (int k = 0; k < TF_EWA_MAX_TEXELS; ++k) {
            if (k >= rows || found)
                break;
            float j = rowSpan.x + float(k), dy = j + 0.5 - frac.y;
            vec2 span = tfi_ewa_row_span(M, det, frac.x, dy);
            int cols = int(clamp(span.y - span.x + 1.0, 0.0, float(TF_EWA_MAX_TEXELS)));
            for (int n = 0; n < TF_EWA_MAX_TEXELS; ++n) {
                if (n >= cols)
                    break;
                float i = span.x + float(n), r2 = tfi_ewa_r2(M, det, i + 0.5 - frac.x, dy);
                float w = r2 < 1.0 ? tfi_ewa_weight(r2, alpha) : 0.0;
                if (pass == 0) {
                    total += w;
                } else if (w > 0.0) {
                    chosen = vec2(i, j); // the last texel of positive weight, should rounding end the walk early
                    if (target < below + w) {
                        found = true;
                        break;
                    }
                    below += w;
                }
            }
        }
        target = u * total;
    }
    TF_COUNT_FETCHES(1);
    return TFI_FETCH(ivec2(TFI_WRAP(base.x + chosen.x, size.x, wrapMode), TFI_WRAP(base.y + chosen.y, size.y, wrapMode)),
                     level);
}
#endif

#if TFI_HW
// ewa_hw: one 2x2 block of `level` with probability (its weight) / total, one bilinear tap at its weight centroid
// less the taps' common centroid offset: tf_ewa_hw's walk (tfi_ewa_blocks_hw) picking one block with u.
vec4 tfi_ewa_stochastic_level_hw(TFI_T, vec2 uv TFI_X, int level, int wrapMode, tfi_EwaShape shape, float alpha, float u)
{
    if (tf_level_size(TFI_A, level) == ivec2(1)) {
        TF_COUNT_HW_LOOKUPS(1);
        return TFI_LOOKUP(vec2(0.5), float(level));
    }
    return tfi_ewa_blocks_hw(TFI_A, uv TFI_XA, level, wrapMode, shape, alpha, u);
}
#endif

// The families' shared body: `hardware` picks the tap form (a constant at every call: folded away).
vec4 tfi_trilinear_stochastic_impl(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi, bool hardware)
{
    if (!tf_finite(uv))
        return vec4(0.0);
    xi = tfi_unit3(xi);
    float lod = tf_lod(TFI_A, dUVdx, dUVdy, s);
    vec4 color = vec4(0.0); // one return from here on (common.glsl); a shadow sampler has only the _hw forms
#if TFI_HW
    if (hardware) {
        float rest;
        int level = tfi_stochastic_level(lod, xi.z, rest);
        TF_COUNT_HW_LOOKUPS(1);
        color = TFI_LOOKUP(tf_reduce_uv(uv, s.wrap), float(level));
    }
#endif
#if TFI_CAN_FETCH
    if (!hardware)
        color = tfi_trilinear_stochastic_at(TFI_A, uv TFI_XA, lod, s.wrap, xi);
#endif
    return color;
}

vec4 tfi_aniso_stochastic_impl(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape,
                               vec3 xi, bool hardware)
{
    if (!tf_finite(uv))
        return vec4(0.0);
    xi = tfi_unit3(xi);
    tfi_AnisoFootprint fp = tfi_aniso_footprint(TFI_A, dUVdx, dUVdy, s, maxProbes, shape);
    uv = tfi_aniso_centre(uv, fp.axis, s.wrap); // as tf_aniso (aniso.glsl)
    vec2 p = uv;
    if (fp.probes > 1) {
        float rest;
        p = uv + tfi_stochastic_probe(fp.probes, shape, xi.z, rest) * fp.axis;
        xi.z = rest;
    }
    vec4 color = vec4(0.0); // one return from here on (common.glsl)
#if TFI_HW
    if (hardware) {
        TF_COUNT_HW_LOOKUPS(1);
        color = TFI_LOOKUP(tf_reduce_uv(p, s.wrap), fp.lod); // the probe's hardware trilinear tap
    }
#endif
#if TFI_CAN_FETCH
    if (!hardware)
        color = tfi_trilinear_stochastic_at(TFI_A, p TFI_XA, fp.lod, s.wrap, xi);
#endif
    return color;
}

vec4 tfi_ewa_stochastic_impl(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso,
                             vec3 xi, bool hardware)
{
    if (!tf_finite(uv))
        return vec4(0.0);
    xi = tfi_unit3(xi);
    uv = tf_reduce_uv(uv, s.wrap);
    float a = alpha >= 0.0 ? min(alpha, 64.0) : 0.0;
    // Magnification (ewa.glsl): with probability level 0's trilinear share, the bilinear magnification filter at
    // one of its four spread points (tfi_ewa_magnified), a quarter of the share each, and there one texel (one
    // tap); the rest of xi.z, rescaled, picks the ellipse's level.
    float magnifyShare = 1.0 - clamp(tf_lod(TFI_A, dUVdx, dUVdy, s), 0.0, 1.0);
    vec4 color = vec4(0.0); // one return from here on (common.glsl)
    if (xi.z < magnifyShare) {
        vec2 spreadA, spreadB;
        tfi_ewa_spread(TFI_A, dUVdx, dUVdy, a, spreadA, spreadB);
        float point = min(floor(xi.z / magnifyShare * 4.0), 3.0); // 0..3: +a, -a, +b, -b as in tfi_ewa_magnified
        vec2 p = tf_reduce_uv(uv + (point < 2.0 ? spreadA : spreadB) * (mod(point, 2.0) == 0.0 ? 1.0 : -1.0), s.wrap);
#if TFI_HW
        if (hardware) {
            TF_COUNT_HW_LOOKUPS(1);
            color = TFI_LOOKUP(p, 0.0);
        }
#endif
#if TFI_CAN_FETCH
        if (!hardware)
            color = tf_bilinear_stochastic_level(TFI_A, p TFI_XA, 0, s.wrap, xi);
#endif
    } else {
        xi.z = clamp((xi.z - magnifyShare) / (1.0 - magnifyShare), 0.0, 0.99999994);
        float lambda, rest;
        tfi_EwaShape shape = tfi_ewa_shape(TFI_A, dUVdx, dUVdy, s, maxAniso, lambda);
        int level = tfi_stochastic_level(lambda, xi.z, rest);
#if TFI_HW
        if (hardware)
            color = tfi_ewa_stochastic_level_hw(TFI_A, uv TFI_XA, level, s.wrap, shape, a, xi.x);
#endif
#if TFI_CAN_FETCH
        if (!hardware)
            color = tfi_ewa_stochastic_level(TFI_A, uv TFI_XA, level, s.wrap, shape, a, xi.x);
#endif
    }
    return color;
}

#if TFI_MANUAL && !TFI_ENV
vec4 tf_bilinear_stochastic(TFI_T, vec2 uv TFI_X, tf_Sampler s, vec3 xi)
{
    return tf_bilinear_stochastic_level(TFI_A, uv TFI_XA, 0, s.wrap, xi);
}
vec4 tf_trilinear_stochastic(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi)
{
    return tfi_trilinear_stochastic_impl(TFI_A, uv TFI_XA, dUVdx, dUVdy, s, xi, false);
}
vec4 tf_aniso_stochastic(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape, vec3 xi)
{
    return tfi_aniso_stochastic_impl(TFI_A, uv TFI_XA, dUVdx, dUVdy, s, maxProbes, shape, xi, false);
}
vec4 tf_ewa_stochastic(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi)
{
    return tfi_ewa_stochastic_impl(TFI_A, uv TFI_XA, dUVdx, dUVdy, s, alpha, maxAniso, xi, false);
}
#endif

#if TFI_HW && !TFI_ENV
vec4 tf_bilinear_stochastic_hw(TFI_T, vec2 uv TFI_X, tf_Sampler s, vec3 xi)
{
    if (!tf_finite(uv))
        return vec4(0.0);
    TF_COUNT_HW_LOOKUPS(1);
    return TFI_LOOKUP(tf_reduce_uv(uv, s.wrap), 0.0); // the hardware's bilinear tap is already one tap
}
vec4 tf_trilinear_stochastic_hw(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, vec3 xi)
{
    return tfi_trilinear_stochastic_impl(TFI_A, uv TFI_XA, dUVdx, dUVdy, s, xi, true);
}
vec4 tf_aniso_stochastic_hw(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape,
                            vec3 xi)
{
    return tfi_aniso_stochastic_impl(TFI_A, uv TFI_XA, dUVdx, dUVdy, s, maxProbes, shape, xi, true);
}
vec4 tf_ewa_stochastic_hw(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float alpha, float maxAniso,
                          vec3 xi)
{
    return tfi_ewa_stochastic_impl(TFI_A, uv TFI_XA, dUVdx, dUVdy, s, alpha, maxAniso, xi, true);
}
#endif
