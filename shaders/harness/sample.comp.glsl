#version 450
#extension GL_GOOGLE_include_directive : require
// Harness: point lookups (uv and gradients from a buffer) through the same filter selection.
#include "config.h"
#include "filter_select.glsl"

layout(local_size_x = TF_SAMPLE_LOCAL_SIZE) in;

layout(set = 0, binding = TF_BINDING_LOOKUPS, std430) readonly buffer tf_Lookups { float lookups[]; };
layout(set = 0, binding = TF_BINDING_RESULTS, std430) writeonly buffer tf_Results { vec4 results[]; };
layout(set = 0, binding = TF_BINDING_STATS, std430) writeonly buffer tf_Stats { uvec2 stats[]; };

void main()
{
    uint i = gl_GlobalInvocationID.x;
    if (i >= pc.count)
        return;
    uint b = 6u * i;
    vec2 uv = vec2(lookups[b], lookups[b + 1u]);
    vec2 dUVdx = vec2(lookups[b + 2u], lookups[b + 3u]);
    vec2 dUVdy = vec2(lookups[b + 4u], lookups[b + 5u]);
    results[i] = tf_harness_filter(uv, dUVdx, dUVdy);
    stats[i] = uvec2(tf_fetchCount, tf_hwLookupCount);
}
