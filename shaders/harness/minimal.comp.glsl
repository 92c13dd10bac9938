#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#extension GL_KHR_shader_subgroup_quad : require
// Harness only: the bench's minimal pass, no texture (minimal.glsl).
#include "minimal.glsl"
