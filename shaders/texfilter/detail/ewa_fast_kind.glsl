// texfilter/detail/ewa_fast_kind.glsl — internal: ewa_fast.glsl's functions for one resource kind.
// detail/instantiate.glsl includes it once per kind (no include guard on purpose), with detail/access.glsl's macros.
#if !defined(TFI_KIND)
#error "texfilter/detail/ewa_fast_kind.glsl is internal: include texfilter/ewa_fast.glsl"
#endif

#if TFI_HW
vec4 tf_ewa_fast(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s)
{
    vec4 color = vec4(0.0); // one return (common.glsl)
    if (tf_finite(uv)) {
        // The eigenvalues of J·Jᵀ / m² and its projector, no eccentricity clamp (ewa.glsl's shape; its LOD is
        // kept only where the footprint is zero or non-finite: m = 0, the finest or the coarsest level).
        float lambda;
        tfi_EwaShape shape = tfi_ewa_shape(TFI_A, dUVdx, dUVdy, s, 1e18, lambda);
        vec2 step = vec2(0.0), zig = vec2(0.0); // the row's step along u1 and zigzag across it (uv units)
        vec2 a = vec2(0.0), b = vec2(0.0);      // the triangle's vertices a, −½a ± b (uv units)
        float weights = 1.0, mean = 0.0;        // the row's Σ w_t, and its zigzag's mean offset
        int h = 0;
        bool triangle = false;
        float m2 = 4.0 * TFI_EWA_FAST_PIXEL_VARIANCE * shape.m * shape.m;
        float A = m2 * shape.major2 + 1.0, B = m2 * shape.minor2 + 1.0; // 4k²σ² + 1
        if (shape.m > 0.0 && isinf(A)) {
            lambda = tfi_clamp_lod(1.0 / 0.0, s, TFI_A); // σ1 past ~1.8e19 texels: one lookup, the coarsest level
        } else if (shape.m > 0.0) {
            triangle = A < TFI_EWA_FAST_ROW_FROM * B;
            // The row's LOD starts at the triangle's where the layouts meet (A = ROW_FROM·B) and falls to its own
            // by A = 2·ROW_FROM·B: no jump of the LOD at the switch.
            float meet = clamp(2.0 - A / (TFI_EWA_FAST_ROW_FROM * B), 0.0, 1.0);
            float target = triangle ? A / TFI_EWA_FAST_TRIANGLE_REACH
                                    : max(max(B / TFI_EWA_FAST_ZIGZAG_REACH, A / TFI_EWA_FAST_ROW_REACH),
                                          meet * A / TFI_EWA_FAST_TRIANGLE_REACH);
            lambda = tfi_clamp_lod(0.5 * tfi_log2(target) + s.lodBias, s, TFI_A);
            float texel = exp2(lambda), t2 = texel * texel;
            float reach = TFI_EWA_FAST_SPACING * texel; // the largest spacing
            if (triangle) {
                // S = C − P(λ)·I = ¼·(4k²·J·Jᵀ + (1 − t²)·I), its negative part (a clamped LOD) dropped.
                float below = max(B - t2, 0.0), along = max(A - t2, 0.0);
                float f = A > B ? (along - below) / (A - B) : 0.0;
                vec3 S = 0.25 * (vec3(below, 0.0, below) +
                                 f * m2 * (shape.cov - vec3(shape.minor2, 0.0, shape.minor2)));
                // √S = (S + √det·I)/√(tr S + 2√det), symmetric; in units of tr S (no overflow), shrunk where a
                // clamped LOD would space the probes past `reach` (they are √(3 tr S) apart).
                float trace = S.x + S.z;
                vec3 N = S / max(trace, 1e-30);
                float root = sqrt(max(N.x * N.z - N.y * N.y, 0.0));
                if (trace * (1.0 + 2.0 * root) > TFI_EWA_FAST_ONE_PROBE * t2) { // (tr √S)²
                    vec3 R = (N + vec3(root, 0.0, root)) * inversesqrt(1.0 + 2.0 * root) *
                             min(sqrt(trace), reach * 0.57735027);
                    // Three probes √2·√S·e_k, e_k at 90°, 210°, 330°: covariance √S·(2·½I)·√S = S.
                    a = 1.41421356 * R.yz / vec2(TFI_SIZE0);               // √2·√S·(0, 1)
                    b = 1.41421356 * (0.8660254 * R.xy) / vec2(TFI_SIZE0); // √2·√S·(cos 30°, 0)
                } else {
                    triangle = false;
                }
            } else {
                float spread = 0.5 * sqrt(max(A - t2, 0.0)); // s, level-0 texels
                h = int(clamp(ceil(2.0 * spread / reach - 0.3), 0.0, float(TFI_EWA_FAST_MAX_HALF)));
                if (h > 0) {
                    vec3 moments = tfi_ewa_fast_moments(h);
                    weights = moments.x;
                    mean = moments.z / moments.x;
                    float delta = min(spread * sqrt(moments.x / moments.y), reach);
                    float across = min(0.5 * sqrt(max(B - t2, 0.0) / (1.0 - mean * mean)), 0.5 * reach);
                    vec3 p = shape.cov - vec3(shape.minor2, 0.0, shape.minor2); // (major2 − minor2)·u1u1ᵀ
                    vec2 q = p.x >= p.z ? p.xy : p.yz;
                    vec2 u1 = dot(q, q) > 0.0 ? normalize(q) : vec2(1.0, 0.0); // none when isotropic
                    u1 = dot(u1, TFI_EWA_FAST_SIDE) >= 0.0 ? u1 : -u1; // the zigzag's side: one sign of u1
                    step = delta * u1 / vec2(TFI_SIZE0);
                    zig = across * vec2(-u1.y, u1.x) / vec2(TFI_SIZE0);
                }
            }
        }
        if (triangle) {
            uv = tfi_aniso_centre(uv, 2.0 * (abs(a) + abs(b)), s.wrap);
            for (int i = 0; i < 3; ++i) // a, −½a ± b: the triangle's vertices
                color += tfi_aniso_probe_hw(TFI_A, uv + (i == 0 ? a : -0.5 * a + (i == 1 ? b : -b)) TFI_XA, lambda,
                                            s.wrap);
            color *= 1.0 / 3.0;
        } else if (h == 0) {
            uv = tfi_aniso_centre(uv, vec2(0.0), s.wrap);
            color = tfi_aniso_probe_hw(TFI_A, uv TFI_XA, lambda, s.wrap);
        } else {
            uv = tfi_aniso_centre(uv, 2.0 * float(h) * abs(step) + 4.0 * abs(zig), s.wrap);
            for (int t = -TFI_EWA_FAST_MAX_HALF; t <= TFI_EWA_FAST_MAX_HALF; ++t) {
                if (abs(t) > h)
                    continue;
                vec2 p = uv + float(t) * step + (((t & 1) == 0 ? 1.0 : -1.0) - mean) * zig;
                color += tfi_ewa_fast_weight(t, h) * tfi_aniso_probe_hw(TFI_A, p TFI_XA, lambda, s.wrap);
            }
            color /= weights;
        }
    }
    return color;
}
#endif
