// texfilter/derivatives.glsl — UV gradients for the filters, in every stage: 2x2 quad differences in the
// fragment stage (fine or coarse, plain or seam-free on periodic uv), the same quads built in compute from
// subgroup quad operations, and ray differentials (through a mirror too) and ray cones for ray tracing.
//
// Use:     struct tf_Gradients { vec2 dUVdx, dUVdy; }; // change of uv one pixel right / down: the filters'
//                                                      // dUVdx, dUVdy for any resource kind or texel source
//          fragment (macros over dFdx/dFdy):
//                  tf_Gradients tf_quad_gradients_fine(vec2 uv);   // dFdxFine / dFdyFine
//                  tf_Gradients tf_quad_gradients_coarse(vec2 uv); // dFdxCoarse / dFdyCoarse
//                  tf_Gradients tf_quad_gradients_fine_periodic(vec2 uv);   // seam-free on wrapping uv
//                  tf_Gradients tf_quad_gradients_coarse_periodic(vec2 uv);
//          compute, with TF_COMPUTE_QUADS:
//                  ivec2 tf_quad_pixel(ivec2 tileOrigin, int tileWidth); // the pixel this invocation shades
//                  tf_Gradients tf_compute_quad_gradients(vec2 uv, int mode); // TF_DERIVATIVES_FINE / _COARSE
//                  tf_Gradients tf_compute_quad_gradients_periodic(vec2 uv, int mode);
//          any stage:
//                  tf_Gradients tf_periodic_gradients(tf_Gradients g, tf_Gradients gShifted, bvec2 periodic);
//                  tf_Gradients tf_ray_differential_gradients(vec3 dir, vec3 dDirdx, vec3 dDirdy, float t,
//                                                             vec3 normal, vec3 dPdu, vec3 dPdv);
//                  tf_RayDifferentials tf_transfer_ray_differentials(vec3 dir, float t, vec3 n,
//                                                                    tf_RayDifferentials rd);
//                  tf_RayDifferentials tf_reflect_ray_differentials(vec3 dir, vec3 n, vec3 dNdx, vec3 dNdy,
//                                                                   tf_RayDifferentials rd);
//                  float tf_ray_cone_pixel_spread(float fovY, float heightPixels); // gamma
//                  tf_RayCone tf_ray_cone_propagate(tf_RayCone cone, float distance);
//                  tf_RayCone tf_ray_cone_reflect(tf_RayCone cone, float curvature);
//                  tf_Gradients tf_ray_cone_gradients(vec3 dir, float width, vec3 normal, vec3 dPdu, vec3 dPdv);
//                  tf_DirGradients tf_ray_cone_direction_gradients(vec3 dir, vec3 side, float spreadSide,
//                                                                  float spreadOther);
//                  tf_DirGradients tf_ray_cone_reflect_direction_gradients(vec3 dir, vec3 n, tf_RayCone cone,
//                                                                          float curvature);
// Math:    fine dx = p(x|1, y) − p(x&~1, y), dy = p(x, y|1) − p(x, y&~1) within each 2x2 quad; coarse: one pair
//          for the quad from its top-left pixel (Vulkan allows any pixel; the compute form and the CPU
//          reference use the top-left). Periodic (Tarini 2012): per component the smaller of the differences
//          of uv and of fract(uv + 0.5). Ray differentials (Igehy 1999): the hit's dP projected onto the
//          surface, mapped to uv by dPdu, dPdv. Ray cones (Akenine-Möller et al. 2019, 2021): the cone's
//          cross-section of width w projected onto the tangent plane, its two axes mapped to uv. Below, more.
// Options: TF_COMPUTE_QUADS: define before including, in a compute shader that also enables
//          #extension GL_KHR_shader_subgroup_quad : require (before the include); adds tf_quad_pixel and
//          tf_compute_quad_gradients[_periodic]. The fragment helpers are macros, so this file also compiles
//          in stages without dFdx.
// Needs:   nothing bound. Periodic forms: the texture must repeat (TF_WRAP_REPEAT) on a periodic axis; exact
//          while the true difference is under half a period a pixel. Compute quads: lanes 4q..4q+3 of a
//          subgroup form quad q (bit 0 = x, bit 1 = y); a subgroup size that is a multiple of 4, a workgroup
//          size that is a multiple of it (ask for full subgroups), and every invocation of a quad must run the
//          quad operation (keep out-of-image invocations alive until after it). Ray differentials: a pinhole
//          camera (offset rays share the origin). Ray cones: isotropic curvature only (sphere, plane).
// Cost:    no texel fetch. fine: 2 quad swaps; coarse: 3 quad broadcasts; periodic: the same on a vec4
//          (+ 2 fract, 4 compares); ray differentials: ~40 flops; a mirror's transfer + reflection ~60;
//          ray cone gradients ~50 flops and 2 normalizations; direction footprints ~20 flops.
// Degenerate input: non-finite ray input, a ray parallel to the surface (cos theta = 0) or dPdu parallel to
//          dPdv give non-finite gradients, which every filter reads as "blur fully" (coarsest level); zero
//          width or spread (t = 0 at the eye) gives zero gradients (the finest level); NaN in uv gives NaN
//          periodic gradients. Defined, never a hang.
// Example: tf_Gradients g = tf_quad_gradients_fine(uv);
//          vec4 c = tf_trilinear(tex, uv, g.dUVdx, g.dUVdy, tf_sampler(TF_WRAP_REPEAT));
//          // ray tracing: tf_RayCone cone = tf_ray_cone_propagate(tf_RayCone(0.0, gamma), hitDistance);
//          tf_Gradients gc = tf_ray_cone_gradients(rayDir, cone.width, n, dPdu, dPdv);
#ifndef TF_DERIVATIVES_GLSL
#define TF_DERIVATIVES_GLSL

