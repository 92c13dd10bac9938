// b/blur.comp.glsl: EWA in compute, the other blur.comp.glsl (a/ has the first).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "texfilter/ewa.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0) uniform sampler2D tex;
layout(set = 0, binding = 1, std430) writeonly buffer Out { vec4 pixels[]; };

void main()
{
    vec2 uv = (vec2(gl_GlobalInvocationID.xy) + 0.5) / 64.0;
    tf_Sampler s = tf_Sampler(TF_WRAP_CLAMP, 0.0, 0.0, 1000.0);
    pixels[gl_GlobalInvocationID.y * 64u + gl_GlobalInvocationID.x] = tf_ewa(tex, uv, vec2(0.03, 0.01), vec2(0.0, 0.02), s, 2.0, 8.0);
}
