#version 450
#extension GL_GOOGLE_include_directive : require
// Harness: one pass of the GPU summed-area table build (texfilter/build_sat.glsl) from level 0 of an
// RGBA32F chain. The host (vulkan/gpu_build.cpp) dispatches the range, rows and columns passes in order.
// Compiled twice: as is, and with -DTF_SAT_NO_FP64 for devices without shaderFloat64.
#include "config.h"

layout(set = 0, binding = HARNESS_BUILD_BINDING_LEVEL0, rgba32f) uniform readonly image2D level0;
layout(set = 0, binding = HARNESS_BUILD_BINDING_SAT_LOW, rgba32ui) uniform uimage2D satLow;
layout(set = 0, binding = HARNESS_BUILD_BINDING_SAT_HIGH, r32ui) uniform writeonly uimage2D satHigh;
layout(set = 0, binding = HARNESS_BUILD_BINDING_RANGE, std430) buffer Range { uint words[9]; } range;
layout(push_constant) uniform Push { ivec2 size; int pass; } pc;

#define TF_SAT_LOAD(p) imageLoad(level0, p)
#define TF_SAT_LOAD_LOW(e) imageLoad(satLow, e)
#define TF_SAT_STORE_LOW(e, v) imageStore(satLow, e, v)
#define TF_SAT_STORE_HIGH(e, v) imageStore(satHigh, e, uvec4(v))
#define TF_SAT_RANGE range.words
#include "texfilter/build_sat.glsl"

layout(local_size_x = TF_SAT_GROUP_SIZE) in;

void main()
{
    if (pc.pass == HARNESS_SAT_PASS_RANGE)
        tf_sat_range_pass(pc.size);
    else if (pc.pass == HARNESS_SAT_PASS_ROWS)
        tf_sat_rows_pass(pc.size);
    else
        tf_sat_columns_pass(pc.size);
}
