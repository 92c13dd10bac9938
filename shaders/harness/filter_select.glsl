// Harness only: runs the filter chosen at run time (push constant) through the texfilter includes,
// or the hardware sampler through textureGrad with the same gradients. Counts texel fetches and
// hardware lookups through the includes' TF_COUNT_* hooks (for `sample --stats`).
#ifndef HARNESS_FILTER_SELECT_GLSL
#define HARNESS_FILTER_SELECT_GLSL

#include "config.h"

uint fetchCount = 0u;
uint hwLookupCount = 0u;
#define TF_COUNT_FETCHES(n) fetchCount += uint(n)
#define TF_COUNT_HW_LOOKUPS(n) hwLookupCount += uint(n)

#ifndef HARNESS_RESOURCE
#define HARNESS_RESOURCE HARNESS_RESOURCE_COMBINED
#endif
// Only the resource kinds this variant binds are instantiated (compile time); the SAT's usampler2D tables
// come with TF_RESOURCE_SAMPLER_2D.
#if HARNESS_RESOURCE == HARNESS_RESOURCE_SEPARATE
#define TF_RESOURCES TF_RESOURCE_TEXTURE_2D
#elif HARNESS_RESOURCE == HARNESS_RESOURCE_ARRAY
#define TF_RESOURCES TF_RESOURCE_SAMPLER_2D_ARRAY
#elif HARNESS_RESOURCE == HARNESS_RESOURCE_SEPARATE_ARRAY
#define TF_RESOURCES TF_RESOURCE_TEXTURE_2D_ARRAY
#elif HARNESS_RESOURCE == HARNESS_RESOURCE_UINT || HARNESS_RESOURCE == HARNESS_RESOURCE_SINT
#define TF_RESOURCES (TF_RESOURCE_SAMPLER_2D | TF_RESOURCE_INTEGER)
#elif HARNESS_RESOURCE == HARNESS_RESOURCE_SHADOW
#define TF_RESOURCES (TF_RESOURCE_SAMPLER_2D | TF_RESOURCE_SHADOW)
#elif HARNESS_RESOURCE == HARNESS_RESOURCE_ATLAS || HARNESS_RESOURCE == HARNESS_RESOURCE_VIRTUAL
#define TF_RESOURCES 0 // the TF_SOURCE kind only (texel_sources.glsl)
#else
#define TF_RESOURCES TF_RESOURCE_SAMPLER_2D
#endif
#if HARNESS_RESOURCE == HARNESS_RESOURCE_BINDLESS
#extension GL_EXT_nonuniform_qualifier : require
#define TF_NONUNIFORM nonuniformEXT // every image instruction in the includes: the index is divergent
#endif
#include "push_constants.glsl"    // before the includes: TF_MAGNIFY reads MAGNIFY_ID
#define TF_MAGNIFY MAGNIFY_ID
#if HARNESS_RESOURCE == HARNESS_RESOURCE_ATLAS || HARNESS_RESOURCE == HARNESS_RESOURCE_VIRTUAL
#include "texel_sources.glsl" // TF_SOURCE and its functions, before the includes
#endif
#include "texfilter/texfilter.glsl"
#include "texfilter/debug.glsl"
#include "stochastic_noise.glsl"

// The options the host passes through unchanged are the includes' own ids.
#if HARNESS_WRAP_REPEAT != TF_WRAP_REPEAT || HARNESS_WRAP_CLAMP != TF_WRAP_CLAMP || \
    HARNESS_WRAP_MIRROR != TF_WRAP_MIRROR
#error "config.h: HARNESS_WRAP_* must equal texfilter's TF_WRAP_*"
#endif
#if HARNESS_ANISO_GPU != TF_ANISO_GPU || HARNESS_ANISO_FELINE != TF_ANISO_FELINE
#error "config.h: HARNESS_ANISO_* must equal texfilter's TF_ANISO_*"
#endif
#if HARNESS_TAPS_MANUAL != TF_TAPS_MANUAL || HARNESS_TAPS_HARDWARE != TF_TAPS_HARDWARE
#error "config.h: HARNESS_TAPS_* must equal texfilter's TF_TAPS_*"
#endif
#if HARNESS_RECONSTRUCT_BILINEAR != TF_RECONSTRUCT_BILINEAR || HARNESS_RECONSTRUCT_BSPLINE != TF_RECONSTRUCT_BSPLINE || \
    HARNESS_RECONSTRUCT_CATMULL_ROM != TF_RECONSTRUCT_CATMULL_ROM
