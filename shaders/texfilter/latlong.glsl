// texfilter/latlong.glsl — lat-long (equirectangular) environment lookups by direction: nearest, bilinear,
// bicubic, trilinear, aniso, EWA and the stochastic forms, across the u = 0/1 seam and the poles, with the
// footprint from the mapping's Jacobian (docs/ENVIRONMENT.md; host/reference/environment.cpp is its CPU twin).
//
// Use:     vec4 tf_trilinear_latlong(sampler2D tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s);
//          vec4 tf_aniso_latlong(sampler2D tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes,
//                                int shape);
//          vec4 tf_ewa_latlong(sampler2D tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha,
//                              float maxAniso);
//          and the 2D families' other forms with the 2D name + _latlong, as cube.glsl lists them (nearest,
//          bilinear, bspline, catmull_rom, nearest_mip, bilinear_mip, the _hw forms, the stochastic forms with
//          vec3 xi last). tf_LatLongLookup tf_latlong_lookup(vec3 dir, vec3 dDirdx, vec3 dDirdy): the uv and
//          uv gradients. No TF_SOURCE form. The prototype list below. The 2D families also take
//          (sampler2D tex, vec2 uv, tf_LatLong latlong, ...): a lat-long map filtered in uv (their files' lists).
// Math:    +y up: u = ½ + atan(d.x, −d.z)/2π, v = acos(d.y/|d|)/π (computed as atan(ρ, d.y)/π); the gradients
//          are the mapping's Jacobian times the direction derivatives (never a difference of uv: no seam at
//          u = 0/1); then the 2D family of the same name, columns repeating and rows past a pole read from the
//          other side, half a turn round. _hw taps: the sampler repeats in u and clamps in v, so they do not
//          cross a pole.
// Options: s.lodBias, s.lodMin, s.lodMax and each family's own; s.wrap is ignored. TF_MAGNIFY (common.glsl)
//          applies to tf_trilinear_latlong, tf_aniso_latlong(_hw), tf_ewa_latlong(_hw).
// Needs:   a sampler2D (TF_RESOURCE_LATLONG) with a full MIP chain; manual forms read it with texelFetch,
//          _hw forms through its sampler (LINEAR, repeat in u, clamp in v, no bias).
// Cost:    the 2D family's (trilinear 8 texel fetches, stochastic forms 1, ...) plus two atans and a sqrt.
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

// BEGIN prototypes (generated: tests/prototypes.py --write; ctest prototypes.current checks it)
// Every overload below is defined by this file's detail/*_kind.glsl for the kinds its #if names.
#if (TF_RESOURCES & TF_RESOURCE_LATLONG) != 0
vec4 tf_aniso_latlong(sampler2D tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_latlong_hw(sampler2D tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_stochastic_latlong(sampler2D tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_aniso_stochastic_latlong_hw(sampler2D tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_bilinear_latlong(sampler2D tex, vec3 dir, tf_Sampler s);
vec4 tf_bilinear_mip_latlong(sampler2D tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s);
vec4 tf_bilinear_stochastic_latlong(sampler2D tex, vec3 dir, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic_latlong_hw(sampler2D tex, vec3 dir, tf_Sampler s, vec3 xi);
vec4 tf_bspline_latlong(sampler2D tex, vec3 dir, tf_Sampler s);
vec4 tf_bspline_latlong_hw(sampler2D tex, vec3 dir, tf_Sampler s);
vec4 tf_catmull_rom_latlong(sampler2D tex, vec3 dir, tf_Sampler s);
vec4 tf_catmull_rom_latlong_hw(sampler2D tex, vec3 dir, tf_Sampler s);
vec4 tf_ewa_latlong(sampler2D tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_latlong_hw(sampler2D tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_stochastic_latlong(sampler2D tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_ewa_stochastic_latlong_hw(sampler2D tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_nearest_latlong(sampler2D tex, vec3 dir, tf_Sampler s);
vec4 tf_nearest_mip_latlong(sampler2D tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s);
vec4 tf_trilinear_latlong(sampler2D tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s);
vec4 tf_trilinear_stochastic_latlong(sampler2D tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, vec3 xi);
vec4 tf_trilinear_stochastic_latlong_hw(sampler2D tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, vec3 xi);
#endif
// END prototypes

#define TFI_FAMILY TFI_FAMILY_LATLONG
#include "detail/instantiate.glsl"
#undef TFI_FAMILY

#endif
