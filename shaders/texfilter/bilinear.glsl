// texfilter/bilinear.glsl — manual bilinear lookups from texelFetch (4 fetches).
//
// Use:     vec4 c = tf_bilinear(tex, uv, s);                     // level 0 only (no MIP chain)
//          vec4 c = tf_bilinear_mip(tex, uv, dUVdx, dUVdy, s);   // one level chosen by LOD
//          vec4 c = tf_bilinear_level(tex, uv, level, wrapMode); // a given level
// Options: s.wrap selects repeat/clamp/mirror; LOD bias and clamp as in lod.glsl.
//          Vulkan linear filtering: i0 = floor(u·w_l − ½), α = frac(u·w_l − ½), full float weights
//          (hardware samplers round α to subTexelPrecisionBits, often 8). Non-finite uv returns vec4(0).
// Example: vec4 c = tf_bilinear(tex, uv, tf_sampler(TF_WRAP_REPEAT));
#ifndef TF_BILINEAR_GLSL
#define TF_BILINEAR_GLSL

#include "common.glsl"
#include "lod.glsl"

vec4 tf_bilinear_level(sampler2D tex, vec2 uv, int level, int wrapMode)
{
    if (!tf_finite(uv))
        return vec4(0.0);
    ivec2 size = tf_level_size(tex, level);
    vec2 x = uv * vec2(size) - 0.5;
    vec2 i0 = floor(x);
    vec2 a = x - i0;
    ivec2 xs = tf_wrap_pair(i0.x, size.x, wrapMode), ys = tf_wrap_pair(i0.y, size.y, wrapMode);
    TF_COUNT_FETCHES(4);
    vec4 top = mix(texelFetch(tex, ivec2(xs.x, ys.x), level), texelFetch(tex, ivec2(xs.y, ys.x), level), a.x);
    vec4 bottom = mix(texelFetch(tex, ivec2(xs.x, ys.y), level), texelFetch(tex, ivec2(xs.y, ys.y), level), a.x);
    return mix(top, bottom, a.y);
}

vec4 tf_bilinear(sampler2D tex, vec2 uv, tf_Sampler s) { return tf_bilinear_level(tex, uv, 0, s.wrap); }

vec4 tf_bilinear_mip(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s)
{
    return tf_bilinear_level(tex, uv, tf_mip_level_nearest(tf_lod(tex, dUVdx, dUVdy, s)), s.wrap);
}

#endif
