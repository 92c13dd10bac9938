// texfilter/detail/brilinear_kind.glsl — internal: brilinear.glsl's functions for one resource kind. detail/instantiate.glsl
// includes it once per kind (no include guard on purpose), with detail/access.glsl's macros for that kind.
#if !defined(TFI_KIND)
#error "texfilter/detail/brilinear_kind.glsl is internal: include texfilter/brilinear.glsl"
#endif
#if TFI_MANUAL && !TFI_ENV

vec4 tf_brilinear(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, float band)
{
    float f;
    int lo = tfi_split_lod(tf_lod(TFI_A, dUVdx, dUVdy, s), f);
    float w = tf_brilinear_weight(f, band); // 0 or 1 outside the band: one level, 4 fetches
    // uv checked and moved by whole periods once for both levels; selects, not an early return (one path).
    bool finite = tf_finite(uv);
    vec2 reduced = finite ? tf_reduce_uv(uv, s.wrap) : vec2(0.0);
#define TFI_BRILINEAR_LEVEL(level) tfi_bilinear_level_reduced(TFI_A, reduced TFI_XA, level, s.wrap)
    vec4 color;
    TFI_BLEND_LEVELS(color, TFI_BRILINEAR_LEVEL, lo, w); // outside the band: one level (lod.glsl)
#undef TFI_BRILINEAR_LEVEL
    return finite ? color : vec4(0.0);
}

#endif