// Compute layout: invocations form quads by subgroup invocation id (lanes 4q..4q+3 = one quad; lane bit 0
//          = x, bit 1 = y), which is what subgroupQuadSwapHorizontal/Vertical exchange across. tf_quad_pixel
//          maps a 1-D workgroup onto a tile of quads (tileWidth even), using gl_SubgroupID and
//          gl_SubgroupInvocationID so the quads match the hardware's quads whatever the subgroup size
//          (8, 32 and 64 are common); it needs a subgroup size that is a multiple of 4 (all of
//          these) and a workgroup size that is a multiple of the subgroup size (ask for full subgroups), and
//          every invocation of a quad must run the quad operation (keep out-of-image invocations alive
//          until after it, then discard their result).
// Periodic (Tarini 2012): where uv wraps (a cylinder's or sphere's u, in units of whole texture periods),
//          the quad difference across the seam jumps by a whole number of periods and the filter drops to
//          its coarsest level (a line of blurred quads). The _periodic forms take, per component, the
//          smaller of the differences of uv and of fract(uv + 0.5) (the plain one while it is at most half a
//          period, so away from seams nothing changes, bit for bit): the latter has its jumps half a period
//          away from uv's, and both are exact away from their own jumps. Right where the true difference is
//          under half a period a pixel (anything a filter can show sharply); at or above it the smaller one
//          may be the aliased one. Wrap mode: the texture must repeat (TF_WRAP_REPEAT) on a periodic axis.
//          The _periodic macros and tf_compute_quad_gradients_periodic treat both axes as periodic (a
//          difference under half a period is kept either way); tf_periodic_gradients(g, gShifted, mask)
//          takes the two sets of differences, from any source, and a mask of the axes that wrap.
// Ray differentials (Igehy 1999): dir the ray direction (any length), dDirdx/dDirdy its change one pixel
//          right/down, t the hit's ray parameter (hit = origin + t·dir), normal and the tangents dPdu, dPdv
//          (position change per unit u, v) of the hit surface; pinhole camera (offset rays share the origin).
//          Through a mirror: tf_transfer_ray_differentials moves the differentials (dP, dD) to the hit,
//          the caller turns dP into the normal's change (sphere of radius R: dN = dP / R), and
//          tf_reflect_ray_differentials gives the reflected ray's (dP kept, dD of reflect(dir, n)).
// Ray cones (Akenine-Möller et al. 2019, 2021): a cone of width w at the hit and spread angle gamma a
//          pixel (primary rays: w = 0 at the eye, gamma = tf_ray_cone_pixel_spread(fovY, height), w grows
//          by gamma a unit of distance: tf_ray_cone_propagate). tf_ray_cone_gradients projects the cone's
//          circular cross-section (diameter w) along dir onto the tangent plane (an ellipse: w across the
//          plane of incidence, w / |cos theta| along it) and maps its two axes to uv: those are the
//          gradients, so every filter takes them unchanged. A mirror of curvature k (1/R for a convex
//          sphere, 0 for a plane, negative concave) adds beta = 2 k w to the spread (tf_ray_cone_reflect:
//          the isotropic cone, exact at normal incidence); tf_ray_cone_reflect_direction_gradients gives
//          the reflected cone's direction footprint for tf_*_cube / tf_*_latlong (two vectors perpendicular
//          to the reflected direction: gamma + 2 k w |cos theta| across the plane of incidence, gamma +
//          2 k w / |cos theta| within it), tf_ray_cone_direction_gradients an unreflected one (a sky).
//          A cone is isotropic where a pixel is not: for a pinhole and a plane the cone's footprint is the
//          ray differentials' at the image centre and up to 1/cos^2(phi) larger at phi off the axis
//          (docs/DERIVATIVES.md). Isotropic curvature only (sphere, plane); a general surface's two
//          principal curvatures are not modelled.

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

