#pragma once
// The C++ side of what the harness shaders read from the host beyond the scene (scene.h): the push
// constants every pass shares. Layout and ids come from shaders/harness/config.h.
#include <cstdint>

namespace tf {

// Mirrors tf_PushConstants in shaders/harness/filter_select.glsl.
struct PushConstants {
    int32_t wrap_mode;
    float lod_bias;
    float lod_min;
    float lod_max;
    uint32_t count;
    float band;
    int32_t probes;
    int32_t aniso_shape;
    int32_t taps;
    float alpha;
    float max_aniso;
    int32_t boxes;
    int32_t gradients; // TF_GRADIENTS_*
    int32_t truth_side;   // ground-truth: samples a pixel = side^2
    int32_t pixel_filter; // ground-truth: TF_PIXEL_FILTER_*
    int32_t padding;      // the vec4s start at byte 64, as in GLSL
    float sat_offset[4];  // sat: SatTable::offset, ::scale (per channel)
    float sat_scale[4];
};
static_assert(sizeof(PushConstants) == 96, "PushConstants must match tf_PushConstants (std430)");

} // namespace tf
