// Harness only: the procedural textures' analytic definitions, the GPU twin (float) of
// host/core/analytic_texture.cpp (double), for the ground truth's --truth analytic (ground_truth.glsl).
// Use: analytic_value(HARNESS_ANALYTIC_CHECKER, 256, uv, TF_WRAP_REPEAT). kind: HARNESS_ANALYTIC_* (config.h);
// size: level 0's side in texels. The wrap mode maps uv into [0,1)^2 first (repeat: fract; clamp: the
// nearest point; mirror: reflected every other period). Cost: a few ALU operations (zoneplate: one cos).
//   checker   0.9 where floor(8u) + floor(8v) is even, else 0.05 (RGB; alpha 1)
//   zoneplate 0.5 + 0.5 cos(pi size ((u - 1/2)^2 + (v - 1/2)^2)), in texels from the centre as on the CPU
//   grid      a line where frac(16u) size < 16 width (or in v), width 2 at size >= 512 else 1
#ifndef HARNESS_ANALYTIC_TEXTURE_GLSL
#define HARNESS_ANALYTIC_TEXTURE_GLSL

#include "config.h"

// The largest float below 1: clamp and mirror keep u = 1 in the last cell (clamp-to-edge's last texel).
const float analytic_below_one = 0.99999994;

float analytic_wrap(float u, int wrapMode)
{
    if (wrapMode == HARNESS_WRAP_REPEAT)
        u = fract(u);
    else if (wrapMode == HARNESS_WRAP_MIRROR) {
        float t = u - 2.0 * floor(0.5 * u); // [0, 2): one period of the mirrored pattern
        u = t <= 1.0 ? t : 2.0 - t;
    }
    return clamp(u, 0.0, analytic_below_one);
}

bool analytic_grid_line(float u, int size)
{
    float width = size >= 512 ? 2.0 : 1.0;
    return fract(16.0 * u) * float(size) < 16.0 * width;
}

vec4 analytic_value(int kind, int size, vec2 uv, int wrapMode)
{
    vec2 st = vec2(analytic_wrap(uv.x, wrapMode), analytic_wrap(uv.y, wrapMode));
    if (kind == HARNESS_ANALYTIC_CHECKER) {
        ivec2 cell = ivec2(floor(8.0 * st));
        float v = ((cell.x + cell.y) & 1) == 0 ? 0.9 : 0.05;
        return vec4(v, v, v, 1.0);
    }
    if (kind == HARNESS_ANALYTIC_ZONEPLATE) {
        vec2 d = st * float(size) - 0.5 * float(size);
        // The phase in half turns, reduced to [-1, 1) (exact in float): cos keeps the spec's 2^-11 bound
        // only on [-pi, pi], and the phase reaches pi size / 2.
        float x = dot(d, d) / float(size);
        x -= 2.0 * floor(0.5 * x + 0.5);
        float v = 0.5 + 0.5 * cos(3.14159265358979 * x);
        return vec4(v, v, v, 1.0);
    }
    bool line = analytic_grid_line(st.x, size) || analytic_grid_line(st.y, size);
    return line ? vec4(0.9, 0.85, 0.6, 1.0) : vec4(0.02, 0.03, 0.08, 1.0);
}

#endif
