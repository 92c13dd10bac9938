// bindless.comp.glsl — texfilter example: a bindless array of combined samplers, indexed per invocation
// (divergent), so every image access inside the includes must carry NonUniform: TF_NONUNIFORM before the
// first include, nonuniformEXT at the call. Needs vulkan1.2 (runtime descriptor array) and the device
// features runtimeDescriptorArray and shaderSampledImageArrayNonUniformIndexing (resources.cpp checks).
// Every element is one constant colour (resources.cpp), so each lookup must return its element's colour.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_nonuniform_qualifier : require

#define TF_NONUNIFORM nonuniformEXT
#include "texfilter/texfilter.glsl"
#include "probes.glsl"

layout(local_size_x = 64) in;

layout(set = 0, binding = 0) uniform sampler2D u_textures[]; // pc.count elements
layout(set = 0, binding = 1, std430) writeonly buffer Results { vec4 results[]; };

void main()
{
    uint i = gl_GlobalInvocationID.x;
    Probe p = probe(i);
    int t = probe_index(i * 7u, pc.count); // neighbours differ: the index is not uniform
    results[2u * i + 0u] = tf_trilinear(u_textures[nonuniformEXT(t)], p.uv, p.dx, p.dy, p.s);
    results[2u * i + 1u] = tf_ewa(u_textures[nonuniformEXT(t)], p.uv, p.dx, p.dy, p.s, 2.0, 8.0);
}