#error "config.h: HARNESS_RECONSTRUCT_* must equal texfilter's TF_RECONSTRUCT_*"
#endif

// The texture as HARNESS_RESOURCE binds it (config.h), and how harness_filter passes it to the includes:
// HARNESS_TEX / HARNESS_X the texture and the extras after uv for the manual forms, HARNESS_TEX_HW /
// HARNESS_X_HW for the _hw forms (none for integer data), HARNESS_SAT / HARNESS_SAT_X the SAT's tables,
// HARNESS_GRAD the hw-* modes' lookup, HARNESS_SIZE0 / HARNESS_LEVELS the queries of the debug views. The
// texel-source kinds (atlas, virtual) pass a TF_SOURCE value (texel_sources.glsl) where the others pass a texture.
// sample's lookup index (bindless: which texture a lookup reads); 0 in render.
uint harnessLookupIndex = 0u;
// render's pixel (--stochastic: the random numbers are a function of pixel, frame and lookup); (0, 0) in sample.
ivec2 harnessPixel = ivec2(0);

#if HARNESS_RESOURCE == HARNESS_RESOURCE_COMBINED || HARNESS_RESOURCE == HARNESS_RESOURCE_BINDLESS || \
    HARNESS_RESOURCE == HARNESS_RESOURCE_UINT || HARNESS_RESOURCE == HARNESS_RESOURCE_SINT || \
    HARNESS_RESOURCE == HARNESS_RESOURCE_SHADOW
layout(set = 0, binding = HARNESS_BINDING_SAT_LOW) uniform usampler2D u_satLow;
layout(set = 0, binding = HARNESS_BINDING_SAT_HIGH) uniform usampler2D u_satHigh;
#define HARNESS_SAT_X
#endif

