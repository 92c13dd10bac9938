// texfilter/detail/trilinear_kind.glsl — internal: trilinear.glsl's functions for one resource kind. detail/instantiate.glsl
// includes it once per kind (no include guard on purpose), with detail/access.glsl's macros for that kind.
#if !defined(TFI_KIND)
#error "texfilter/detail/trilinear_kind.glsl is internal: include texfilter/trilinear.glsl"
#endif
#if TFI_MANUAL

vec4 tf_trilinear(TFI_T, vec2 uv TFI_X, vec2 dUVdx, vec2 dUVdy, tf_Sampler s)
{
    float f;
    int lo = tfi_split_lod(tf_lod(TFI_A, dUVdx, dUVdy, s), f);
    // uv checked and moved by whole periods once for both levels; selects, not an early return (one path).
    bool finite = tf_finite(uv);
    vec2 reduced = finite ? tf_reduce_uv(uv, s.wrap) : vec2(0.0);
#define TFI_TRILINEAR_LEVEL(level) tfi_mip_level_reduced(TFI_A, reduced TFI_XA, level, s.wrap)
    vec4 color;
    TFI_BLEND_LEVELS(color, TFI_TRILINEAR_LEVEL, lo, f); // on a level, one level's fetches (lod.glsl)
#undef TFI_TRILINEAR_LEVEL
    return finite ? color : vec4(0.0);
}

#endif
