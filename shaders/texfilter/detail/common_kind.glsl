// texfilter/detail/common_kind.glsl — internal: common.glsl's functions for one resource kind. detail/instantiate.glsl
// includes it once per kind (no include guard on purpose), with detail/access.glsl's macros for that kind.
#if !defined(TFI_KIND)
#error "texfilter/detail/common_kind.glsl is internal: include texfilter/common.glsl"
#endif
#if TFI_OWNS_T
// Size of a MIP level: the Vulkan floor rule from level 0 (access.glsl), or the texel source's own answer.
ivec2 tf_level_size(TFI_T, int level) { return TFI_LEVEL_SIZE(level); }
#endif

#if TFI_CUBE
// Texel p of level `level` of the face, any p (docs/ENVIRONMENT.md, "Texels off the face"): the texel that the
// direction through p's centre on the face's extended plane hits, read through the (NEAREST) sampler at that
// direction, which selects the face itself; one texel past both edges of a corner, the mean of the three texels
// that meet there. In the face the direction is the texel's own centre, half a texel from every boundary.
vec4 tfi_cube_read(TFI_T TFI_X, ivec2 p, int level, float n)
{
    vec3 d = tfi_cube_direction(face, (vec2(p) + 0.5) / n);
#if TFI_KIND == 15
    return textureLod(TF_NONUNIFORM(tex), d, float(level));
#elif TFI_KIND == 16
    return textureLod(TF_NONUNIFORM(samplerCube(tex, smp)), d, float(level));
#elif TFI_KIND == 17
    return textureLod(TF_NONUNIFORM(tex), vec4(d, float(layer)), float(level));
#else
    return textureLod(TF_NONUNIFORM(samplerCubeArray(tex, smp)), vec4(d, float(layer)), float(level));
#endif
}

vec4 tfi_cube_texel(TFI_T TFI_X, ivec2 p, int level)
{
    int n = max(TFI_SIZE0.x >> level, 1);
    ivec2 c = clamp(p, ivec2(0), ivec2(n - 1));
    if (abs(p.x - c.x) != 1 || abs(p.y - c.y) != 1)
        return tfi_cube_read(TFI_A TFI_XA, p, level, float(n));
    return (tfi_cube_read(TFI_A TFI_XA, c, level, float(n)) + tfi_cube_read(TFI_A TFI_XA, ivec2(p.x, c.y), level, float(n)) +
            tfi_cube_read(TFI_A TFI_XA, ivec2(c.x, p.y), level, float(n))) / 3.0;
}
#endif

#if TFI_LATLONG
// Texel p of a lat-long level, any p (docs/ENVIRONMENT.md): columns repeat; a row past a pole is the row as
// far from it on the other side, half a turn round (W/2 columns: exact for even widths). Rows repeat every
// 2H (over both poles and back), so p.y is first reduced into [0, 2H).
vec4 tfi_latlong_texel(TFI_T, ivec2 p, int level)
{
    ivec2 size = tf_level_size(TFI_A, level);
    int j = tf_wrap(float(p.y), 2 * size.y, TF_WRAP_REPEAT);
    float i = float(p.x);
    if (j >= size.y) {
        j = 2 * size.y - 1 - j;
        i += float(size.x / 2);
    }
    return texelFetch(TF_NONUNIFORM(tex), ivec2(tf_wrap(i, size.x, TF_WRAP_REPEAT), j), level);
}
#endif

#if TFI_CAN_FETCH
vec4 tf_fetch(TFI_T, ivec2 texel TFI_X, int level, int wrapMode)
{
    ivec2 size = tf_level_size(TFI_A, level);
    TF_COUNT_FETCHES(1);
    return TFI_FETCH(ivec2(TFI_WRAP(float(texel.x), size.x, wrapMode), TFI_WRAP(float(texel.y), size.y, wrapMode)),
                     level);
}
#endif
