// texfilter/nearest.glsl — manual nearest-texel lookups from texelFetch (1 fetch).
//
// Use:     vec4 c = tf_nearest(tex, uv, s);                      // level 0 only (no MIP chain)
//          vec4 c = tf_nearest_mip(tex, uv, dUVdx, dUVdy, s);    // one level chosen by LOD
// Options: s.wrap selects repeat/clamp/mirror; LOD bias and clamp as in lod.glsl.
//          Texel i = floor(u · w_l). Non-finite uv returns vec4(0).
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
    vec2 texel = floor(uv * vec2(size));
    TF_COUNT_FETCHES(1);
    return texelFetch(tex, ivec2(tf_wrap(texel.x, size.x, wrapMode), tf_wrap(texel.y, size.y, wrapMode)), level);
}

vec4 tf_nearest(sampler2D tex, vec2 uv, tf_Sampler s) { return tf_nearest_level(tex, uv, 0, s.wrap); }

vec4 tf_nearest_mip(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s)
{
    return tf_nearest_level(tex, uv, tf_mip_level_nearest(tf_lod(tex, dUVdx, dUVdy, s)), s.wrap);
}

#endif
