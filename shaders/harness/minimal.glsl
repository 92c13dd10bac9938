// Harness only: the bench's minimal pass, the yardstick its timed frames are compared with (docs/BENCHMARKS.md,
// "The harness's frame"). The scene's ray cast (specialised to its kind, as the harness's), one pair of fine quad
// gradients, one store: what any engine's pass that textures this surface must do at least. With
// HARNESS_MINIMAL_TRILINEAR it adds the least a manual trilinear lookup needs — the isotropic level, four
// texelFetch on each of two levels, a power-of-two repeat by a mask, no guards — so that tf_trilinear's cost
// is measured against the cost it should have, in the same run. Not a filter: bench-only, repeat only, its
// texture square and power-of-two (the bench's procedural ones).
#ifndef HARNESS_MINIMAL_GLSL
#define HARNESS_MINIMAL_GLSL

#define TF_COMPUTE_QUADS
#include "config.h"
#include "scene.glsl"
#include "texfilter/derivatives.glsl"

layout(local_size_x = HARNESS_RENDER_TILE * HARNESS_RENDER_TILE) in;

layout(set = 0, binding = HARNESS_BINDING_RESULTS, std430) writeonly buffer PixelsBuffer { vec4 pixels[]; };

#ifdef HARNESS_MINIMAL_TRILINEAR
layout(set = 0, binding = HARNESS_BINDING_TEXTURE) uniform sampler2D u_texture;

vec4 minimal_bilinear(vec2 uv, int level, int side)
{
    int s = max(side >> level, 1);
    vec2 p = uv * float(s) - 0.5;
    vec2 cell = floor(p);
    vec2 f = p - cell;
    ivec2 i = ivec2(cell);
    int m = s - 1;
    vec4 a = texelFetch(u_texture, i & m, level);
    vec4 b = texelFetch(u_texture, (i + ivec2(1, 0)) & m, level);
    vec4 c = texelFetch(u_texture, (i + ivec2(0, 1)) & m, level);
    vec4 d = texelFetch(u_texture, (i + ivec2(1, 1)) & m, level);
    return mix(mix(a, b, f.x), mix(c, d, f.x), f.y);
}

vec4 minimal_trilinear(vec2 uv, vec2 dx, vec2 dy)
{
    int side = textureSize(u_texture, 0).x; // uniform: one query a pixel, not one a level
    int levels = textureQueryLevels(u_texture);
    float rho2 = max(dot(dx, dx), dot(dy, dy)) * float(side * side);
    float lod = clamp(0.5 * log2(rho2), 0.0, float(levels - 1));
    int lo = int(lod);
    int hi = min(lo + 1, levels - 1);
    return mix(minimal_bilinear(uv, lo, side), minimal_bilinear(uv, hi, side), lod - float(lo));
}
#endif

void main()
{
    ivec2 pixel = tf_quad_pixel(ivec2(gl_WorkGroupID.xy) * HARNESS_RENDER_TILE, HARNESS_RENDER_TILE);
    Hit h = scene_hit(scene, vec2(pixel) + 0.5);
    tf_Gradients g = tf_compute_quad_gradients(h.uv, TF_DERIVATIVES_FINE);
#ifdef HARNESS_MINIMAL_TRILINEAR
    vec4 color = minimal_trilinear(h.uv, g.dUVdx, g.dUVdy);
#else
    vec4 color = vec4(h.uv, g.dUVdx.x + g.dUVdy.y, g.dUVdx.y + g.dUVdy.x); // the lookup's inputs, kept live
#endif
    ivec2 size = scene.kindSize.yz;
    if (all(lessThan(pixel, size)))
        pixels[pixel.y * size.x + pixel.x] = h.hit ? color : scene.background;
}

#endif
