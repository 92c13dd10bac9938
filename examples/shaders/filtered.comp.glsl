// filtered.comp.glsl — texfilter example, compute path: the same image as filtered.frag.glsl, with
// invocations grouped into 2x2 quads through subgroup quad operations, so that the uv gradients are
// the fragment stage's fine derivatives. Writes linear RGBA to a buffer, row by row.
#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_quad : require

#define TF_COMPUTE_QUADS // opt in to tf_quad_pixel and tf_compute_quad_gradients
#include "texfilter/texfilter.glsl"
#include "ground_plane.glsl"

// A workgroup shades an 8x8 tile as 16 quads. Its size must be a multiple of the subgroup size
// (main.cpp checks that and asks for full subgroups).
#define TILE 8
layout(local_size_x = TILE * TILE) in;

layout(set = 0, binding = 1, std430) writeonly buffer Pixels { vec4 pixels[]; };

void main()
{
    ivec2 pixel = tf_quad_pixel(ivec2(gl_WorkGroupID.xy) * TILE, TILE);
    vec3 ground = ground_uv(vec2(pixel) + 0.5);
    // Every invocation takes part in the quad operation, also those past the image's edge.
    tf_Gradients g = tf_compute_quad_gradients(ground.xy, TF_DERIVATIVES_FINE);
    if (all(lessThan(pixel, params.imageSize)))
        pixels[pixel.y * params.imageSize.x + pixel.x] = shade(ground, g);
}
