// texfilter/detail/lod_kind.glsl — internal: lod.glsl's functions for one resource kind. detail/instantiate.glsl
// includes it once per kind (no include guard on purpose), with detail/access.glsl's macros for that kind.
#if !defined(TFI_KIND)
#error "texfilter/detail/lod_kind.glsl is internal: include texfilter/lod.glsl"
#endif
#if TFI_OWNS_T

// Unclamped log2(rho) + bias; +Inf for non-finite gradients, -Inf for zero gradients.
float tf_lod_unclamped(TFI_T, vec2 dUVdx, vec2 dUVdy, float lodBias)
{
    vec2 size0 = vec2(TFI_SIZE0);
    vec2 ax = dUVdx * size0;
    vec2 ay = dUVdy * size0;
    float rho2 = max(dot(ax, ax), dot(ay, ay)); // squared lengths: tfi_log2_rho
    return tf_finite(dUVdx) && tf_finite(dUVdy) ? tfi_log2_rho(rho2) + lodBias : 1.0 / 0.0;
}

float tfi_clamp_lod(float lambda, tf_Sampler s, TFI_T)
{
    return tfi_clamp_lod_levels(lambda, s, TFI_LEVELS);
}

float tf_lod(TFI_T, vec2 dUVdx, vec2 dUVdy, tf_Sampler s)
{
    return tfi_clamp_lod(tf_lod_unclamped(TFI_A, dUVdx, dUVdy, s.lodBias), s, TFI_A);
}

#endif
