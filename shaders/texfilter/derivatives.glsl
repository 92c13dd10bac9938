// texfilter/derivatives.glsl — UV gradients for the filters, in every stage: 2x2 quad differences in
// the fragment stage (fine or coarse), the same quads built in compute from subgroup quad operations,
// and ray differentials for ray-tracing stages, where no quads exist.
//
// Use (fragment):  tf_Gradients tf_quad_gradients_fine(vec2 uv);   // macro: dFdxFine / dFdyFine
//                  tf_Gradients tf_quad_gradients_coarse(vec2 uv); // macro: dFdxCoarse / dFdyCoarse
// Use (compute, with TF_COMPUTE_QUADS):
//                  ivec2 tf_quad_pixel(ivec2 tileOrigin, int tileWidth); // the pixel this invocation shades
//                  tf_Gradients tf_compute_quad_gradients(vec2 uv, int mode); // TF_DERIVATIVES_FINE / _COARSE
// Use (any stage): tf_Gradients tf_ray_differential_gradients(vec3 dir, vec3 dDirdx, vec3 dDirdy, float t,
//                                                             vec3 normal, vec3 dPdu, vec3 dPdv);
//                  struct tf_Gradients { vec2 dUVdx, dUVdy; }; // change of uv one pixel right / down
// Options: TF_COMPUTE_QUADS: define before including, in a compute shader that also enables
//          #extension GL_KHR_shader_subgroup_quad : require (before the include: glslang predefines
//          extension macros, so this is opt-in); adds tf_quad_pixel and tf_compute_quad_gradients.
//          The fragment helpers are macros, so this file also compiles in stages without dFdx.
// Needs:   nothing bound. Conventions (DESIGN.md §3, docs/DERIVATIVES.md):
//          fine dx = p(x|1, y) − p(x&~1, y), dy = p(x, y|1) − p(x, y&~1) within each
//          2x2 quad; coarse: one pair for the whole quad, taken from its top-left pixel (dx along the top
//          row, dy down the left column). Vulkan lets coarse derivatives come from any pixel of the quad;
//          the compute version and the CPU reference use the top-left one.
// Compute layout: invocations form quads by subgroup invocation id (lanes 4q..4q+3 = one quad; lane bit 0
//          = x, bit 1 = y), which is what subgroupQuadSwapHorizontal/Vertical exchange across. tf_quad_pixel
//          maps a 1-D workgroup onto a tile of quads (tileWidth even), using gl_SubgroupID and
//          gl_SubgroupInvocationID so the quads match the hardware's quads whatever the subgroup size
//          (lavapipe: 8; NVIDIA: 32; AMD: 32/64); it needs a subgroup size that is a multiple of 4 (all of
//          these) and a workgroup size that is a multiple of the subgroup size (ask for full subgroups), and
//          every invocation of a quad must run the quad operation (keep out-of-image invocations alive
//          until after it, then discard their result).
// Ray differentials (Igehy 1999): dir the ray direction (any length), dDirdx/dDirdy its change one pixel
//          right/down, t the hit's ray parameter (hit = origin + t·dir), normal and the tangents dPdu, dPdv
//          (position change per unit u, v) of the hit surface; pinhole camera (offset rays share the origin).
// Cost:    no texel fetch. fine: 2 quad swaps; coarse: 3 quad broadcasts; ray differentials: ~40 flops.
// Degenerate input: non-finite ray input, a ray parallel to the surface or dPdu parallel to dPdv give
//          non-finite gradients, which every filter reads as "blur fully" (coarsest level).
// Example: tf_Gradients g = tf_quad_gradients_fine(uv);
//          vec4 c = tf_trilinear(tex, uv, g.dUVdx, g.dUVdy, tf_sampler(TF_WRAP_REPEAT));
#ifndef TF_DERIVATIVES_GLSL
#define TF_DERIVATIVES_GLSL

#include "common.glsl" // tf_Sampler and the wrap modes, which callers pass with these gradients

