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
#define TFI_BRILINEAR_LEVEL(level) tf_bilinear_level(TFI_A, uv TFI_XA, level, s.wrap)
    vec4 color;
    TFI_BLEND_LEVELS(color, TFI_BRILINEAR_LEVEL, lo, w); // outside the band: one level (lod.glsl)
#undef TFI_BRILINEAR_LEVEL
    return color;
}

#endif
