// texfilter/detail/latlong_kind.glsl — internal: latlong.glsl's functions for one resource kind. detail/instantiate.glsl
// includes it once per kind (no include guard on purpose), with detail/access.glsl's macros for that kind.
#if !defined(TFI_KIND)
#error "texfilter/detail/latlong_kind.glsl is internal: include texfilter/latlong.glsl"
#endif
#if TFI_LATLONG

// Each form: the uv lookup, then the 2D family with the lat-long texel rule (TFI_XA passes `latlong`).
#define TFI_LATLONG_BEGIN(dDirdx, dDirdy) \
    tf_LatLongLookup c = tf_latlong_lookup(dir, dDirdx, dDirdy); \
    if (!c.valid) \
        return vec4(0.0); \
    tf_LatLong latlong = tf_LatLong(0); \
    tf_Sampler t = tf_Sampler(TF_WRAP_REPEAT, s.lodBias, s.lodMin, s.lodMax)

vec4 tf_nearest_latlong(TFI_T, vec3 dir, tf_Sampler s)
{
    TFI_LATLONG_BEGIN(vec3(0.0), vec3(0.0));
    return tf_nearest_level(TFI_A, c.uv TFI_XA, 0, t.wrap);
}

vec4 tf_bilinear_latlong(TFI_T, vec3 dir, tf_Sampler s)
{
    TFI_LATLONG_BEGIN(vec3(0.0), vec3(0.0));
    return tf_bilinear_level(TFI_A, c.uv TFI_XA, 0, t.wrap);
}

vec4 tf_bspline_latlong(TFI_T, vec3 dir, tf_Sampler s)
{
    TFI_LATLONG_BEGIN(vec3(0.0), vec3(0.0));
    return tf_cubic_level(TFI_A, c.uv TFI_XA, 0, t.wrap, TF_RECONSTRUCT_BSPLINE);
}

vec4 tf_catmull_rom_latlong(TFI_T, vec3 dir, tf_Sampler s)
{
    TFI_LATLONG_BEGIN(vec3(0.0), vec3(0.0));
    return tf_cubic_level(TFI_A, c.uv TFI_XA, 0, t.wrap, TF_RECONSTRUCT_CATMULL_ROM);
}

vec4 tf_bspline_latlong_hw(TFI_T, vec3 dir, tf_Sampler s)
{
    TFI_LATLONG_BEGIN(vec3(0.0), vec3(0.0));
    return tf_cubic_level_hw(TFI_A, c.uv TFI_XA, 0, t.wrap, TF_RECONSTRUCT_BSPLINE);
}

vec4 tf_catmull_rom_latlong_hw(TFI_T, vec3 dir, tf_Sampler s)
{
    TFI_LATLONG_BEGIN(vec3(0.0), vec3(0.0));
    return tf_cubic_level_hw(TFI_A, c.uv TFI_XA, 0, t.wrap, TF_RECONSTRUCT_CATMULL_ROM);
}

vec4 tf_nearest_mip_latlong(TFI_T, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s)
{
    TFI_LATLONG_BEGIN(dDirdx, dDirdy);
    return tf_nearest_mip(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t);
}

vec4 tf_bilinear_mip_latlong(TFI_T, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s)
{
    TFI_LATLONG_BEGIN(dDirdx, dDirdy);
    return tf_bilinear_mip(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t);
}

vec4 tf_trilinear_latlong(TFI_T, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s)
{
    TFI_LATLONG_BEGIN(dDirdx, dDirdy);
    return tf_trilinear(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t);
}

vec4 tf_aniso_latlong(TFI_T, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape)
{
    TFI_LATLONG_BEGIN(dDirdx, dDirdy);
    return tfi_aniso_filter(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t, maxProbes, shape, false);
}

vec4 tf_aniso_latlong_hw(TFI_T, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape)
{
    TFI_LATLONG_BEGIN(dDirdx, dDirdy);
    return tfi_aniso_filter(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t, maxProbes, shape, true);
}

vec4 tf_ewa_latlong(TFI_T, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso)
{
    TFI_LATLONG_BEGIN(dDirdx, dDirdy);
    return tfi_ewa_impl(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t, alpha, maxAniso, false);
}

vec4 tf_ewa_latlong_hw(TFI_T, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso)
{
    TFI_LATLONG_BEGIN(dDirdx, dDirdy);
    return tfi_ewa_impl(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t, alpha, maxAniso, true);
}

// --stochastic (stochastic.glsl): one texel (manual) or one hardware tap (_hw) a lookup, chosen by xi.
vec4 tf_bilinear_stochastic_latlong(TFI_T, vec3 dir, tf_Sampler s, vec3 xi)
{
    TFI_LATLONG_BEGIN(vec3(0.0), vec3(0.0));
    return tf_bilinear_stochastic_level(TFI_A, c.uv TFI_XA, 0, t.wrap, xi);
}

vec4 tf_bilinear_stochastic_latlong_hw(TFI_T, vec3 dir, tf_Sampler s, vec3 xi)
{
    TFI_LATLONG_BEGIN(vec3(0.0), vec3(0.0));
    TF_COUNT_HW_LOOKUPS(1);
    return TFI_LOOKUP(c.uv, 0.0); // the hardware's bilinear tap is already one tap
}

vec4 tf_trilinear_stochastic_latlong(TFI_T, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, vec3 xi)
{
    TFI_LATLONG_BEGIN(dDirdx, dDirdy);
    return tfi_trilinear_stochastic_impl(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t, xi, false);
}

vec4 tf_trilinear_stochastic_latlong_hw(TFI_T, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, vec3 xi)
{
    TFI_LATLONG_BEGIN(dDirdx, dDirdy);
    return tfi_trilinear_stochastic_impl(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t, xi, true);
}

vec4 tf_aniso_stochastic_latlong(TFI_T, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape,
                              vec3 xi)
{
    TFI_LATLONG_BEGIN(dDirdx, dDirdy);
    return tfi_aniso_stochastic_impl(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t, maxProbes, shape, xi, false);
}

vec4 tf_aniso_stochastic_latlong_hw(TFI_T, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes,
                                 int shape, vec3 xi)
{
    TFI_LATLONG_BEGIN(dDirdx, dDirdy);
    return tfi_aniso_stochastic_impl(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t, maxProbes, shape, xi, true);
}

vec4 tf_ewa_stochastic_latlong(TFI_T, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso,
                            vec3 xi)
{
    TFI_LATLONG_BEGIN(dDirdx, dDirdy);
    return tfi_ewa_stochastic_impl(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t, alpha, maxAniso, xi, false);
}

vec4 tf_ewa_stochastic_latlong_hw(TFI_T, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha,
                               float maxAniso, vec3 xi)
{
    TFI_LATLONG_BEGIN(dDirdx, dDirdy);
    return tfi_ewa_stochastic_impl(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t, alpha, maxAniso, xi, true);
}

#undef TFI_LATLONG_BEGIN
#endif