#define TF_DERIVATIVES_FINE 0
#define TF_DERIVATIVES_COARSE 1

struct tf_Gradients {
    vec2 dUVdx; // change of uv one pixel to the right
    vec2 dUVdy; // change of uv one pixel down
};

// Fragment stage only (macros: dFdx does not exist in other stages).
#define tf_quad_gradients_fine(uv) tf_Gradients(dFdxFine(uv), dFdyFine(uv))
#define tf_quad_gradients_coarse(uv) tf_Gradients(dFdxCoarse(uv), dFdyCoarse(uv))

#ifdef TF_COMPUTE_QUADS

// Pixel of this invocation: quads laid out row by row over a tile tileWidth pixels wide (even), starting at
// tileOrigin. Invocation p = gl_SubgroupID * gl_SubgroupSize + gl_SubgroupInvocationID; quad p/4, lane p%4.
ivec2 tf_quad_pixel(ivec2 tileOrigin, int tileWidth)
{
    int p = int(gl_SubgroupID * gl_SubgroupSize + gl_SubgroupInvocationID);
    int quad = p >> 2, quadsPerRow = tileWidth >> 1;
    ivec2 quadOrigin = 2 * ivec2(quad % quadsPerRow, quad / quadsPerRow);
    return tileOrigin + quadOrigin + ivec2(p & 1, (p >> 1) & 1);
}

// The fragment stage's quad derivatives, from the 2x2 quad this invocation belongs to (see the layout above).
tf_Gradients tf_compute_quad_gradients(vec2 uv, int mode)
{
    if (mode == TF_DERIVATIVES_COARSE) {
        vec2 topLeft = subgroupQuadBroadcast(uv, 0u);
        return tf_Gradients(subgroupQuadBroadcast(uv, 1u) - topLeft, subgroupQuadBroadcast(uv, 2u) - topLeft);
    }
    vec2 across = subgroupQuadSwapHorizontal(uv), down = subgroupQuadSwapVertical(uv);
    uint lane = gl_SubgroupInvocationID & 3u;
    return tf_Gradients((lane & 1u) != 0u ? uv - across : across - uv, (lane & 2u) != 0u ? uv - down : down - uv);
}

#endif

// Ray differentials (Igehy 1999) for a hit at distance t along direction dir (not necessarily unit) with
// dDirdx/dDirdy the change of dir one pixel right/down, on a surface with normal n and tangents dPdu, dPdv
// (the change of position per unit of u and v). The offset rays are intersected with the hit's tangent
// plane and the position change is expressed in (u, v). Non-finite or degenerate input (ray parallel
// to the surface, dPdu parallel to dPdv) gives non-finite gradients, which the filters read as "blur
// fully" (coarsest level): defined, never a hang.
tf_Gradients tf_ray_differential_gradients(vec3 dir, vec3 dDirdx, vec3 dDirdy, float t, vec3 n, vec3 dPdu, vec3 dPdv)
{
    float dn = dot(dir, n);
    // Position change of the offset ray's hit on the tangent plane (ray origins shared, as for a pinhole).
    vec3 dPdx = t * (dDirdx - (dot(dDirdx, n) / dn) * dir);
    vec3 dPdy = t * (dDirdy - (dot(dDirdy, n) / dn) * dir);
    // Solve [dPdu dPdv] (du, dv)ᵀ = dP in the least-squares sense (exact for dP in the tangent plane).
    float a = dot(dPdu, dPdu), b = dot(dPdu, dPdv), c = dot(dPdv, dPdv);
    float inverseDet = 1.0 / (a * c - b * b);
    vec2 x = vec2(dot(dPdx, dPdu), dot(dPdx, dPdv)), y = vec2(dot(dPdy, dPdu), dot(dPdy, dPdv));
    return tf_Gradients(inverseDet * vec2(c * x.x - b * x.y, a * x.y - b * x.x),
                        inverseDet * vec2(c * y.x - b * y.y, a * y.y - b * y.x));
}

#endif
