#version 450
#extension GL_GOOGLE_include_directive : require
// Harness: ray-casts the scene at the pixel centre, takes 2x2 quad derivatives of uv (fine or coarse)
// or ray differentials, filters.
#include "config.h"
#include "filter_select.glsl"
#include "gradients.glsl"

layout(set = 0, binding = TF_BINDING_SCENE, std140) uniform tf_SceneBlock { tf_SceneParams scene; };

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
    vec4 c = tf_harness_filter(h.uv, g.dUVdx, g.dUVdy);
    outColor = h.hit ? c : scene.background;
}
