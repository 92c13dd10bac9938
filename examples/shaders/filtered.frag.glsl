// filtered.frag.glsl — texfilter example, fragment path: the ground plane (ground_plane.glsl) with
// uv gradients from the fragment quad's fine derivatives (dFdxFine / dFdyFine).
#version 450
#extension GL_GOOGLE_include_directive : require

#include "texfilter/texfilter.glsl"
#include "ground_plane.glsl"

layout(location = 0) out vec4 color;

void main()
{
    vec3 ground = ground_uv(gl_FragCoord.xy); // gl_FragCoord is the pixel centre: (x + 0.5, y + 0.5)
    tf_Gradients g = tf_quad_gradients_fine(ground.xy);
    color = shade(ground, g);
}
