#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
// Harness: point lookups (uv and gradients from a buffer) through the same filter selection.
//
// Lookups are unrelated, so neighbouring invocations hold unrelated uv. The texfilter includes and the
// hardware-tap forms (textureLod with an explicit LOD) do not mind. A hardware lookup through textureGrad
// may: lavapipe's anisotropic filter takes its footprint from the 2x2 quad's uv differences, not from
// the gradients given, and its level from the first quad of the SIMD batch (one subgroup), so the same
// lookup gave 0.06 or 0.70 by file order. So each hw-* lookup (HARNESS_SAMPLE_IN_QUADS) gets a whole subgroup
// to itself, every quad of it (lanes 4q..4q+3 by subgroup invocation id, bit 0 = x, bit 1 = y: the quads
// of GL_KHR_shader_subgroup_quad, and lavapipe's) laid out as
//     (0,0) uv   (1,0) uv + dUVdx   (0,1) uv + dUVdy   (1,1) uv + dUVdx + dUVdy
// each lane calling textureGrad with the same gradients; lane 0's answer is the lookup's. A sampler that
// honours the gradients gives lane 0 exactly textureGrad(uv, dUVdx, dUVdy); one that differences the quad
// sees fl(uv + d) − uv, within ½ ulp(uv + d) ≤ 2^-24·|uv + d| of d: 2^-24·|u + du|·w level-0 texels.
// Relative to a footprint of at least one texel (where the level or the anisotropy matter) with |uv| ≤ 1
// on a side of at most 16384 that is below 2^-9, i.e. < 0.003 in LOD: far inside mipmapPrecisionBits.
// Degenerate input keeps its documented meaning (docs/API.md) and the quad finite: a non-finite uv gives
// vec4(0) (the quad samples uv 0 with zero gradients); a NaN or ±Inf gradient component, or one of at
// least G = 2^20 uv units, means "blur fully": the gradients become (G, 0) and (0, G), an isotropic
// footprint the coarsest level under every LOD rule, as the original was under Vulkan's (2^20 texels or
// more: log2(2^20 / 16 probes) is beyond the last level of a 65536 texture); uv + 2G stays finite.
// (lavapipe's anisotropic filter put a 2^20 x 0 texel footprint on level 0.)
// Workgroups are numbered over a 2-D grid (gl_NumWorkGroups.x ≤ 65535), so any count of lookups fits.
#include "config.h"
#include "filter_select.glsl"

layout(local_size_x = HARNESS_SAMPLE_LOCAL_SIZE) in;

layout(set = 0, binding = HARNESS_BINDING_LOOKUPS, std430) readonly buffer LookupsBuffer { float lookups[]; };
layout(set = 0, binding = HARNESS_BINDING_RESULTS, std430) writeonly buffer ResultsBuffer { vec4 results[]; };
layout(set = 0, binding = HARNESS_BINDING_STATS, std430) writeonly buffer StatsBuffer { uvec2 stats[]; };

const float HUGE_GRADIENT = 1048576.0; // G = 2^20

void main()
{
    const bool quads = HARNESS_SAMPLE_IN_QUADS(FILTER_ID); // a specialization constant: uniform
    // The invocation's place, subgroup by subgroup (full subgroups: the host checks that the subgroup size
    // divides the workgroup size and is a multiple of 4).
    uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    uint i = group * HARNESS_SAMPLE_LOCAL_SIZE + gl_LocalInvocationIndex;
    if (quads)
        i = (group * HARNESS_SAMPLE_LOCAL_SIZE) / gl_SubgroupSize + gl_SubgroupID;
    if (i >= pc.count) // a subgroup's lanes leave together in quads mode
        return;
    harnessLookupIndex = i; // bindless: lookup i reads u_textures[(pc.layer + i) % HARNESS_BINDLESS_COUNT]
    uint b = uint(HARNESS_LOOKUP_FLOATS) * i;
    vec2 uv = vec2(lookups[b], lookups[b + 1u]);
    vec2 dUVdx = vec2(lookups[b + 2u], lookups[b + 3u]);
    vec2 dUVdy = vec2(lookups[b + 4u], lookups[b + 5u]);
    if (!quads) {
        results[i] = harness_filter(uv, dUVdx, dUVdy);
        stats[i] = uvec2(fetchCount, hwLookupCount);
        return;
    }
    bool finiteUV = tf_finite(uv);
    if (!finiteUV) {
        uv = vec2(0.0);
        dUVdx = dUVdy = vec2(0.0);
    } else if (!tf_finite(dUVdx) || !tf_finite(dUVdy) ||
               any(greaterThanEqual(abs(vec4(dUVdx, dUVdy)), vec4(HUGE_GRADIENT)))) {
        dUVdx = vec2(HUGE_GRADIENT, 0.0); // blur fully
        dUVdy = vec2(0.0, HUGE_GRADIENT);
    }
    uint lane = gl_SubgroupInvocationID & 3u;
    vec2 at = uv;
    if ((lane & 1u) != 0u)
        at += dUVdx;
    if ((lane & 2u) != 0u)
        at += dUVdy;
    vec4 color = harness_filter(at, dUVdx, dUVdy);
    if (gl_SubgroupInvocationID == 0u) {
        results[i] = finiteUV ? color : vec4(0.0);
        stats[i] = uvec2(fetchCount, hwLookupCount);
    }
}
