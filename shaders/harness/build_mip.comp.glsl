#version 450
#extension GL_GOOGLE_include_directive : require
// Harness: one pass of the GPU MIP build (texfilter/build_mip.glsl) over an RGBA32F chain, one storage view
// a level. The host (vulkan/gpu_build.cpp) dispatches the passes of tf::plan_mip_build.
#include "config.h"

layout(set = 0, binding = HARNESS_BUILD_BINDING_LEVELS, rgba32f) uniform coherent image2D chain[HARNESS_MIP_MAX_LEVELS];
layout(set = 0, binding = HARNESS_BUILD_BINDING_COUNTER, std430) coherent buffer Counter { uint groupsDone; };
layout(push_constant) uniform Push { ivec2 size0; int sourceLevel; int levels; int tail; } pc;

#define TF_MIP_LOAD(level, p) imageLoad(chain[level], p)
#define TF_MIP_STORE(level, p, v) imageStore(chain[level], p, v)
#define TF_MIP_COUNTER groupsDone
#include "texfilter/build_mip.glsl"

layout(local_size_x = TF_MIP_GROUP_SIZE) in;

void main()
{
    tf_build_mip_pass(pc.sourceLevel, pc.levels, pc.tail != 0, pc.size0);
}
