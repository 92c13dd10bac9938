// Harness only: the uv gradients a render asked for (GRADIENTS_ID), for a ray-cast hit: quads (seam-free
// where the scene's uv wraps), ray differentials or ray cones. Quad derivatives must run in uniform control
// flow, so every form is computed and one is kept.
#ifndef HARNESS_GRADIENTS_GLSL
#define HARNESS_GRADIENTS_GLSL

#include "scene.glsl"

tf_Gradients ray_gradients(SceneParams scene, vec2 pixelCentre, Hit h)
{
    return tf_ray_differential_gradients(camera_ray(scene, pixelCentre), camera_ray_dx(scene),
                                         camera_ray_dy(scene), h.t, h.normal, h.dPdu, h.dPdv);
}

// The primary ray cone at the hit: width gamma·distance (h.t is in units of the unnormalised camera ray).
tf_Gradients cone_gradients(SceneParams scene, vec2 pixelCentre, Hit h)
{
    vec3 d = camera_ray(scene, pixelCentre);
    tf_RayCone cone = tf_ray_cone_propagate(tf_RayCone(0.0, camera_pixel_spread(scene)), h.t * length(d));
    return tf_ray_cone_gradients(d, cone.width, h.normal, h.dPdu, h.dPdv);
}

// The uv axes that wrap with period 1, from the scene description: the tunnel's u (p0.z whole turns of the
// texture around the axis). Quad differences there take Tarini's seam-free form.
// A constant where the pipeline is specialised to the scene (scene_kind): then a plane's frame holds no second
// gradient pass, its result unused.
bvec2 scene_periodic_axes(SceneParams scene) { return bvec2(scene_kind(scene) == HARNESS_SCENE_CYLINDER, false); }

// The second quantity Tarini's selection differences: uv shifted by half a period, then wrapped.
vec2 half_period_shift(vec2 uv) { return fract(uv + 0.5); }

// Tarini's selection from the differences of uv (g) and of half_period_shift(uv) (shifted), on the scene's
// periodic axes (none: g as it is).
tf_Gradients scene_quad_gradients(SceneParams scene, tf_Gradients g, tf_Gradients shifted)
{
    return tf_periodic_gradients(g, shifted, scene_periodic_axes(scene));
}

// What a pixel filters. Every lane filters, hit or miss, and the hit picks the result afterwards: behind
// a branch, lavapipe still ran the lookup for the missed lanes of a SIMD batch. Its anisotropic sampler
// is an EWA that scans the bounding box of an ellipse made from the quad's uv differences (not the
// gradients passed), for as long as any lane of the batch, masked ones included, has texels left. Missed
// lanes carried the unbounded surface's uv, enormous near its horizon, and one frame of the plane or
// the slanted scene took up to a minute. So a missed lane takes the uv of a quad neighbour that hit (no
// spread for the ellipse), or 0.5 in an all-miss quad, with gradients of one texture per pixel.
struct PixelLookup {
    vec2 uv, dUVdx, dUVdy;
};

// One step of that adoption. q = (uv, 1) where the lane has a uv (hit or adopted), (0, 0, 0) where not;
// across, down: the horizontal and vertical quad neighbours' q. Two steps reach the diagonal neighbour.
vec3 adopt_uv(vec3 q, vec3 across, vec3 down)
{
    return q.z > 0.5 ? q : across.z > 0.5 ? across : down.z > 0.5 ? down : q;
}

vec3 uv_or_none(Hit h) { return h.hit ? vec3(h.uv, 1.0) : vec3(0.0); }

PixelLookup pixel_lookup(Hit h, tf_Gradients g, vec3 adopted)
{
    if (h.hit)
        return PixelLookup(h.uv, g.dUVdx, g.dUVdy);
    return PixelLookup(adopted.z > 0.5 ? adopted.xy : vec2(0.5), vec2(1.0, 0.0), vec2(0.0, 1.0));
}

#endif
