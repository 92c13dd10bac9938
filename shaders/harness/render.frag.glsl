#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
// Harness: ray-casts the scene at the pixel centre, takes 2x2 quad derivatives of uv (fine or coarse)
// or ray differentials, filters.
#include "config.h"
#include "filter_select.glsl"
#include "gradients.glsl"

layout(location = 0) out vec4 outColor;

void main()
{
    tf_Hit h = tf_scene_hit(scene, gl_FragCoord.xy);
    // Every lane of the quad computes uv, hit or not, before any branch.
    tf_Gradients fine = tf_quad_gradients_fine(h.uv);
    tf_Gradients coarse = tf_quad_gradients_coarse(h.uv);
    tf_Gradients g = pc.gradients == TF_GRADIENTS_COARSE ? coarse
                     : pc.gradients == TF_GRADIENTS_RAY  ? tf_harness_ray_gradients(scene, gl_FragCoord.xy, h)
                                                         : fine;
    // Filter hits only: a miss's uv and gradients are those of the unbounded surface, often enormous, and
    // a hardware anisotropic sampler may spend unbounded time on them (lavapipe's does).
    outColor = h.hit ? tf_harness_filter(h.uv, g.dUVdx, g.dUVdy) : scene.background;
}
