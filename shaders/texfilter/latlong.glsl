// texfilter/latlong.glsl — lat-long (equirectangular) environment lookups by direction: nearest, bilinear,
// trilinear, aniso and EWA, wrapping at the u = 0/1 seam and across the poles, with the footprint from the
// Jacobian of the mapping (docs/ENVIRONMENT.md; host/reference/environment.cpp is its CPU twin).
//
// Use:     vec4 tf_trilinear_latlong(sampler2D tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s);
//          vec4 tf_aniso_latlong(sampler2D tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes,
//                                int shape);
//          vec4 tf_ewa_latlong(sampler2D tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha,
//                              float maxAniso);
//          also tf_nearest_latlong / tf_bilinear_latlong (tex, dir, s: level 0), tf_nearest_mip_latlong /
//          tf_bilinear_mip_latlong (tex, dir, dDirdx, dDirdy, s), tf_bspline_latlong / tf_catmull_rom_latlong (tex,
//          dir, s: level 0 through bicubic.glsl's cubics, 16 texel fetches, across the seam and the poles as every
//          manual form), tf_aniso_latlong_hw / tf_ewa_latlong_hw / tf_bspline_latlong_hw /
//          tf_catmull_rom_latlong_hw (hardware taps, 4 for the B-spline and 9 for Catmull-Rom: the sampler
//          repeats in u and clamps in v, so these do not cross a pole). Stochastic forms (stochastic.glsl, the
//          caller's vec3 xi appended last): tf_bilinear_stochastic_latlong, tf_trilinear_stochastic_latlong,
//          tf_aniso_stochastic_latlong, tf_ewa_stochastic_latlong and their _hw forms, the cube's parameters
//          (cube.glsl). TF_MAGNIFY (common.glsl) applies to
//          tf_trilinear_latlong, tf_aniso_latlong(_hw) and tf_ewa_latlong(_hw) as to their 2D families.
//          tf_LatLongLookup tf_latlong_lookup(vec3 dir, vec3 dDirdx, vec3 dDirdy): the uv and uv gradients.
// Math:    +y up: u = ½ + atan(d.x, −d.z)/2π, v = acos(d.y/|d|)/π (computed as atan(ρ, d.y)/π); the gradients are the mapping's Jacobian
//          times the direction derivatives (never a difference of uv, so no seam at u = 0/1); then the 2D
//          family of the same name, its texels read with columns repeating and rows past a pole taken from
//          the other side, half a turn round. s.wrap is ignored.
// Needs:   a sampler2D (TF_RESOURCE_LATLONG) with a full MIP chain; manual forms read it with texelFetch.
// Options: s.lodBias, s.lodMin, s.lodMax, each family's own. No defines.
// Cost:    the 2D family's (trilinear 8 texel fetches, stochastic forms 1, ...), plus two atans and a sqrt.
// Degenerate input: a zero or non-finite dir gives vec4(0); at a pole itself (d.x = d.z = 0) the u gradient is
//          infinite: the coarsest level, as for any non-finite footprint.
// Example: vec4 c = tf_trilinear_latlong(sky, d, dFdxFine(d), dFdyFine(d), tf_sampler(TF_WRAP_REPEAT));
#ifndef TF_LATLONG_GLSL
#define TF_LATLONG_GLSL

#include "common.glsl"
#include "nearest.glsl"
#include "trilinear.glsl"
#include "aniso.glsl"
#include "ewa.glsl"
#include "stochastic.glsl"

struct tf_LatLongLookup {
    bool valid; // false for a zero or non-finite dir
    vec2 uv, dUVdx, dUVdy;
};

tf_LatLongLookup tf_latlong_lookup(vec3 dir, vec3 dDirdx, vec3 dDirdy)
{
    const float pi = 3.14159265358979;
    tf_LatLongLookup l = tf_LatLongLookup(false, vec2(0.5), vec2(0.0), vec2(0.0));
    float r2 = dot(dir, dir);
    if (any(isnan(dir)) || any(isinf(dir)) || !(r2 > 0.0))
        return l;
    l.valid = true;
    float rho2 = dir.x * dir.x + dir.z * dir.z, rho = sqrt(rho2);
    // θ = atan(ρ, y), not acos(y/|d|): acos is ill-conditioned near the poles, and GPUs approximate it more
    // loosely than atan (with acos, lavapipe missed the lat-long goldens by up to 0.0126 on 5 % of the pixels).
    // At an exact pole (x = z = 0) the longitude is any: 0 (u = ½), as the reference; GLSL leaves atan(0, 0)
    // undefined, and a NaN u would give vec4(0). Formed first so that the choice is one select.
    float longitude = atan(dir.x, -dir.z);
    l.uv = vec2(0.5 + (rho2 > 0.0 ? longitude : 0.0) / (2.0 * pi), atan(rho, dir.y) / pi);
    // du = (−z dx + x dz) / (2π ρ²), dv = −(dy − y (d·dd)/r²) / (π ρ).
    l.dUVdx = vec2((dir.x * dDirdx.z - dir.z * dDirdx.x) / (2.0 * pi * rho2),
                   -(dDirdx.y - dir.y * dot(dir, dDirdx) / r2) / (pi * rho));
    l.dUVdy = vec2((dir.x * dDirdy.z - dir.z * dDirdy.x) / (2.0 * pi * rho2),
                   -(dDirdy.y - dir.y * dot(dir, dDirdy) / r2) / (pi * rho));
    return l;
}

#define TFI_FAMILY TFI_FAMILY_LATLONG
#include "instantiate.glsl"
#undef TFI_FAMILY

#elif defined(TFI_FAMILY)
#if TFI_FAMILY == TFI_FAMILY_LATLONG && TFI_LATLONG // the lat-long kind (access.glsl)

// Each form: the uv lookup, then the 2D family with the lat-long texel rule (TFI_XA passes `latlong`).
#define TFI_LATLONG_BEGIN(dDirdx, dDirdy) \
    tf_LatLongLookup c = tf_latlong_lookup(dir, dDirdx, dDirdy); \
    if (!c.valid) \
        return vec4(0.0); \
    tfi_LatLong latlong = tfi_LatLong(0); \
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
#endif
