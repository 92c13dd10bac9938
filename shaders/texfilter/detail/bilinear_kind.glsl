// texfilter/detail/bilinear_kind.glsl — internal: bilinear.glsl's functions for one resource kind. detail/instantiate.glsl
// includes it once per kind (no include guard on purpose), with detail/access.glsl's macros for that kind.
#if !defined(TFI_KIND)
#error "texfilter/detail/bilinear_kind.glsl is internal: include texfilter/bilinear.glsl"
#endif
#if TFI_CAN_FETCH

// tf_bilinear_level on a uv already finite and moved by whole periods (tf_reduce_uv): the filters that read
// several levels at one uv (trilinear, brilinear, aniso's probes) check and move it once.
vec4 tfi_bilinear_level_reduced(TFI_T, vec2 uv TFI_X, int level, int wrapMode)
{
    ivec2 size = tf_level_size(TFI_A, level);
    // The whole-period move first: no finite uv makes the texel coordinate overflow float.
    vec2 x = clamp(uv * vec2(size) - 0.5, -TF_MAX_TEXEL_COORD, TF_MAX_TEXEL_COORD);
    vec2 i0 = floor(x);
    vec2 a = x - i0;
    ivec2 xs = TFI_WRAP_PAIR(i0.x, size.x, wrapMode), ys = TFI_WRAP_PAIR(i0.y, size.y, wrapMode);
    TF_COUNT_FETCHES(4);
    vec4 top = mix(TFI_FETCH(ivec2(xs.x, ys.x), level), TFI_FETCH(ivec2(xs.y, ys.x), level), a.x);
    vec4 bottom = mix(TFI_FETCH(ivec2(xs.x, ys.y), level), TFI_FETCH(ivec2(xs.y, ys.y), level), a.x);
    return mix(top, bottom, a.y);
}

vec4 tf_bilinear_level(TFI_T, vec2 uv TFI_X, int level, int wrapMode)
{
    // Selects, not an early return: one path (lavapipe runs both sides of a branch under a mask anyway).
    bool finite = tf_finite(uv);
    vec4 color = tfi_bilinear_level_reduced(TFI_A, finite ? tf_reduce_uv(uv, wrapMode) : vec2(0.0) TFI_XA, level,
                                            wrapMode);
    return finite ? color : vec4(0.0);
}

#if TFI_MANUAL
vec4 tf_bilinear(TFI_T, vec2 uv TFI_X, tf_Sampler s) { return tf_bilinear_level(TFI_A, uv TFI_XA, 0, s.wrap); }

vec4 tf_bilinear_mip(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s)
{
    return tf_bilinear_level(TFI_A, uv TFI_XA, tf_mip_level_nearest(tf_lod(TFI_A, dUVdx, dUVdy, s)), s.wrap);
}
#endif

#endif
