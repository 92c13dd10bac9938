// texfilter/detail/bicubic_kind.glsl — internal: bicubic.glsl's functions for one resource kind. detail/instantiate.glsl
// includes it once per kind (no include guard on purpose), with detail/access.glsl's macros for that kind.
#if !defined(TFI_KIND)
#error "texfilter/detail/bicubic_kind.glsl is internal: include texfilter/bicubic.glsl"
#endif
#if TFI_CAN_FETCH
// The cubic kernels from texel fetches (tf_cubic_level without its bilinear case).
vec4 tfi_cubic_level_fetched(TFI_T, vec2 uv TFI_X, int level, int wrapMode, int kernel)
{
    if (!tf_finite(uv))
        return vec4(0.0);
    ivec2 size = tf_level_size(TFI_A, level);
    vec2 x = clamp(tf_reduce_uv(uv, wrapMode) * vec2(size) - 0.5, -TF_MAX_TEXEL_COORD, TF_MAX_TEXEL_COORD);
    vec2 i0 = floor(x);
    vec4 wx = tfi_cubic_weights(x.x - i0.x, kernel), wy = tfi_cubic_weights(x.y - i0.y, kernel);
    ivec4 xs = ivec4(TFI_WRAP(i0.x - 1.0, size.x, wrapMode), TFI_WRAP(i0.x, size.x, wrapMode),
                     TFI_WRAP(i0.x + 1.0, size.x, wrapMode), TFI_WRAP(i0.x + 2.0, size.x, wrapMode));
    ivec4 ys = ivec4(TFI_WRAP(i0.y - 1.0, size.y, wrapMode), TFI_WRAP(i0.y, size.y, wrapMode),
                     TFI_WRAP(i0.y + 1.0, size.y, wrapMode), TFI_WRAP(i0.y + 2.0, size.y, wrapMode));
    TF_COUNT_FETCHES(16);
    vec4 sum = vec4(0.0);
    for (int j = 0; j < 4; ++j) {
        vec4 row = wx.x * TFI_FETCH(ivec2(xs.x, ys[j]), level) + wx.y * TFI_FETCH(ivec2(xs.y, ys[j]), level) +
                   wx.z * TFI_FETCH(ivec2(xs.z, ys[j]), level) + wx.w * TFI_FETCH(ivec2(xs.w, ys[j]), level);
        sum += wy[j] * row;
    }
    return sum;
}

vec4 tf_cubic_level(TFI_T, vec2 uv TFI_X, int level, int wrapMode, int kernel)
{
    return kernel == TF_RECONSTRUCT_BILINEAR // one return (common.glsl)
               ? tf_bilinear_level(TFI_A, uv TFI_XA, level, wrapMode)
               : tfi_cubic_level_fetched(TFI_A, uv TFI_XA, level, wrapMode, kernel);
}
#endif

#if TFI_HW
// The cubic kernels from hardware taps at an already reduced uv (tf_cubic_level_hw without its bilinear case).
vec4 tfi_cubic_level_taps(TFI_T, vec2 uv TFI_X, int level, int kernel)
{
    float l = float(level);
    vec2 size = vec2(tf_level_size(TFI_A, level));
    vec2 x = clamp(uv * size - 0.5, -TF_MAX_TEXEL_COORD, TF_MAX_TEXEL_COORD);
    vec2 i0 = floor(x);
    vec4 wx = tfi_cubic_weights(x.x - i0.x, kernel), wy = tfi_cubic_weights(x.y - i0.y, kernel);
    // A tap at texel coordinate c reads texels floor(c − ½) and the next, the second weighted frac(c − ½).
    vec4 sum = vec4(0.0);
    if (kernel == TF_RECONSTRUCT_CATMULL_ROM) { // one return (common.glsl)
        vec3 gx = vec3(wx.x, wx.y + wx.z, wx.w), gy = vec3(wy.x, wy.y + wy.z, wy.w); // middle pair >= 1
        vec3 px = vec3(i0.x - 0.5, i0.x + 0.5 + wx.z / gx.y, i0.x + 2.5) / size.x;
        vec3 py = vec3(i0.y - 0.5, i0.y + 0.5 + wy.z / gy.y, i0.y + 2.5) / size.y;
        TF_COUNT_HW_LOOKUPS(9);
        for (int j = 0; j < 3; ++j)
            sum += gy[j] * (gx.x * TFI_LOOKUP(vec2(px.x, py[j]), l) + gx.y * TFI_LOOKUP(vec2(px.y, py[j]), l) +
                            gx.z * TFI_LOOKUP(vec2(px.z, py[j]), l));
    } else {
        vec2 g0 = vec2(wx.x + wx.y, wy.x + wy.y), g1 = vec2(wx.z + wx.w, wy.z + wy.w); // each >= 1/6
        vec2 p0 = (i0 - 0.5 + vec2(wx.y, wy.y) / g0) / size;
        vec2 p1 = (i0 + 1.5 + vec2(wx.w, wy.w) / g1) / size;
        TF_COUNT_HW_LOOKUPS(4);
        sum = g0.y * (g0.x * TFI_LOOKUP(p0, l) + g1.x * TFI_LOOKUP(vec2(p1.x, p0.y), l)) +
              g1.y * (g0.x * TFI_LOOKUP(vec2(p0.x, p1.y), l) + g1.x * TFI_LOOKUP(p1, l));
    }
    return sum;
}

