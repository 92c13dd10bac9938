#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
// Harness: the environment scenes (skybox, reflect): each pixel's lookup direction from env_scene.glsl, its
// 2x2 quad derivatives (fine or coarse), ray differentials or ray cones, filtered from the cube or lat-long map the
// variant binds (-DHARNESS_ENV); or the ground truth over the pixel's directions.
#include "config.h"
#include "env_select.glsl"
#include "env_scene.glsl"
#include "ground_truth.glsl"

layout(location = 0) out vec4 outColor;

// The mean of the frame's samples (truth_samples) of level 0 over the directions the pixel sees.
vec4 env_ground_truth(ivec2 pixel)
{
    int side, first, count;
    truth_samples(side, first, count);
    vec4 sum = vec4(0.0);
    [[dont_unroll]] for (int i = first; i < first + count; ++i)
        sum += harness_env_level0(env_hit(scene, truth_sample(pixel, i, side, pc.pixelFilter)).dir);
    return sum / float(count);
}

void main()
{
    if (FILTER_ID == HARNESS_FILTER_GROUND_TRUTH) { // a specialization constant: uniform control flow
        outColor = env_ground_truth(ivec2(gl_FragCoord.xy));
        return;
    }
    harnessPixel = ivec2(gl_FragCoord.xy);
    EnvHit h = env_hit(scene, gl_FragCoord.xy);
    // Quad derivatives in uniform control flow: every form, then the one asked for.
    vec3 fineX = dFdxFine(h.dir), fineY = dFdyFine(h.dir), coarseX = dFdxCoarse(h.dir), coarseY = dFdyCoarse(h.dir);
    vec3 dx = GRADIENTS_ID == HARNESS_GRADIENTS_COARSE ? coarseX
              : GRADIENTS_ID == HARNESS_GRADIENTS_RAY  ? h.dirDx
              : GRADIENTS_ID == HARNESS_GRADIENTS_CONE ? h.coneDx
                                                       : fineX;
    vec3 dy = GRADIENTS_ID == HARNESS_GRADIENTS_COARSE ? coarseY
              : GRADIENTS_ID == HARNESS_GRADIENTS_RAY  ? h.dirDy
              : GRADIENTS_ID == HARNESS_GRADIENTS_CONE ? h.coneDy
                                                       : fineY;
    outColor = harness_env_filter(h.dir, dx * pc.gradientScale, dy * pc.gradientScale);
}
