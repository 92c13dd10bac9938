// sky.frag.glsl: bilinear in a fragment shader, with an include of the caller's own (include/tint.glsl,
// found through INCLUDE_DIRS) and a define (SKY_SCALE, from DEFINES).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "texfilter/bilinear.glsl"
#include "tint.glsl"
#ifndef SKY_SCALE
#error "SKY_SCALE: texfilter_add_shaders(... DEFINES) did not pass it"
#endif

layout(set = 0, binding = 0) uniform sampler2D tex;
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;

void main()
{
    tf_Sampler s = tf_Sampler(TF_WRAP_MIRROR, 0.0, 0.0, 1000.0);
    color = sky_tint() * tf_bilinear(tex, uv * SKY_SCALE, s);
}
