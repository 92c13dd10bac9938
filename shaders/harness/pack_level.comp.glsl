#version 450
#extension GL_GOOGLE_include_directive : require
// Harness: one level of a GPU-built RGBA32F chain stored into the texture's own format (rgba8-srgb, rgba8,
// rgba16f, r8, r16f, r32f) through an integer view of that level, the codes rounded as the host rounds them
// (texfilter/encode.glsl). Compiled once an integer view format (-DHARNESS_CODES_FORMAT=rgba8ui, rgba16ui,
// r8ui, r16ui, r32ui): a store without a format qualifier would need shaderStorageImageWriteWithoutFormat,
// and llvmpipe compiles such a store for every format it could be (13 s a pipeline, cold).
#include "config.h"
#include "texfilter/encode.glsl"

layout(set = 0, binding = HARNESS_BUILD_BINDING_LEVELS, rgba32f) uniform readonly image2D chain[HARNESS_MIP_MAX_LEVELS];
#ifndef HARNESS_CODES_FORMAT
#define HARNESS_CODES_FORMAT rgba8ui
#endif
layout(set = 0, binding = HARNESS_BUILD_BINDING_CODES, HARNESS_CODES_FORMAT) uniform writeonly uimage2D codes[HARNESS_MIP_MAX_LEVELS];
layout(push_constant) uniform Push { ivec2 size; int level; int encoding; int alphaEncoding; int channels; } pc;

layout(local_size_x = 16, local_size_y = 16) in;

// HARNESS_CODES_ENCODINGS: the encodings this variant's view format can hold (1 << HARNESS_ENCODING_*), so
// that a variant compiles only its own encoders (the sRGB table's search is the costly one to compile).
#ifndef HARNESS_CODES_ENCODINGS
#define HARNESS_CODES_ENCODINGS 15
#endif
uint code(float v, int encoding)
{
#if (HARNESS_CODES_ENCODINGS & (1 << HARNESS_ENCODING_SRGB8)) != 0
    if (encoding == HARNESS_ENCODING_SRGB8)
        return tf_mip_srgb8(v);
#endif
#if (HARNESS_CODES_ENCODINGS & (1 << HARNESS_ENCODING_UNORM8)) != 0
    if (encoding == HARNESS_ENCODING_UNORM8)
        return tf_mip_unorm8(v);
#endif
#if (HARNESS_CODES_ENCODINGS & (1 << HARNESS_ENCODING_FLOAT16)) != 0
    if (encoding == HARNESS_ENCODING_FLOAT16)
        return tf_mip_half(v);
#endif
    return floatBitsToUint(v); // float32
}

void main()
{
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, pc.size)))
        return;
    const vec4 v = imageLoad(chain[pc.level], p);
    uvec4 c = uvec4(code(v.r, pc.encoding), 0u, 0u, 0u);
    if (pc.channels == 4)
        c = uvec4(c.r, code(v.g, pc.encoding), code(v.b, pc.encoding), code(v.a, pc.alphaEncoding));
    imageStore(codes[pc.level], p, c);
}