#if HARNESS_RESOURCE == HARNESS_RESOURCE_COMBINED
layout(set = 0, binding = HARNESS_BINDING_TEXTURE) uniform sampler2D u_texture;
#define HARNESS_TEX u_texture
#define HARNESS_X
#define HARNESS_TEX_HW u_texture
#define HARNESS_X_HW
#define HARNESS_GRAD(uv, dx, dy) textureGrad(u_texture, uv, dx, dy)
#define HARNESS_SIZE0 textureSize(u_texture, 0)
#define HARNESS_LEVELS textureQueryLevels(u_texture)
#elif HARNESS_RESOURCE == HARNESS_RESOURCE_SEPARATE
layout(set = 0, binding = HARNESS_BINDING_TEXTURE) uniform texture2D u_image;
layout(set = 0, binding = HARNESS_BINDING_SAMPLER) uniform sampler u_sampler;
layout(set = 0, binding = HARNESS_BINDING_SAT_LOW) uniform utexture2D u_satLow;
layout(set = 0, binding = HARNESS_BINDING_SAT_HIGH) uniform utexture2D u_satHigh;
#define HARNESS_SAT_X
#define HARNESS_TEX u_image
#define HARNESS_X
#define HARNESS_TEX_HW u_image, u_sampler
#define HARNESS_X_HW
#ifdef __SLANG__ // no sampler2D(texture, sampler) nor samplerless queries there: the texture's own methods
#define HARNESS_GRAD(uv, dx, dy) u_image.SampleGrad(u_sampler, uv, dx, dy)
ivec3 harness_image_size0()
{
    uint w, h, levels;
    u_image.GetDimensions(0u, w, h, levels);
    return ivec3(int(w), int(h), int(levels));
}
#define HARNESS_SIZE0 harness_image_size0().xy
#define HARNESS_LEVELS harness_image_size0().z
#else
#define HARNESS_GRAD(uv, dx, dy) textureGrad(sampler2D(u_image, u_sampler), uv, dx, dy)
#define HARNESS_SIZE0 textureSize(u_image, 0)
#define HARNESS_LEVELS textureQueryLevels(u_image)
#endif
#elif HARNESS_RESOURCE == HARNESS_RESOURCE_ARRAY
layout(set = 0, binding = HARNESS_BINDING_TEXTURE) uniform sampler2DArray u_texture;
layout(set = 0, binding = HARNESS_BINDING_SAT_LOW) uniform usampler2DArray u_satLow;
layout(set = 0, binding = HARNESS_BINDING_SAT_HIGH) uniform usampler2DArray u_satHigh;
#define HARNESS_SAT_X , pc.layer
#define HARNESS_TEX u_texture
#define HARNESS_X , pc.layer
#define HARNESS_TEX_HW u_texture
#define HARNESS_X_HW , pc.layer
#define HARNESS_GRAD(uv, dx, dy) textureGrad(u_texture, vec3(uv, float(pc.layer)), dx, dy)
#define HARNESS_SIZE0 textureSize(u_texture, 0).xy
#define HARNESS_LEVELS textureQueryLevels(u_texture)
#elif HARNESS_RESOURCE == HARNESS_RESOURCE_SEPARATE_ARRAY
layout(set = 0, binding = HARNESS_BINDING_TEXTURE) uniform texture2DArray u_image;
layout(set = 0, binding = HARNESS_BINDING_SAMPLER) uniform sampler u_sampler;
layout(set = 0, binding = HARNESS_BINDING_SAT_LOW) uniform utexture2DArray u_satLow;
layout(set = 0, binding = HARNESS_BINDING_SAT_HIGH) uniform utexture2DArray u_satHigh;
#define HARNESS_SAT_X , pc.layer
#define HARNESS_TEX u_image
#define HARNESS_X , pc.layer
#define HARNESS_TEX_HW u_image, u_sampler
#define HARNESS_X_HW , pc.layer
#ifdef __SLANG__ // as the separate kind's
#define HARNESS_GRAD(uv, dx, dy) u_image.SampleGrad(u_sampler, vec3(uv, float(pc.layer)), dx, dy)
ivec3 harness_image_size0()
{
    uint w, h, layers, levels;
    u_image.GetDimensions(0u, w, h, layers, levels);
    return ivec3(int(w), int(h), int(levels));
}
#define HARNESS_SIZE0 harness_image_size0().xy
#define HARNESS_LEVELS harness_image_size0().z
#else
#define HARNESS_GRAD(uv, dx, dy) textureGrad(sampler2DArray(u_image, u_sampler), vec3(uv, float(pc.layer)), dx, dy)
#define HARNESS_SIZE0 textureSize(u_image, 0).xy
#define HARNESS_LEVELS textureQueryLevels(u_image)
#endif
#elif HARNESS_RESOURCE == HARNESS_RESOURCE_BINDLESS
layout(set = 0, binding = HARNESS_BINDING_TEXTURE) uniform sampler2D u_textures[HARNESS_BINDLESS_COUNT];
#define HARNESS_INDEX ((uint(pc.layer) + harnessLookupIndex) % uint(HARNESS_BINDLESS_COUNT))
#define HARNESS_TEX u_textures[nonuniformEXT(HARNESS_INDEX)]
#define HARNESS_X
#define HARNESS_TEX_HW HARNESS_TEX
#define HARNESS_X_HW
#define HARNESS_GRAD(uv, dx, dy) textureGrad(HARNESS_TEX, uv, dx, dy)
#define HARNESS_SIZE0 textureSize(HARNESS_TEX, 0)
#define HARNESS_LEVELS textureQueryLevels(HARNESS_TEX)
#elif HARNESS_RESOURCE == HARNESS_RESOURCE_UINT || HARNESS_RESOURCE == HARNESS_RESOURCE_SINT
#if HARNESS_RESOURCE == HARNESS_RESOURCE_UINT
layout(set = 0, binding = HARNESS_BINDING_TEXTURE) uniform usampler2D u_texture;
#else
layout(set = 0, binding = HARNESS_BINDING_TEXTURE) uniform isampler2D u_texture;
#endif
#define HARNESS_TEX u_texture
#define HARNESS_X
#define HARNESS_GRAD(uv, dx, dy) vec4(0.0) // integer formats cannot be filtered: the host refuses hw-*
#define HARNESS_SIZE0 textureSize(u_texture, 0)
#define HARNESS_LEVELS textureQueryLevels(u_texture)
#elif HARNESS_RESOURCE == HARNESS_RESOURCE_SHADOW
layout(set = 0, binding = HARNESS_BINDING_TEXTURE) uniform texture2D u_image;
layout(set = 0, binding = HARNESS_BINDING_SAMPLER) uniform samplerShadow u_sampler;
#define HARNESS_TEX u_image
#define HARNESS_X , tf_compare(pc.compareOp, pc.dref)
#define HARNESS_TEX_HW u_image, u_sampler
#define HARNESS_X_HW , pc.dref
#define HARNESS_GRAD(uv, dx, dy) vec4(textureGrad(sampler2DShadow(u_image, u_sampler), vec3(uv, pc.dref), dx, dy))
#define HARNESS_SIZE0 textureSize(u_image, 0)
#define HARNESS_LEVELS textureQueryLevels(u_image)
#elif HARNESS_RESOURCE == HARNESS_RESOURCE_ATLAS || HARNESS_RESOURCE == HARNESS_RESOURCE_VIRTUAL
// The includes' TF_SOURCE overloads (texel_sources.glsl): manual taps only, so no HARNESS_TEX_HW (the host
// refuses --taps hardware); hw-* sample the atlas at the tile's uv (virtual: refused by the host).
#define HARNESS_TEX harness_source()
#define HARNESS_X
#define HARNESS_GRAD(uv, dx, dy) harness_source_grad(uv, dx, dy)
#define HARNESS_SIZE0 tf_source_size(harness_source(), 0)
#define HARNESS_LEVELS tf_source_levels(harness_source())
#else
#error "HARNESS_RESOURCE: unknown resource kind"
#endif