// Tarini's selection: per component, the difference of uv (g) or of fract(uv + 0.5) (gShifted), whichever is
// smaller in magnitude, on the axes `periodic` marks (the others keep g). g is kept while it is at most half
// a period: there both are the same change (a smaller gShifted differs only by its own rounding), so away
// from a seam the result is the plain quads' bit for bit. NaN in g stays NaN.
bvec2 tfi_take_shifted(vec2 g, vec2 gShifted, bvec2 periodic)
{
    bvec2 jump = greaterThan(abs(g), vec2(0.5));
    bvec2 smaller = lessThan(abs(gShifted), abs(g));
    return bvec2(periodic.x && jump.x && smaller.x, periodic.y && jump.y && smaller.y);
}
tf_Gradients tf_periodic_gradients(tf_Gradients g, tf_Gradients gShifted, bvec2 periodic)
{
    return tf_Gradients(mix(g.dUVdx, gShifted.dUVdx, tfi_take_shifted(g.dUVdx, gShifted.dUVdx, periodic)),
                        mix(g.dUVdy, gShifted.dUVdy, tfi_take_shifted(g.dUVdy, gShifted.dUVdy, periodic)));
}

// uv and its half-period shift in one vec4, so one derivative instruction serves both.
vec4 tfi_periodic_pair(vec2 uv) { return vec4(uv, fract(uv + 0.5)); }
tf_Gradients tfi_periodic_from_pair(vec4 dx, vec4 dy)
{
    return tf_periodic_gradients(tf_Gradients(dx.xy, dy.xy), tf_Gradients(dx.zw, dy.zw), bvec2(true));
}
#define tf_quad_gradients_fine_periodic(uv) \
    tfi_periodic_from_pair(dFdxFine(tfi_periodic_pair(uv)), dFdyFine(tfi_periodic_pair(uv)))
#define tf_quad_gradients_coarse_periodic(uv) \
    tfi_periodic_from_pair(dFdxCoarse(tfi_periodic_pair(uv)), dFdyCoarse(tfi_periodic_pair(uv)))

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

// tf_compute_quad_gradients of uv and of fract(uv + 0.5) in one vec4, then Tarini's selection on both axes.
tf_Gradients tf_compute_quad_gradients_periodic(vec2 uv, int mode)
{
    vec4 q = tfi_periodic_pair(uv), dx, dy;
    if (mode == TF_DERIVATIVES_COARSE) {
        vec4 topLeft = subgroupQuadBroadcast(q, 0u);
        dx = subgroupQuadBroadcast(q, 1u) - topLeft;
        dy = subgroupQuadBroadcast(q, 2u) - topLeft;
    } else {
        vec4 across = subgroupQuadSwapHorizontal(q), down = subgroupQuadSwapVertical(q);
        uint lane = gl_SubgroupInvocationID & 3u;
        dx = (lane & 1u) != 0u ? q - across : across - q;
        dy = (lane & 2u) != 0u ? q - down : down - q;
    }
    return tfi_periodic_from_pair(dx, dy);
}

