// texfilter/lod.glsl — level of detail from explicit UV gradients (Vulkan "Scale Factor and LOD").
//
// Use:     float tf_lod(sampler2D tex, vec2 dUVdx, vec2 dUVdy, tf_Sampler s); // biased, clamped: [0, levels−1]
//          float tf_lod_unclamped(sampler2D tex, vec2 dUVdx, vec2 dUVdy, float lodBias); // log2(ρ) + lodBias
//          int   tf_mip_level_nearest(float lod); // mipmapMode NEAREST: ceil(lod + ½) − 1, ties to the finer
// Math:    ρ = max(|J e_x|, |J e_y|) with J = [dUVdx dUVdy] in level-0 texels, λ = log2(ρ) + s.lodBias,
//          clamped to [s.lodMin, s.lodMax] (lodMin <= lodMax, as Vulkan's minLod <= maxLod) and then to
//          [0, levels − 1], levels = textureQueryLevels(tex).
// Options: s.lodBias, s.lodMin, s.lodMax. No defines.
// Needs:   tex: only its size and level count are queried.
// Cost:    no texel fetch (one log2).
// Degenerate input: zero gradients give the finest level allowed (λ = −∞ before clamping); NaN or ±Inf
//          gradients, or ρ past float range, the coarsest (+∞): a defined, blurry answer, never undefined.
// Example: int level = tf_mip_level_nearest(tf_lod(tex, dFdxFine(uv), dFdyFine(uv), s));
#ifndef TF_LOD_GLSL
#define TF_LOD_GLSL

#include "common.glsl"

// Unclamped log2(rho) + bias; +Inf for non-finite gradients, -Inf for zero gradients.
float tf_lod_unclamped(sampler2D tex, vec2 dUVdx, vec2 dUVdy, float lodBias)
{
    if (!tf_finite(dUVdx) || !tf_finite(dUVdy))
        return 1.0 / 0.0;
    vec2 size0 = vec2(textureSize(tex, 0));
    vec2 ax = dUVdx * size0;
    vec2 ay = dUVdy * size0;
    // Squared lengths, so one log2 serves both: log2(sqrt(x)) = 0.5 log2(x). Overflow gives +Inf: fine.
    float rho2 = max(dot(ax, ax), dot(ay, ay));
    return 0.5 * log2(rho2) + lodBias;
}

float tf_lod(sampler2D tex, vec2 dUVdx, vec2 dUVdy, tf_Sampler s)
{
    float lambda = tf_lod_unclamped(tex, dUVdx, dUVdy, s.lodBias);
    float top = float(textureQueryLevels(tex) - 1);
    return clamp(clamp(lambda, s.lodMin, s.lodMax), 0.0, top);
}

// Vulkan mipmapMode NEAREST: ceil(d + 0.5) - 1, so d = 0.5 still picks the finer level. Written with
// floor and a comparison because lod + 0.5 rounds in float (1.50000012 + 0.5 == 2.0 exactly).
int tf_mip_level_nearest(float lod)
{
    float level = floor(lod);
    return int(level) + (lod - level > 0.5 ? 1 : 0);
}

#endif