// --stochastic: the one-texel (or one-tap) forms of stochastic.glsl, xi from stochastic_noise.glsl. Only in
// pipelines specialised with STOCHASTIC_ID 1 (the host allows it on bilinear, trilinear, aniso and ewa).
vec4 harness_filter_stochastic(vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s, bool hardwareTaps)
{
    vec3 xi = stochastic_xi(pc.stochastic, harnessPixel, harnessLookupIndex);
    switch (FILTER_ID) {
#ifdef HARNESS_TEX_HW
    case HARNESS_FILTER_BILINEAR:
        return hardwareTaps ? tf_bilinear_stochastic_hw(HARNESS_TEX_HW, uv HARNESS_X_HW, s, xi)
                            : tf_bilinear_stochastic(HARNESS_TEX, uv HARNESS_X, s, xi);
    case HARNESS_FILTER_TRILINEAR:
        return hardwareTaps ? tf_trilinear_stochastic_hw(HARNESS_TEX_HW, uv HARNESS_X_HW, dUVdx, dUVdy, s, xi)
                            : tf_trilinear_stochastic(HARNESS_TEX, uv HARNESS_X, dUVdx, dUVdy, s, xi);
    case HARNESS_FILTER_ANISO:
        return hardwareTaps
                   ? tf_aniso_stochastic_hw(HARNESS_TEX_HW, uv HARNESS_X_HW, dUVdx, dUVdy, s, pc.probes, pc.anisoShape, xi)
                   : tf_aniso_stochastic(HARNESS_TEX, uv HARNESS_X, dUVdx, dUVdy, s, pc.probes, pc.anisoShape, xi);
    case HARNESS_FILTER_EWA:
        return hardwareTaps ? tf_ewa_stochastic_hw(HARNESS_TEX_HW, uv HARNESS_X_HW, dUVdx, dUVdy, s, pc.alpha, pc.maxAniso, xi)
                            : tf_ewa_stochastic(HARNESS_TEX, uv HARNESS_X, dUVdx, dUVdy, s, pc.alpha, pc.maxAniso, xi);
#else
    case HARNESS_FILTER_BILINEAR: return tf_bilinear_stochastic(HARNESS_TEX, uv HARNESS_X, s, xi);
    case HARNESS_FILTER_TRILINEAR: return tf_trilinear_stochastic(HARNESS_TEX, uv HARNESS_X, dUVdx, dUVdy, s, xi);
    case HARNESS_FILTER_ANISO:
        return tf_aniso_stochastic(HARNESS_TEX, uv HARNESS_X, dUVdx, dUVdy, s, pc.probes, pc.anisoShape, xi);
    case HARNESS_FILTER_EWA:
        return tf_ewa_stochastic(HARNESS_TEX, uv HARNESS_X, dUVdx, dUVdy, s, pc.alpha, pc.maxAniso, xi);
#endif
    default: return vec4(0.0); // refused by the host
    }
}

