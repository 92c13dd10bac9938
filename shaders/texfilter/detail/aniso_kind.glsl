// texfilter/detail/aniso_kind.glsl — internal: aniso.glsl's functions for one resource kind. detail/instantiate.glsl
// includes it once per kind (no include guard on purpose), with detail/access.glsl's macros for that kind.
#if !defined(TFI_KIND)
#error "texfilter/detail/aniso_kind.glsl is internal: include texfilter/aniso.glsl"
#endif

#if TFI_OWNS_T
tfi_AnisoFootprint tfi_aniso_footprint(TFI_T, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape)
{
    int maxN = clamp(maxProbes, 1, TF_ANISO_MAX_PROBES);
    tfi_AnisoFootprint fp = tfi_AnisoFootprint(vec2(0.0), 1, 0.0);
    vec2 size0 = vec2(TFI_SIZE0);
    vec2 ax = dUVdx * size0, ay = dUVdy * size0; // the columns of J, in level-0 texels
    float m = max(max(abs(ax.x), abs(ax.y)), max(abs(ay.x), abs(ay.y)));
    if (!(m > 0.0) || isinf(m) || !tf_finite(dUVdx) || !tf_finite(dUVdy)) {
        // Zero gradients: λ = −∞, the finest level. NaN/±Inf (or past float range in texels): +∞, the coarsest.
        fp.lod = tf_lod(TFI_A, dUVdx, dUVdy, s);
        return fp;
    }
    // J scaled by a power of two so that its largest entry is in [½, 1): the scale is exact, and nothing
    // below overflows; a minor axis below ~1e-19 of the major one underflows to zero (N = N_max either way).
    int e;
    frexp(m, e);
    vec2 cx = ldexp(ax, ivec2(-e)), cy = ldexp(ay, ivec2(-e));

    if (shape != TF_ANISO_FELINE) {
        float px2 = dot(cx, cx), py2 = dot(cy, cy);
        fp.probes = tfi_aniso_count(sqrt(max(px2, py2) / min(px2, py2)), maxN);
        tf_Sampler t = s;
        if (fp.probes > 1) { // log2(Pmax/N) + bias = log2(Pmax) + (bias − log2 N); N = 1 stays tf_lod exactly
            t.lodBias -= tfi_log2(float(fp.probes));
            fp.axis = px2 >= py2 ? dUVdx : dUVdy; // ties: dUVdx
        }
        fp.lod = tf_lod(TFI_A, dUVdx, dUVdy, t);
        return fp;
    }

    // Feline. Closed-form 2x2 SVD of J = [a b; c d] (columns cx, cy): with E = (a+d)/2, F = (a−d)/2,
    // G = (c+b)/2, H = (c−b)/2, Q = |(E, H)|, R = |(F, G)|, the singular values are Q + R and |Q − R|, and u1
    // lies at half the angle of the complex product (F + iG)(E + iH).
    float E = 0.5 * (cx.x + cy.y), F = 0.5 * (cx.x - cy.y);
    float G = 0.5 * (cx.y + cy.x), H = 0.5 * (cx.y - cy.x);
    float Q = length(vec2(E, H)), R = length(vec2(F, G));
    float major = Q + R, minor = abs(Q - R); // σ1, σ2 times 2^-e
    fp.probes = tfi_aniso_count(major / minor, maxN);
    float lambda = float(e) + tfi_log2(max(minor, major / float(fp.probes))) + s.lodBias;
    fp.lod = tfi_clamp_lod(lambda, s, TFI_A);
    if (fp.probes > 1) { // then major > minor, so R > 0, Q > 0 and z != 0
        vec2 z = vec2(F * E - G * H, F * H + G * E);
        float r = length(z);
        vec2 u1 = normalize(z.x >= 0.0 ? vec2(r + z.x, z.y) : vec2(z.y, r - z.x)); // half angle, up to sign
        fp.axis = ldexp(major * u1 / size0, ivec2(e));
    }
    return fp;
}
#endif

