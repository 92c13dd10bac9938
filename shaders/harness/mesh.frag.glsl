#version 450
#extension GL_GOOGLE_include_directive : require
// Harness: the way most users will call texfilter — interpolated uv, quad derivatives, one include.
#include "config.h"
#include "filter_select.glsl"

layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 outColor;

void main()
{
    tf_Gradients fine = tf_quad_gradients_fine(uv);
    tf_Gradients coarse = tf_quad_gradients_coarse(uv);
    tf_Gradients g = GRADIENTS_ID == HARNESS_GRADIENTS_COARSE ? coarse : fine;
    harnessPixel = ivec2(gl_FragCoord.xy);
    outColor = harness_shade(uv, g.dUVdx, g.dUVdy);
}
