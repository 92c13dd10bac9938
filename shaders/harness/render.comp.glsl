#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#extension GL_KHR_shader_subgroup_quad : require
#extension GL_KHR_shader_subgroup_vote : require
// Harness: the fragment render in a compute shader. Invocations form 2x2 quads through subgroup quad
// operations (texfilter/derivatives.glsl), so the quad derivatives are the fragment stage's.
#define TF_COMPUTE_QUADS
#include "config.h"
#include "filter_select.glsl"
#include "gradients.glsl"
#include "ground_truth.glsl"

layout(local_size_x = HARNESS_RENDER_TILE * HARNESS_RENDER_TILE) in;

layout(set = 0, binding = HARNESS_BINDING_RESULTS, std430) writeonly buffer PixelsBuffer { vec4 pixels[]; };

void main()
{
    ivec2 pixel = tf_quad_pixel(ivec2(gl_WorkGroupID.xy) * HARNESS_RENDER_TILE, HARNESS_RENDER_TILE);
    vec2 centre = vec2(pixel) + 0.5;
    ivec2 size = scene.kindSize.yz;
    if (FILTER_ID == HARNESS_FILTER_GROUND_TRUTH) { // no quads needed: a specialization constant, uniform
        if (all(lessThan(pixel, size)))
            pixels[pixel.y * size.x + pixel.x] = ground_truth(pixel);
        return;
    }
    Hit h = scene_hit(scene, centre);
    // All lanes (those past the image's edge too) take part in the quad operations.
    // Seam-free differences where the scene's uv wraps: those of uv and of its half-period shift (gradients.glsl).
    int mode = GRADIENTS_ID == HARNESS_GRADIENTS_COARSE ? TF_DERIVATIVES_COARSE : TF_DERIVATIVES_FINE;
    tf_Gradients quad = scene_quad_gradients(scene, tf_compute_quad_gradients(h.uv, mode),
                                             tf_compute_quad_gradients(half_period_shift(h.uv), mode));
    tf_Gradients g = GRADIENTS_ID == HARNESS_GRADIENTS_RAY    ? ray_gradients(scene, centre, h)
                     : GRADIENTS_ID == HARNESS_GRADIENTS_CONE ? cone_gradients(scene, centre, h)
                                                              : quad;
    vec3 q = uv_or_none(h);
    // Only the hardware sampler needs a missed lane's uv from a neighbour (gradients.glsl): a manual filter's
    // missed lane reads uv 0.5 at the coarsest level. The test is uniform in the subgroup, so whole quads swap;
    // where every lane hit, none is needed. The no-texture frame (the bench's baseline) adopts nothing.
    if (harness_hardware_lookups() && subgroupAny(!h.hit))
        [[unroll]] for (int step = 0; step < 2; ++step)
            q = adopt_uv(q, subgroupQuadSwapHorizontal(q), subgroupQuadSwapVertical(q));
    PixelLookup l = pixel_lookup(h, g, q);
    harnessPixel = pixel;
    vec4 color = harness_shade(l.uv, l.dUVdx, l.dUVdy);
    if (all(lessThan(pixel, size)))
        pixels[pixel.y * size.x + pixel.x] = h.hit ? color : scene.background;
}