#endif

// Position changes dPdx, dPdy in the tangent plane of a surface with tangents dPdu, dPdv, in uv: solve
// [dPdu dPdv] (du, dv)ᵀ = dP in the least-squares sense (exact for dP in the tangent plane).
tf_Gradients tfi_tangent_to_uv(vec3 dPdx, vec3 dPdy, vec3 dPdu, vec3 dPdv)
{
    float a = dot(dPdu, dPdu), b = dot(dPdu, dPdv), c = dot(dPdv, dPdv);
    float inverseDet = 1.0 / (a * c - b * b);
    vec2 x = vec2(dot(dPdx, dPdu), dot(dPdx, dPdv)), y = vec2(dot(dPdy, dPdu), dot(dPdy, dPdv));
    return tf_Gradients(inverseDet * vec2(c * x.x - b * x.y, a * x.y - b * x.x),
                        inverseDet * vec2(c * y.x - b * y.y, a * y.y - b * y.x));
}

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
    return tfi_tangent_to_uv(dPdx, dPdy, dPdu, dPdv);
}

// A ray's differentials (Igehy 1999): how its origin (or hit point) and direction change one pixel right
// (x) and down (y). A pinhole's primary ray: dPdx = dPdy = 0, dDdx, dDdy the camera's per-pixel steps.
struct tf_RayDifferentials {
    vec3 dPdx, dPdy; // position
    vec3 dDdx, dDdy; // direction (of the dir the functions are given: any length)
};

// Moves the differentials of a ray (origin o, direction dir) to its hit o + t·dir on a surface with normal n
// (any length): the offset rays meet the hit's tangent plane (dt = −(dP + t dD)·n / (dir·n)). dD is kept.
// A ray parallel to the surface (dir·n = 0) gives non-finite dP.
tf_RayDifferentials tf_transfer_ray_differentials(vec3 dir, float t, vec3 n, tf_RayDifferentials rd)
{
    float dn = dot(dir, n);
    vec3 px = rd.dPdx + t * rd.dDdx, py = rd.dPdy + t * rd.dDdy;
    return tf_RayDifferentials(px - (dot(px, n) / dn) * dir, py - (dot(py, n) / dn) * dir, rd.dDdx, rd.dDdy);
}

// Reflects the differentials of a ray that hit a mirror, after tf_transfer_ray_differentials: n the unit
// normal at the hit, dNdx, dNdy its change one pixel right/down (from rd.dPdx, dPdy and the surface: a
// sphere of radius R has dN = dP / R; a plane 0). Returns the differentials of reflect(dir, n) = dir −
// 2 (dir·n) n (the same length as dir): dP kept, dD = dD − 2 ((dir·n) dN + (dD·n + dir·dN) n).
tf_RayDifferentials tf_reflect_ray_differentials(vec3 dir, vec3 n, vec3 dNdx, vec3 dNdy, tf_RayDifferentials rd)
{
    float dn = dot(dir, n);
    vec3 rx = rd.dDdx - 2.0 * (dn * dNdx + (dot(rd.dDdx, n) + dot(dir, dNdx)) * n);
    vec3 ry = rd.dDdy - 2.0 * (dn * dNdy + (dot(rd.dDdy, n) + dot(dir, dNdy)) * n);
    return tf_RayDifferentials(rd.dPdx, rd.dPdy, rx, ry);
}

// A ray cone (Akenine-Möller et al. 2019): its width at the current point and its spread angle (radians).
struct tf_RayCone {
    float width;
    float spread;
};

// The spread angle of one pixel of a pinhole camera: gamma = atan(2 tan(fovY / 2) / heightPixels).
float tf_ray_cone_pixel_spread(float fovY, float heightPixels) { return atan(2.0 * tan(0.5 * fovY) / heightPixels); }

// The cone after `distance` (world units along the unit direction): w' = w + gamma·distance.
tf_RayCone tf_ray_cone_propagate(tf_RayCone cone, float distance)
{
    return tf_RayCone(cone.width + cone.spread * distance, cone.spread);
}

