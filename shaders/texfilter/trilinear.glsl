// texfilter/trilinear.glsl — manual trilinear lookups from texelFetch (8 fetches, 4 where the LOD
// sits exactly on a level or is clamped to the last one).
//
// Use:     vec4 c = tf_trilinear(tex, uv, dUVdx, dUVdy, s);
// Options: s.wrap, s.lodBias, s.lodMin, s.lodMax (see common.glsl, lod.glsl).
//          Blends bilinear lookups on levels floor(λ) and floor(λ)+1 by frac(λ) in full float
//          (hardware samplers round the blend to mipmapPrecisionBits, often 4 or 8).
// Example: vec4 c = tf_trilinear(tex, uv, dFdxFine(uv), dFdyFine(uv), tf_sampler(TF_WRAP_REPEAT));
#ifndef TF_TRILINEAR_GLSL
#define TF_TRILINEAR_GLSL

#include "bilinear.glsl"
#include "lod.glsl"

vec4 tf_trilinear(sampler2D tex, vec2 uv, vec2 dUVdx, vec2 dUVdy, tf_Sampler s)
{
    float lod = tf_lod(tex, dUVdx, dUVdy, s);
    int lo = int(floor(lod));
    float f = lod - float(lo);
    vec4 fine = tf_bilinear_level(tex, uv, lo, s.wrap);
    if (f == 0.0)
        return fine; // on a level, or clamped to the last one: the second level would weigh 0
    return mix(fine, tf_bilinear_level(tex, uv, lo + 1, s.wrap), f);
}

#endif