// One trilinear probe at a given LOD in [0, levels−1], from texelFetch: tf_trilinear's blend.
vec4 tfi_aniso_probe(TFI_T, vec2 uv TFI_X, float lod, int wrapMode)
{
#if !TFI_CAN_FETCH
    return vec4(0.0); // no texelFetch on this kind: it has only the _hw entry points, which never come here
#else
    float f;
    int lo = tfi_split_lod(lod, f);
#define TFI_PROBE_LEVEL(level) tfi_mip_level(TFI_A, uv TFI_XA, level, wrapMode)
    vec4 color;
    TFI_BLEND_LEVELS_ONCE(color, TFI_PROBE_LEVEL, lo, f); // each level's fetches issued once (lod.glsl)
    return color;
#undef TFI_PROBE_LEVEL
#endif
}

// One trilinear probe through the hardware sampler, at uv moved by whole periods as the manual form's
// bilinear lookups do (a sampler given |uv| >= ~1e37 returns NaN on lavapipe: uv·size overflows).
// With TF_MAGNIFY, a probe that reads level 0 (lod < 1) takes TF_MAGNIFY's taps there and one bilinear tap
// of level 1, blended as trilinear blends them.
vec4 tfi_aniso_probe_hw(TFI_T, vec2 uv TFI_X, float lod, int wrapMode)
{
    uv = tf_reduce_uv(uv, wrapMode);
    vec4 color; // one return (common.glsl): TF_MAGNIFY is a constant
    if (TF_MAGNIFY != TF_RECONSTRUCT_BILINEAR && lod < 1.0) {
        color = tfi_magnified_level0(TFI_A, uv TFI_XA, wrapMode, true);
        if (lod > 0.0) {
            TF_COUNT_HW_LOOKUPS(1);
            color = mix(color, TFI_LOOKUP(uv, 1.0), lod);
        }
    } else {
        TF_COUNT_HW_LOOKUPS(1);
        color = TFI_LOOKUP(uv, lod);
    }
    return color;
}

vec4 tfi_aniso_filter(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape,
                     bool hardware)
{
    if (!tf_finite(uv))
        return vec4(0.0);
    tfi_AnisoFootprint fp = tfi_aniso_footprint(TFI_A, dUVdx, dUVdy, s, maxProbes, shape);
    uv = tfi_aniso_centre(uv, fp.axis, s.wrap);
    if (fp.probes == 1)
        return hardware ? tfi_aniso_probe_hw(TFI_A, uv TFI_XA, fp.lod, s.wrap) : tfi_aniso_probe(TFI_A, uv TFI_XA, fp.lod, s.wrap);
    vec4 sum = vec4(0.0);
    float weights = 0.0;
    for (int k = 0; k < TF_ANISO_MAX_PROBES; ++k) {
        if (k >= fp.probes)
            break;
        float t = (float(k) + 0.5) / float(fp.probes) - 0.5;
        float w = shape == TF_ANISO_FELINE ? exp(-8.0 * t * t) : 1.0;
        vec2 p = uv + t * fp.axis;
        sum += w * (hardware ? tfi_aniso_probe_hw(TFI_A, p TFI_XA, fp.lod, s.wrap) : tfi_aniso_probe(TFI_A, p TFI_XA, fp.lod, s.wrap));
        weights += w;
    }
    return sum / weights;
}

#if TFI_MANUAL
vec4 tf_aniso(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape)
{
    return tfi_aniso_filter(TFI_A, uv TFI_XA, dUVdx, dUVdy, s, maxProbes, shape, false);
}
#endif

#if TFI_HW
vec4 tf_aniso_hw(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, int maxProbes, int shape)
{
    return tfi_aniso_filter(TFI_A, uv TFI_XA, dUVdx, dUVdy, s, maxProbes, shape, true);
}
#endif