// The cone reflected by a mirror of curvature k (1/R convex sphere, 0 plane, −1/R concave): the width is
// kept, the spread gains beta = 2 k w (the normal turns by k w across the cone, the reflection doubles it).
// Isotropic: exact at normal incidence; tf_ray_cone_reflect_direction_gradients has the anisotropic form.
tf_RayCone tf_ray_cone_reflect(tf_RayCone cone, float curvature)
{
    return tf_RayCone(cone.width, cone.spread + 2.0 * curvature * cone.width);
}

// A unit vector perpendicular to unit v: v × the coordinate axis least aligned with v (ties: x, then y).
vec3 tfi_any_perpendicular(vec3 v)
{
    vec3 a = abs(v);
    vec3 axis = a.x <= a.y && a.x <= a.z ? vec3(1.0, 0.0, 0.0) : a.y <= a.z ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0);
    return normalize(cross(v, axis));
}

// The unit axis across the plane of incidence, d × n normalized (both unit), or any perpendicular of d
// within 1e-4 of normal incidence, where d × n has no direction to speak of.
vec3 tfi_incidence_side(vec3 d, vec3 n)
{
    vec3 side = cross(d, n);
    float len = length(side);
    return len > 1e-4 ? side / len : tfi_any_perpendicular(d);
}

// uv gradients of a ray cone of width `width` (world units, at the hit) along dir (any length) on a surface
// with normal n (any length) and tangents dPdu, dPdv: the cone's circular cross-section, projected along dir
// onto the tangent plane, is an ellipse whose two axes (diameters) are the gradients in uv: dUVdx across the
// plane of incidence (length w in the plane), dUVdy within it (w / |cos theta|). Grazing rays (cos theta = 0)
// give non-finite gradients ("blur fully"), width 0 zero gradients.
tf_Gradients tf_ray_cone_gradients(vec3 dir, float width, vec3 n, vec3 dPdu, vec3 dPdv)
{
    vec3 d = normalize(dir), nu = normalize(n);
    vec3 side = tfi_incidence_side(d, nu);
    vec3 along = cross(side, d); // unit, perpendicular to d, in the plane of incidence
    float dn = dot(d, nu);
    vec3 p1 = width * (side - (dot(side, nu) / dn) * d);  // side lies in the tangent plane up to rounding
    vec3 p2 = width * (along - (dot(along, nu) / dn) * d);
    return tfi_tangent_to_uv(p1, p2, dPdu, dPdv);
}

// Direction gradients for the environment filters (tf_*_cube, tf_*_latlong take dDirdx, dDirdy): a cone
// around dir (any length) seen from afar, an ellipse of angular diameters spreadSide along `side` (made
// perpendicular to dir) and spreadOther across it; both vectors are scaled by |dir|, as the change of dir.
struct tf_DirGradients {
    vec3 dDirdx, dDirdy;
};
tf_DirGradients tf_ray_cone_direction_gradients(vec3 dir, vec3 side, float spreadSide, float spreadOther)
{
    float len = length(dir);
    vec3 d = dir / len;
    vec3 s = side - dot(side, d) * d;
    float sl = length(s);
    s = sl > 1e-4 * length(side) ? s / sl : tfi_any_perpendicular(d);
    return tf_DirGradients(s * (spreadSide * len), cross(d, s) * (spreadOther * len));
}

// The direction footprint of a cone reflected by a mirror of curvature k (see tf_ray_cone_reflect) at a hit
// with unit normal n, dir the incoming direction (any length): around r = reflect(dir, n), gamma + 2 k w
// |cos theta| across the plane of incidence (dDirdx) and gamma + 2 k w / |cos theta| within it (dDirdy), both
// scaled by |dir| (= |r|). Grazing incidence gives a non-finite dDirdy.
tf_DirGradients tf_ray_cone_reflect_direction_gradients(vec3 dir, vec3 n, tf_RayCone cone, float curvature)
{
    vec3 d = normalize(dir);
    float c = abs(dot(d, n));
    vec3 r = dir - 2.0 * dot(dir, n) * n;
    float bend = 2.0 * curvature * cone.width;
    return tf_ray_cone_direction_gradients(r, tfi_incidence_side(d, n), cone.spread + bend * c, cone.spread + bend / c);
}

#endif