// The frame's lookups go through the hardware sampler (hw-*, or a filter's --taps hardware): uniform.
bool harness_hardware_lookups()
{
    return (FILTER_ID >= HARNESS_FILTER_HW_NEAREST && FILTER_ID <= HARNESS_FILTER_HW_ANISO) ||
           (FILTER_ID != HARNESS_FILTER_NONE && pc.taps == TF_TAPS_HARDWARE);
}

vec4 harness_filter(vec2 uv, vec2 dUVdx, vec2 dUVdy)
{
    tf_Sampler s = tf_Sampler(pc.wrapMode, pc.lodBias, pc.lodMin, pc.lodMax);
    bool hardwareTaps = pc.taps == TF_TAPS_HARDWARE;
    if (STOCHASTIC_ID != 0)
        return harness_filter_stochastic(uv, dUVdx, dUVdy, s, hardwareTaps);
    switch (FILTER_ID) {
    case HARNESS_FILTER_NEAREST: return tf_nearest(HARNESS_TEX, uv HARNESS_X, s);
    case HARNESS_FILTER_BILINEAR: return tf_bilinear(HARNESS_TEX, uv HARNESS_X, s);
    case HARNESS_FILTER_TRILINEAR: return tf_trilinear(HARNESS_TEX, uv HARNESS_X, dUVdx, dUVdy, s);
    case HARNESS_FILTER_NEAREST_MIP: return tf_nearest_mip(HARNESS_TEX, uv HARNESS_X, dUVdx, dUVdy, s);
    case HARNESS_FILTER_BILINEAR_MIP: return tf_bilinear_mip(HARNESS_TEX, uv HARNESS_X, dUVdx, dUVdy, s);
    case HARNESS_FILTER_BRILINEAR: return tf_brilinear(HARNESS_TEX, uv HARNESS_X, dUVdx, dUVdy, s, pc.band);
#ifdef HARNESS_TEX_HW
    case HARNESS_FILTER_ANISO:
        return hardwareTaps ? tf_aniso_hw(HARNESS_TEX_HW, uv HARNESS_X_HW, dUVdx, dUVdy, s, pc.probes, pc.anisoShape)
                            : tf_aniso(HARNESS_TEX, uv HARNESS_X, dUVdx, dUVdy, s, pc.probes, pc.anisoShape);
    case HARNESS_FILTER_EWA:
        return hardwareTaps ? tf_ewa_hw(HARNESS_TEX_HW, uv HARNESS_X_HW, dUVdx, dUVdy, s, pc.alpha, pc.maxAniso)
                            : tf_ewa(HARNESS_TEX, uv HARNESS_X, dUVdx, dUVdy, s, pc.alpha, pc.maxAniso);
    case HARNESS_FILTER_EWA_FAST: return tf_ewa_fast(HARNESS_TEX_HW, uv HARNESS_X_HW, dUVdx, dUVdy, s);
    case HARNESS_FILTER_BSPLINE:
        return hardwareTaps ? tf_bspline_hw(HARNESS_TEX_HW, uv HARNESS_X_HW, s) : tf_bspline(HARNESS_TEX, uv HARNESS_X, s);
    case HARNESS_FILTER_CATMULL_ROM:
        return hardwareTaps ? tf_catmull_rom_hw(HARNESS_TEX_HW, uv HARNESS_X_HW, s)
                            : tf_catmull_rom(HARNESS_TEX, uv HARNESS_X, s);
#else // integer data: no sampler can filter it, so manual taps only (the host refuses --taps hardware)
    case HARNESS_FILTER_ANISO: return tf_aniso(HARNESS_TEX, uv HARNESS_X, dUVdx, dUVdy, s, pc.probes, pc.anisoShape);
    case HARNESS_FILTER_EWA: return tf_ewa(HARNESS_TEX, uv HARNESS_X, dUVdx, dUVdy, s, pc.alpha, pc.maxAniso);
    case HARNESS_FILTER_BSPLINE: return tf_bspline(HARNESS_TEX, uv HARNESS_X, s);
    case HARNESS_FILTER_CATMULL_ROM: return tf_catmull_rom(HARNESS_TEX, uv HARNESS_X, s);
#endif
#ifdef HARNESS_SAT_X
    case HARNESS_FILTER_SAT:
        return tf_sat(u_satLow, u_satHigh, uv HARNESS_SAT_X, dUVdx, dUVdy, s, pc.satOffset, pc.satScale);
    case HARNESS_FILTER_SAT_ASSEMBLY:
        return tf_sat_assembly(u_satLow, u_satHigh, uv HARNESS_SAT_X, dUVdx, dUVdy, s, pc.satOffset, pc.satScale,
                               pc.boxes);
#endif
    case HARNESS_FILTER_NONE: // the scene without the texture, its gradients made too: the baseline cost
        return vec4(fract(uv), tf_finite(dUVdx) && tf_finite(dUVdy) ? 0.5 : 0.0, 1.0);
    case HARNESS_FILTER_GROUND_TRUTH: return vec4(0.0);         // per pixel, not per lookup: see ground_truth.glsl
    default:
        TF_COUNT_HW_LOOKUPS(1);
        return HARNESS_GRAD(uv, dUVdx, dUVdy); // hw-*: sampler state set by the host
    }
}

