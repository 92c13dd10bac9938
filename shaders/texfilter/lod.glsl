// texfilter/lod.glsl — level of detail from explicit UV gradients (Vulkan "Scale Factor and LOD").
//
// Use:     float lambda = tf_lod(tex, dUVdx, dUVdy, s);  // biased and clamped, in [0, levels-1]
// Options: none. rho = max(|J e_x|, |J e_y|) with J in level-0 texels, lambda = log2(rho) + lodBias,
//          clamped to [lodMin, lodMax] and then to the existing levels.
//          Zero gradients give the finest level; NaN or ±Inf gradients give the coarsest (a defined,
//          blurry answer rather than undefined behaviour).
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
