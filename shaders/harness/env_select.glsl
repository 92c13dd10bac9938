// Harness only: the environment-map twin of filter_select.glsl. Binds the cube or lat-long map the variant
// was built for (-DHARNESS_ENV, config.h), runs the filter chosen by the specialization constant through
// texfilter/cube.glsl or latlong.glsl, or the hardware sampler through textureGrad, and integrates the ground
// truth over the pixel's directions.
#ifndef HARNESS_ENV_SELECT_GLSL
#define HARNESS_ENV_SELECT_GLSL

#include "config.h"

uint fetchCount = 0u;
uint hwLookupCount = 0u;
#define TF_COUNT_FETCHES(n) fetchCount += uint(n)
#define TF_COUNT_HW_LOOKUPS(n) hwLookupCount += uint(n)

#include "push_constants.glsl" // before the includes: TF_MAGNIFY reads MAGNIFY_ID
#define TF_MAGNIFY MAGNIFY_ID
#include "stochastic_noise.glsl"

// render's pixel (--stochastic: the random numbers are a function of pixel, frame and lookup 0, as in 2D).
ivec2 harnessPixel = ivec2(0);

#if HARNESS_ENV == HARNESS_ENV_CUBE
#define TF_RESOURCES TF_RESOURCE_CUBE
#include "texfilter/cube.glsl"
layout(set = 0, binding = HARNESS_BINDING_TEXTURE) uniform samplerCube u_env;               // LINEAR (or hw-*)
layout(set = 0, binding = HARNESS_BINDING_TEXTURE_NEAREST) uniform samplerCube u_envNearest; // NEAREST
#define HARNESS_ENV_MANUAL u_envNearest
#define HARNESS_ENV_HW u_env
#elif HARNESS_ENV == HARNESS_ENV_LATLONG
#define TF_RESOURCES TF_RESOURCE_LATLONG
#include "texfilter/latlong.glsl"
layout(set = 0, binding = HARNESS_BINDING_TEXTURE) uniform sampler2D u_env; // texelFetch ignores the sampler
#define HARNESS_ENV_MANUAL u_env
#define HARNESS_ENV_HW u_env
#else
#error "HARNESS_ENV: HARNESS_ENV_CUBE or HARNESS_ENV_LATLONG"
#endif

#if HARNESS_ENV == HARNESS_ENV_CUBE
#define HARNESS_ENV_CALL(name) name##_cube
#define HARNESS_ENV_CALL_HW(name) name##_cube_hw
vec4 harness_env_grad(vec3 d, vec3 dx, vec3 dy) { return textureGrad(u_env, d, dx, dy); }
#else
#define HARNESS_ENV_CALL(name) name##_latlong
#define HARNESS_ENV_CALL_HW(name) name##_latlong_hw
vec4 harness_env_grad(vec3 d, vec3 dx, vec3 dy)
{
    tf_LatLongLookup l = tf_latlong_lookup(d, dx, dy);
    return l.valid ? textureGrad(u_env, l.uv, l.dUVdx, l.dUVdy) : vec4(0.0);
}
#endif

// --stochastic: the one-texel (or one-tap) forms, only in pipelines specialised with STOCHASTIC_ID 1.
vec4 harness_env_filter_stochastic(vec3 d, vec3 dx, vec3 dy, tf_Sampler s, bool hardwareTaps)
{
    vec3 xi = stochastic_xi(pc.stochastic, harnessPixel, 0u);
    switch (FILTER_ID) {
    case HARNESS_FILTER_BILINEAR:
        return hardwareTaps ? HARNESS_ENV_CALL_HW(tf_bilinear_stochastic)(HARNESS_ENV_HW, d, s, xi)
                            : HARNESS_ENV_CALL(tf_bilinear_stochastic)(HARNESS_ENV_MANUAL, d, s, xi);
    case HARNESS_FILTER_TRILINEAR:
        return hardwareTaps ? HARNESS_ENV_CALL_HW(tf_trilinear_stochastic)(HARNESS_ENV_HW, d, dx, dy, s, xi)
                            : HARNESS_ENV_CALL(tf_trilinear_stochastic)(HARNESS_ENV_MANUAL, d, dx, dy, s, xi);
    case HARNESS_FILTER_ANISO:
        return hardwareTaps
                   ? HARNESS_ENV_CALL_HW(tf_aniso_stochastic)(HARNESS_ENV_HW, d, dx, dy, s, pc.probes, pc.anisoShape, xi)
                   : HARNESS_ENV_CALL(tf_aniso_stochastic)(HARNESS_ENV_MANUAL, d, dx, dy, s, pc.probes, pc.anisoShape, xi);
    case HARNESS_FILTER_EWA:
        return hardwareTaps
                   ? HARNESS_ENV_CALL_HW(tf_ewa_stochastic)(HARNESS_ENV_HW, d, dx, dy, s, pc.alpha, pc.maxAniso, xi)
                   : HARNESS_ENV_CALL(tf_ewa_stochastic)(HARNESS_ENV_MANUAL, d, dx, dy, s, pc.alpha, pc.maxAniso, xi);
    default: return vec4(0.0); // refused by the host
    }
}

