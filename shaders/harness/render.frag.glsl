#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
// Harness: ray-casts the scene at the pixel centre, takes 2x2 quad derivatives of uv (fine or coarse)
// (seam-free where uv wraps), ray differentials or ray cones, filters.
#include "config.h"
#include "filter_select.glsl"
#include "gradients.glsl"
#include "ground_truth.glsl"

layout(location = 0) out vec4 outColor;

void main()
{
    if (FILTER_ID == HARNESS_FILTER_GROUND_TRUTH) { // a specialization constant: uniform control flow
        outColor = ground_truth(ivec2(gl_FragCoord.xy));
        return;
    }
    Hit h = scene_hit(scene, gl_FragCoord.xy);
    // Every lane of the quad computes uv, hit or not, before any branch.
    // Seam-free differences where the scene's uv wraps: those of uv and of its half-period shift (gradients.glsl).
    vec2 shifted = half_period_shift(h.uv);
    tf_Gradients fine = scene_quad_gradients(scene, tf_quad_gradients_fine(h.uv), tf_quad_gradients_fine(shifted));
    tf_Gradients coarse = scene_quad_gradients(scene, tf_quad_gradients_coarse(h.uv), tf_quad_gradients_coarse(shifted));
    tf_Gradients g = GRADIENTS_ID == HARNESS_GRADIENTS_COARSE ? coarse
                     : GRADIENTS_ID == HARNESS_GRADIENTS_RAY  ? ray_gradients(scene, gl_FragCoord.xy, h)
                     : GRADIENTS_ID == HARNESS_GRADIENTS_CONE ? cone_gradients(scene, gl_FragCoord.xy, h)
                                                              : fine;
    // A neighbour's q from fine differences: exact where this lane's q is 0 (the only case adoption uses).
    bvec2 odd = equal(ivec2(gl_FragCoord.xy) & 1, ivec2(1));
    vec3 q = uv_or_none(h);
    [[unroll]] for (int step = 0; step < 2; ++step) {
        vec3 dx = dFdxFine(q), dy = dFdyFine(q);
        q = adopt_uv(q, q + (odd.x ? -dx : dx), q + (odd.y ? -dy : dy));
    }
    PixelLookup l = pixel_lookup(h, g, q);
    harnessPixel = ivec2(gl_FragCoord.xy);
    vec4 color = harness_shade(l.uv, l.dUVdx, l.dUVdy);
    outColor = h.hit ? color : scene.background;
}
