// texfilter/detail/cube_kind.glsl — internal: cube.glsl's functions for one resource kind. detail/instantiate.glsl
// includes it once per kind (no include guard on purpose), with detail/access.glsl's macros for that kind.
#if !defined(TFI_KIND)
#error "texfilter/detail/cube_kind.glsl is internal: include texfilter/cube.glsl"
#endif
#if TFI_CUBE

// The public parameters after dir: the layer of an array (the face comes from dir).
#if TFI_KIND == 17 || TFI_KIND == 18
#define TFI_CUBE_X , int layer
#else
#define TFI_CUBE_X
#endif
// Each form: the face lookup, then the 2D family on the face (TFI_XA passes `face` and `layer`).
#define TFI_CUBE_BEGIN(dDirdx, dDirdy) \
    tf_CubeLookup c = tf_cube_lookup(dir, dDirdx, dDirdy); \
    if (c.face < 0) \
        return vec4(0.0); \
    int face = c.face; \
    tf_Sampler t = tfi_cube_sampler(s)

vec4 tf_nearest_cube(TFI_T, vec3 dir TFI_CUBE_X, tf_Sampler s)
{
    TFI_CUBE_BEGIN(vec3(0.0), vec3(0.0));
    return tf_nearest_level(TFI_A, c.uv TFI_XA, 0, t.wrap);
}

vec4 tf_bilinear_cube(TFI_T, vec3 dir TFI_CUBE_X, tf_Sampler s)
{
    TFI_CUBE_BEGIN(vec3(0.0), vec3(0.0));
    return tf_bilinear_level(TFI_A, c.uv TFI_XA, 0, t.wrap);
}

vec4 tf_bspline_cube(TFI_T, vec3 dir TFI_CUBE_X, tf_Sampler s)
{
    TFI_CUBE_BEGIN(vec3(0.0), vec3(0.0));
    return tf_cubic_level(TFI_A, c.uv TFI_XA, 0, t.wrap, TF_RECONSTRUCT_BSPLINE);
}

vec4 tf_catmull_rom_cube(TFI_T, vec3 dir TFI_CUBE_X, tf_Sampler s)
{
    TFI_CUBE_BEGIN(vec3(0.0), vec3(0.0));
    return tf_cubic_level(TFI_A, c.uv TFI_XA, 0, t.wrap, TF_RECONSTRUCT_CATMULL_ROM);
}

vec4 tf_bspline_cube_hw(TFI_T, vec3 dir TFI_CUBE_X, tf_Sampler s)
{
    TFI_CUBE_BEGIN(vec3(0.0), vec3(0.0));
    return tf_cubic_level_hw(TFI_A, c.uv TFI_XA, 0, t.wrap, TF_RECONSTRUCT_BSPLINE);
}

vec4 tf_catmull_rom_cube_hw(TFI_T, vec3 dir TFI_CUBE_X, tf_Sampler s)
{
    TFI_CUBE_BEGIN(vec3(0.0), vec3(0.0));
    return tf_cubic_level_hw(TFI_A, c.uv TFI_XA, 0, t.wrap, TF_RECONSTRUCT_CATMULL_ROM);
}

vec4 tf_nearest_mip_cube(TFI_T, vec3 dir TFI_CUBE_X, vec3 dDirdx, vec3 dDirdy, tf_Sampler s)
{
    TFI_CUBE_BEGIN(dDirdx, dDirdy);
    return tf_nearest_mip(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t);
}

vec4 tf_bilinear_mip_cube(TFI_T, vec3 dir TFI_CUBE_X, vec3 dDirdx, vec3 dDirdy, tf_Sampler s)
{
    TFI_CUBE_BEGIN(dDirdx, dDirdy);
    return tf_bilinear_mip(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t);
}

vec4 tf_trilinear_cube(TFI_T, vec3 dir TFI_CUBE_X, vec3 dDirdx, vec3 dDirdy, tf_Sampler s)
{
    TFI_CUBE_BEGIN(dDirdx, dDirdy);
    return tf_trilinear(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t);
}

