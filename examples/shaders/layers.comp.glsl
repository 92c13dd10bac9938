// layers.comp.glsl — texfilter example: a texture array bound as texture2DArray with a separate sampler,
// the layer an explicit int per lookup. tf_trilinear reads texels itself (no sampler); tf_ewa_hw makes its
// bilinear taps through the sampler (built into a sampler2DArray inside the include, at the point of use).
// Every layer is one constant colour (resources.cpp), so each lookup must return its layer's colour.
#version 450
#extension GL_GOOGLE_include_directive : require

#include "texfilter/texfilter.glsl"
#include "probes.glsl"

layout(local_size_x = 64) in;

layout(set = 0, binding = 0) uniform texture2DArray u_layers; // pc.count layers, full MIP chain
layout(set = 0, binding = 1) uniform sampler u_linear;         // linear min/mag, clamp to edge, no LOD clamp
layout(set = 0, binding = 2, std430) writeonly buffer Results { vec4 results[]; };

void main()
{
    uint i = gl_GlobalInvocationID.x;
    Probe p = probe(i);
    int layer = probe_index(i, pc.count + 2) - 1; // -1 and pc.count check the clamp to [0, count - 1]
    results[2u * i + 0u] = tf_trilinear(u_layers, p.uv, layer, p.dx, p.dy, p.s);
    results[2u * i + 1u] = tf_ewa_hw(u_layers, u_linear, p.uv, layer, p.dx, p.dy, p.s, 2.0, 8.0);
}
