#version 450
#extension GL_GOOGLE_include_directive : require
// Harness: level 0 of the "dynamic" texture at one frame, written into the RGBA32F chain that the GPU build
// then completes (vulkan/gpu_build.cpp): tf::dynamic_texture's integer arithmetic, the same floats bit
// for bit (host/core/procedural.cpp; tests/test_gpu_build.cpp compares them).
#include "config.h"

layout(set = 0, binding = 0, rgba32f) uniform writeonly image2D level0;
layout(push_constant) uniform Push { int size; int frame; } pc;

layout(local_size_x = 16, local_size_y = 16) in;

void main()
{
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    const int size = pc.size, f = pc.frame;
    if (p.x >= size || p.y >= size)
        return;
    const int cell = max(2, size / 16);
    const int phase = f % 16, step = max(1, size / 32);
    const int cx = size / 2 + step * (phase < 8 ? phase - 4 : 12 - phase);
    const int cy = size / 2 + step * (phase < 4 ? phase : phase < 12 ? 8 - phase : phase - 16);
    const int sx = int((uint(p.x) + 3u * uint(f)) % uint(size)), sy = int((uint(p.y) + 2u * uint(f)) % uint(size));
    const bool dark = ((sx / cell + sy / cell) & 1) != 0;
    const int dx = p.x - cx, dy = p.y - cy;
    // (dx² + dy²)·4 stays below 2^31 for sides up to 16384 (2·16384² · 4 / cell², computed in uint)
    const uint r2 = uint(dx * dx) + uint(dy * dy);
    const int ring = int((r2 * 4u / uint(cell * cell) + uint(f)) & 3u);
    const int fine = (sx ^ sy) & 15;
    imageStore(level0, p, vec4(dark ? 0.1 : 0.85, float(ring) * 0.25, float(fine) * 0.0625, 1.0));
}