// What a render pixel shows (VIEW_ID, a specialization constant): the filtered colour, or a debug view of its lookup (texfilter/
// debug.glsl). The filter always runs, so the fetches are this lookup's; the LOD is the one its family
// samples at. The host refuses views for ground-truth and none (no lookup).
vec4 harness_shade(vec2 uv, vec2 dUVdx, vec2 dUVdy)
{
    dUVdx *= pc.gradientScale; // exact at 1
    dUVdy *= pc.gradientScale;
    vec4 color = harness_filter(uv, dUVdx, dUVdy);
    // bench --lookups-per-pixel: more lookups at points of an R2 sequence over the pixel (offsets in (-½, ½)
    // pixels), each its own work the compiler cannot merge; their mean is shown.
    for (int k = 1; k < LOOKUPS_ID; ++k) {
        vec2 o = fract(vec2(0.5) + float(k) * vec2(0.7548776662, 0.5698402910)) - 0.5;
        color += harness_filter(uv + o.x * dUVdx + o.y * dUVdy, dUVdx, dUVdy);
    }
    color /= float(LOOKUPS_ID);
    if (VIEW_ID == HARNESS_VIEW_COLOR)
        return color;
    int family = FILTER_ID == HARNESS_FILTER_ANISO ? TF_DEBUG_ANISO
                 : FILTER_ID == HARNESS_FILTER_EWA ? TF_DEBUG_EWA
                                                   : TF_DEBUG_ISOTROPIC;
    tf_Sampler s = tf_Sampler(pc.wrapMode, pc.lodBias, pc.lodMin, pc.lodMax);
    tf_Footprint f = tf_debug_footprint(uv, dUVdx, dUVdy, vec2(HARNESS_SIZE0), HARNESS_LEVELS, s, family, pc.probes,
                                        pc.anisoShape,
                                        pc.maxAniso);
    float work = float(fetchCount + hwLookupCount);
    switch (VIEW_ID) {
    case HARNESS_VIEW_LOD: return vec4(tf_debug_lod_color(f.lod), 1.0);
    case HARNESS_VIEW_ANISOTROPY: return vec4(tf_debug_anisotropy_color(f.ratio), 1.0);
    case HARNESS_VIEW_FETCHES: return vec4(tf_debug_heat(work, HARNESS_VIEW_FETCHES_MAX), 1.0);
    default: return vec4(f.lod, f.ratio, work, 1.0);
    }
}

#endif