vec4 tf_cubic_level_hw(TFI_T, vec2 uv TFI_X, int level, int wrapMode, int kernel)
{
    if (!tf_finite(uv))
        return vec4(0.0);
    uv = tf_reduce_uv(uv, wrapMode); // a sampler given |uv| >= ~1e37 returns NaN (uv·size overflows)
    vec4 color;
    if (kernel == TF_RECONSTRUCT_BILINEAR) { // one return from here on (common.glsl)
        TF_COUNT_HW_LOOKUPS(1);
        color = TFI_LOOKUP(uv, float(level));
    } else {
        color = tfi_cubic_level_taps(TFI_A, uv TFI_XA, level, kernel);
    }
    return color;
}
#endif

// Level `level` as trilinear and aniso's manual probes read it: TF_MAGNIFY's kernel on level 0, bilinear on
// the others (TF_MAGNIFY is a constant or a specialization constant: the branch folds away).
#if TFI_CAN_FETCH
vec4 tfi_mip_level(TFI_T, vec2 uv TFI_X, int level, int wrapMode)
{
    return TF_MAGNIFY != TF_RECONSTRUCT_BILINEAR && level == 0 // one return (common.glsl)
               ? tf_cubic_level(TFI_A, uv TFI_XA, 0, wrapMode, TF_MAGNIFY)
               : tf_bilinear_level(TFI_A, uv TFI_XA, level, wrapMode);
}

// tfi_mip_level on a uv already finite and reduced (tf_reduce_uv, which leaves a reduced uv as it is, so the
// cubic's own reduction changes nothing): trilinear's two levels at one uv.
vec4 tfi_mip_level_reduced(TFI_T, vec2 uv TFI_X, int level, int wrapMode)
{
    return TF_MAGNIFY != TF_RECONSTRUCT_BILINEAR && level == 0 // one return (common.glsl)
               ? tf_cubic_level(TFI_A, uv TFI_XA, 0, wrapMode, TF_MAGNIFY)
               : tfi_bilinear_level_reduced(TFI_A, uv TFI_XA, level, wrapMode);
}
#endif

// TF_MAGNIFY's level 0 from texel fetches or hardware taps (ewa, aniso's hardware probes).
vec4 tfi_magnified_level0(TFI_T, vec2 uv TFI_X, int wrapMode, bool hardware)
{
    // One return (common.glsl): every caller passes `hardware` as a constant. A shadow sampler has only the
    // _hw forms, which never come here with hardware false.
    vec4 color = vec4(0.0);
#if TFI_HW
    if (hardware)
        color = tf_cubic_level_hw(TFI_A, uv TFI_XA, 0, wrapMode, TF_MAGNIFY);
#endif
#if TFI_CAN_FETCH
    if (!hardware)
        color = tf_cubic_level(TFI_A, uv TFI_XA, 0, wrapMode, TF_MAGNIFY);
#endif
    return color;
}

#if TFI_MANUAL && !TFI_ENV
vec4 tf_bspline(TFI_T, vec2 uv TFI_X, tf_Sampler s)
{
    return tf_cubic_level(TFI_A, uv TFI_XA, 0, s.wrap, TF_RECONSTRUCT_BSPLINE);
}
vec4 tf_catmull_rom(TFI_T, vec2 uv TFI_X, tf_Sampler s)
{
    return tf_cubic_level(TFI_A, uv TFI_XA, 0, s.wrap, TF_RECONSTRUCT_CATMULL_ROM);
}
#endif

#if TFI_HW && !TFI_ENV
vec4 tf_bspline_hw(TFI_T, vec2 uv TFI_X, tf_Sampler s)
{
    return tf_cubic_level_hw(TFI_A, uv TFI_XA, 0, s.wrap, TF_RECONSTRUCT_BSPLINE);
}
vec4 tf_catmull_rom_hw(TFI_T, vec2 uv TFI_X, tf_Sampler s)
{
    return tf_cubic_level_hw(TFI_A, uv TFI_XA, 0, s.wrap, TF_RECONSTRUCT_CATMULL_ROM);
}
#endif
