// texfilter/detail/nearest_kind.glsl — internal: nearest.glsl's functions for one resource kind. detail/instantiate.glsl
// includes it once per kind (no include guard on purpose), with detail/access.glsl's macros for that kind.
#if !defined(TFI_KIND)
#error "texfilter/detail/nearest_kind.glsl is internal: include texfilter/nearest.glsl"
#endif
#if TFI_CAN_FETCH

vec4 tf_nearest_level(TFI_T, vec2 uv TFI_X, int level, int wrapMode)
{
    if (!tf_finite(uv))
        return vec4(0.0);
    ivec2 size = tf_level_size(TFI_A, level);
    vec2 texel = floor(tf_reduce_uv(uv, wrapMode) * vec2(size)); // whole periods first: no overflow
    TF_COUNT_FETCHES(1);
    return TFI_FETCH(ivec2(TFI_WRAP(texel.x, size.x, wrapMode), TFI_WRAP(texel.y, size.y, wrapMode)), level);
}

#if TFI_MANUAL
vec4 tf_nearest(TFI_T, vec2 uv TFI_X, tf_Sampler s) { return tf_nearest_level(TFI_A, uv TFI_XA, 0, s.wrap); }

vec4 tf_nearest_mip(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s)
{
    return tf_nearest_level(TFI_A, uv TFI_XA, tf_mip_level_nearest(tf_lod(TFI_A, dUVdx, dUVdy, s)), s.wrap);
}
#endif

#endif
