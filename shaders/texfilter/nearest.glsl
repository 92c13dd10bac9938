// texfilter/nearest.glsl — manual nearest-texel lookups from texelFetch (Vulkan NEAREST filtering).
//
// Use:     vec4 tf_nearest(sampler2D tex, vec2 uv, tf_Sampler s);                             // level 0 only
//          vec4 tf_nearest_mip(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s); // level by LOD
//          vec4 tf_nearest_level(sampler2D tex, vec2 uv, int level, int wrapMode); // level in [0, levels−1]
// Math:    texel i = floor(u·w_l). tf_nearest_mip reads level tf_mip_level_nearest(tf_lod(...)) (lod.glsl:
//          mipmapMode NEAREST, no blend between levels).
// Options: s.wrap; tf_nearest_mip also s.lodBias, s.lodMin, s.lodMax as in lod.glsl. No defines.
// Needs:   tex: any sampler2D (texelFetch; tf_nearest_mip uses its MIP chain).
// Cost:    1 texel fetch.
// Degenerate input: non-finite uv gives vec4(0), huge uv is moved by whole periods first (tf_reduce_uv);
//          NaN/±Inf gradients the coarsest level, zero the finest (docs/API.md, degenerate input).
// Example: vec4 c = tf_nearest_mip(tex, uv, dFdxFine(uv), dFdyFine(uv), tf_sampler(TF_WRAP_CLAMP));
#ifndef TF_NEAREST_GLSL
#define TF_NEAREST_GLSL

#include "common.glsl"
#include "lod.glsl"

vec4 tf_nearest_level(sampler2D tex, vec2 uv, int level, int wrapMode)
{
    if (!tf_finite(uv))
        return vec4(0.0);
    ivec2 size = tf_level_size(tex, level);
    vec2 texel = floor(tf_reduce_uv(uv, wrapMode) * vec2(size)); // whole periods first: no overflow
    TF_COUNT_FETCHES(1);
    return texelFetch(tex, ivec2(tf_wrap(texel.x, size.x, wrapMode), tf_wrap(texel.y, size.y, wrapMode)), level);
}

vec4 tf_nearest(sampler2D tex, vec2 uv, tf_Sampler s) { return tf_nearest_level(tex, uv, 0, s.wrap); }

vec4 tf_nearest_mip(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s)
{
    return tf_nearest_level(tex, uv, tf_mip_level_nearest(tf_lod(tex, dUVdx, dUVdy, s)), s.wrap);
}

#endif