vec4 harness_env_filter(vec3 d, vec3 dx, vec3 dy)
{
    tf_Sampler s = tf_Sampler(pc.wrapMode, pc.lodBias, pc.lodMin, pc.lodMax);
    bool hardwareTaps = pc.taps == TF_TAPS_HARDWARE;
    if (STOCHASTIC_ID != 0)
        return harness_env_filter_stochastic(d, dx, dy, s, hardwareTaps);
    switch (FILTER_ID) {
    case HARNESS_FILTER_NEAREST: return HARNESS_ENV_CALL(tf_nearest)(HARNESS_ENV_MANUAL, d, s);
    case HARNESS_FILTER_BILINEAR: return HARNESS_ENV_CALL(tf_bilinear)(HARNESS_ENV_MANUAL, d, s);
    case HARNESS_FILTER_BSPLINE:
        return hardwareTaps ? HARNESS_ENV_CALL_HW(tf_bspline)(HARNESS_ENV_HW, d, s)
                            : HARNESS_ENV_CALL(tf_bspline)(HARNESS_ENV_MANUAL, d, s);
    case HARNESS_FILTER_CATMULL_ROM:
        return hardwareTaps ? HARNESS_ENV_CALL_HW(tf_catmull_rom)(HARNESS_ENV_HW, d, s)
                            : HARNESS_ENV_CALL(tf_catmull_rom)(HARNESS_ENV_MANUAL, d, s);
    case HARNESS_FILTER_NEAREST_MIP: return HARNESS_ENV_CALL(tf_nearest_mip)(HARNESS_ENV_MANUAL, d, dx, dy, s);
    case HARNESS_FILTER_BILINEAR_MIP: return HARNESS_ENV_CALL(tf_bilinear_mip)(HARNESS_ENV_MANUAL, d, dx, dy, s);
    case HARNESS_FILTER_TRILINEAR: return HARNESS_ENV_CALL(tf_trilinear)(HARNESS_ENV_MANUAL, d, dx, dy, s);
    case HARNESS_FILTER_ANISO:
        return hardwareTaps ? HARNESS_ENV_CALL_HW(tf_aniso)(HARNESS_ENV_HW, d, dx, dy, s, pc.probes, pc.anisoShape)
                            : HARNESS_ENV_CALL(tf_aniso)(HARNESS_ENV_MANUAL, d, dx, dy, s, pc.probes, pc.anisoShape);
    case HARNESS_FILTER_EWA:
        return hardwareTaps ? HARNESS_ENV_CALL_HW(tf_ewa)(HARNESS_ENV_HW, d, dx, dy, s, pc.alpha, pc.maxAniso)
                            : HARNESS_ENV_CALL(tf_ewa)(HARNESS_ENV_MANUAL, d, dx, dy, s, pc.alpha, pc.maxAniso);
    case HARNESS_FILTER_NONE: return vec4(0.5 * normalize(d) + 0.5, 1.0); // no texture: the baseline cost
    case HARNESS_FILTER_GROUND_TRUTH: return vec4(0.0); // per pixel: env_ground_truth
    default:
        TF_COUNT_HW_LOOKUPS(1);
        return harness_env_grad(d, dx, dy); // hw-*: the sampler state set by the host
    }
}

// Level 0, bilinear, seamless (cube) or across the seam and poles (lat-long): what the truth integrates.
vec4 harness_env_level0(vec3 d)
{
    return HARNESS_ENV_CALL(tf_bilinear)(HARNESS_ENV_MANUAL, d, tf_sampler(TF_WRAP_CLAMP));
}

#endif