vec4 tf_aniso_cube(TFI_T, vec3 dir TFI_CUBE_X, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape)
{
    TFI_CUBE_BEGIN(dDirdx, dDirdy);
    return tfi_aniso_filter(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t, maxProbes, shape, false);
}

vec4 tf_aniso_cube_hw(TFI_T, vec3 dir TFI_CUBE_X, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape)
{
    TFI_CUBE_BEGIN(dDirdx, dDirdy);
    return tfi_aniso_filter(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t, maxProbes, shape, true);
}

vec4 tf_ewa_cube(TFI_T, vec3 dir TFI_CUBE_X, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso)
{
    TFI_CUBE_BEGIN(dDirdx, dDirdy);
    return tfi_ewa_impl(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t, alpha, maxAniso, false);
}

vec4 tf_ewa_cube_hw(TFI_T, vec3 dir TFI_CUBE_X, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso)
{
    TFI_CUBE_BEGIN(dDirdx, dDirdy);
    return tfi_ewa_impl(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t, alpha, maxAniso, true);
}

// --stochastic (stochastic.glsl): one texel (manual) or one hardware tap (_hw) a lookup, chosen by xi.
vec4 tf_bilinear_stochastic_cube(TFI_T, vec3 dir TFI_CUBE_X, tf_Sampler s, vec3 xi)
{
    TFI_CUBE_BEGIN(vec3(0.0), vec3(0.0));
    return tf_bilinear_stochastic_level(TFI_A, c.uv TFI_XA, 0, t.wrap, xi);
}

vec4 tf_bilinear_stochastic_cube_hw(TFI_T, vec3 dir TFI_CUBE_X, tf_Sampler s, vec3 xi)
{
    TFI_CUBE_BEGIN(vec3(0.0), vec3(0.0));
    TF_COUNT_HW_LOOKUPS(1);
    return TFI_LOOKUP(c.uv, 0.0); // the hardware's bilinear tap is already one tap
}

vec4 tf_trilinear_stochastic_cube(TFI_T, vec3 dir TFI_CUBE_X, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, vec3 xi)
{
    TFI_CUBE_BEGIN(dDirdx, dDirdy);
    return tfi_trilinear_stochastic_impl(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t, xi, false);
}

vec4 tf_trilinear_stochastic_cube_hw(TFI_T, vec3 dir TFI_CUBE_X, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, vec3 xi)
{
    TFI_CUBE_BEGIN(dDirdx, dDirdy);
    return tfi_trilinear_stochastic_impl(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t, xi, true);
}

vec4 tf_aniso_stochastic_cube(TFI_T, vec3 dir TFI_CUBE_X, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape,
                              vec3 xi)
{
    TFI_CUBE_BEGIN(dDirdx, dDirdy);
    return tfi_aniso_stochastic_impl(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t, maxProbes, shape, xi, false);
}

vec4 tf_aniso_stochastic_cube_hw(TFI_T, vec3 dir TFI_CUBE_X, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes,
                                 int shape, vec3 xi)
{
    TFI_CUBE_BEGIN(dDirdx, dDirdy);
    return tfi_aniso_stochastic_impl(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t, maxProbes, shape, xi, true);
}

vec4 tf_ewa_stochastic_cube(TFI_T, vec3 dir TFI_CUBE_X, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso,
                            vec3 xi)
{
    TFI_CUBE_BEGIN(dDirdx, dDirdy);
    return tfi_ewa_stochastic_impl(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t, alpha, maxAniso, xi, false);
}

vec4 tf_ewa_stochastic_cube_hw(TFI_T, vec3 dir TFI_CUBE_X, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha,
                               float maxAniso, vec3 xi)
{
    TFI_CUBE_BEGIN(dDirdx, dDirdy);
    return tfi_ewa_stochastic_impl(TFI_A, c.uv TFI_XA, c.dUVdx, c.dUVdy, t, alpha, maxAniso, xi, true);
}

#undef TFI_CUBE_BEGIN
#undef TFI_CUBE_X
#endif
