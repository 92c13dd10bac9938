#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
// Harness: the triangles scene rasterized from a vertex buffer, with the ray-cast camera's projection.
#include "config.h"
#include "scene.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec2 uv;
layout(location = 0) out vec2 outUV; // smooth: perspective-correct interpolation

const float NEAR_PLANE = 0.05, FAR_PLANE = 1000.0;

void main()
{
    // The ray through ndc (x, y) is forward + x right + y up (right, up scaled by the half-fov tangents),
    // so a point at depth z along forward projects to x = dot(c, right) / (|right|² z), likewise y.
    vec3 c = position - scene.origin.xyz;
    float z = dot(c, scene.forward.xyz);
    vec3 right = scene.right.xyz, up = scene.up.xyz;
    // Vulkan's framebuffer y grows downward; the scene's ndc y grows upward.
    gl_Position = vec4(dot(c, right) / dot(right, right), -dot(c, up) / dot(up, up),
                       (z - NEAR_PLANE) * FAR_PLANE / (FAR_PLANE - NEAR_PLANE), z);
    outUV = uv + scene.extent.zw; // the camera path's slide, as the ray-cast twin
}
