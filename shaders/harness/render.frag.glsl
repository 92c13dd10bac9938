#version 450
#extension GL_GOOGLE_include_directive : require
// Harness: ray-casts the scene at the pixel centre, takes fine 2x2 quad derivatives of uv, filters.
#include "config.h"
#include "scene.glsl"
#include "filter_select.glsl"

layout(set = 0, binding = TF_BINDING_SCENE, std140) uniform tf_SceneBlock { tf_SceneParams scene; };

layout(location = 0) out vec4 outColor;

void main()
{
    tf_Hit h = tf_scene_hit(scene, gl_FragCoord.xy);
    // Derivatives in uniform control flow: every lane of the quad computes uv, hit or not.
    vec2 dUVdx = dFdxFine(h.uv);
    vec2 dUVdy = dFdyFine(h.uv);
    vec4 c = tf_harness_filter(h.uv, dUVdx, dUVdy);
    outColor = h.hit ? c : scene.background;
}
