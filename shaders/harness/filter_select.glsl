// Harness only: runs the filter chosen at run time (push constant) through the texfilter includes,
// or the hardware sampler through textureGrad with the same gradients. Counts texel fetches and
// hardware lookups through the includes' TF_COUNT_* hooks (for `sample --stats`).
#ifndef TF_HARNESS_FILTER_SELECT_GLSL
#define TF_HARNESS_FILTER_SELECT_GLSL

#include "config.h"

uint tf_fetchCount = 0u;
uint tf_hwLookupCount = 0u;
#define TF_COUNT_FETCHES(n) tf_fetchCount += uint(n)
#define TF_COUNT_HW_LOOKUPS(n) tf_hwLookupCount += uint(n)

#include "texfilter/texfilter.glsl"

layout(set = 0, binding = TF_BINDING_TEXTURE) uniform sampler2D u_texture;
layout(set = 0, binding = TF_BINDING_SAT_LOW) uniform usampler2D u_satLow;
layout(set = 0, binding = TF_BINDING_SAT_HIGH) uniform usampler2D u_satHigh;

// The filter is a specialization constant, so each pipeline holds one filter's code: with a run-time
// switch every family's texture calls stayed in the shader, and lavapipe generated its anisotropic
// sampling code for all of them (hw-aniso renders ran ~30x slower).
layout(constant_id = TF_SPEC_FILTER) const int TF_FILTER_ID = 0;

// Mirrors tf::PushConstants (host/scene/shader_interface.h).
layout(push_constant) uniform tf_PushConstants {
    int wrapMode;
    float lodBias;
    float lodMin;
    float lodMax;
    uint count;      // sample: number of lookups
    float band;      // brilinear
    int probes;      // aniso
    int anisoShape;  // aniso: TF_ANISO_GPU / TF_ANISO_FELINE
    int taps;        // aniso, ewa: TF_TAPS_MANUAL / TF_TAPS_HARDWARE
    float alpha;     // ewa
    float maxAniso;  // ewa
    int boxes;       // sat-assembly
    int gradients;   // render: TF_GRADIENTS_FINE / COARSE / RAY
    int truthSide;   // ground-truth: side of the stratified sample grid (samples a pixel = side^2)
    int pixelFilter; // ground-truth: TF_PIXEL_FILTER_BOX / GAUSSIAN
    int padding;
    vec4 satOffset;  // sat: per channel, the value of quantisation level 0 and the span of levels 0..65535
    vec4 satScale;   //      (SatTable::offset, ::scale; see sat.glsl)
} pc;

vec4 tf_harness_filter(vec2 uv, vec2 dUVdx, vec2 dUVdy)
{
    tf_Sampler s = tf_Sampler(pc.wrapMode, pc.lodBias, pc.lodMin, pc.lodMax);
    bool hardwareTaps = pc.taps == TF_TAPS_HARDWARE;
    switch (TF_FILTER_ID) {
    case TF_FILTER_NEAREST: return tf_nearest(u_texture, uv, s);
    case TF_FILTER_BILINEAR: return tf_bilinear(u_texture, uv, s);
    case TF_FILTER_TRILINEAR: return tf_trilinear(u_texture, uv, dUVdx, dUVdy, s);
    case TF_FILTER_NEAREST_MIP: return tf_nearest_mip(u_texture, uv, dUVdx, dUVdy, s);
    case TF_FILTER_BILINEAR_MIP: return tf_bilinear_mip(u_texture, uv, dUVdx, dUVdy, s);
    case TF_FILTER_BRILINEAR: return tf_brilinear(u_texture, uv, dUVdx, dUVdy, s, pc.band);
    case TF_FILTER_ANISO:
        return hardwareTaps ? tf_aniso_hw(u_texture, uv, dUVdx, dUVdy, s, pc.probes, pc.anisoShape)
                            : tf_aniso(u_texture, uv, dUVdx, dUVdy, s, pc.probes, pc.anisoShape);
    case TF_FILTER_EWA:
        return hardwareTaps ? tf_ewa_hw(u_texture, uv, dUVdx, dUVdy, s, pc.alpha, pc.maxAniso)
                            : tf_ewa(u_texture, uv, dUVdx, dUVdy, s, pc.alpha, pc.maxAniso);
    case TF_FILTER_SAT: return tf_sat(u_satLow, u_satHigh, uv, dUVdx, dUVdy, s, pc.satOffset, pc.satScale);
    case TF_FILTER_SAT_ASSEMBLY:
        return tf_sat_assembly(u_satLow, u_satHigh, uv, dUVdx, dUVdy, s, pc.satOffset, pc.satScale, pc.boxes);
    case TF_FILTER_NONE: return vec4(fract(uv), 0.5, 1.0); // the scene without the texture: baseline cost
    case TF_FILTER_GROUND_TRUTH: return vec4(0.0);         // per pixel, not per lookup: see ground_truth.glsl
    default:
        TF_COUNT_HW_LOOKUPS(1);
        return textureGrad(u_texture, uv, dUVdx, dUVdy); // hw-*: sampler state set by the host
    }
}

#endif
