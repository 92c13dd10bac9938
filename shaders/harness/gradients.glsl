// Harness only: the uv gradients a render asked for (pc.gradients), for a ray-cast hit. Quad
// derivatives must run in uniform control flow, so every form is computed and one is kept.
#ifndef TF_HARNESS_GRADIENTS_GLSL
#define TF_HARNESS_GRADIENTS_GLSL

#include "scene.glsl"

tf_Gradients tf_harness_ray_gradients(tf_SceneParams scene, vec2 pixelCentre, tf_Hit h)
{
    return tf_ray_differential_gradients(tf_camera_ray(scene, pixelCentre), tf_camera_ray_dx(scene),
                                         tf_camera_ray_dy(scene), h.t, h.normal, h.dPdu, h.dPdv);
}

// What a pixel filters. Every lane filters, hit or miss, and the result is chosen afterwards: behind a
// branch, lavapipe still ran the lookup for the missed lanes of a SIMD batch, with the uv and gradients
// of the unbounded surface (enormous past its horizon), and its anisotropic sampler spent a minute a
// frame on the slanted scene. A miss filters a tiny isotropic footprint at the texture's centre instead.
struct tf_Lookup {
    vec2 uv, dUVdx, dUVdy;
};

tf_Lookup tf_harness_lookup(tf_Hit h, tf_Gradients g)
{
    if (h.hit)
        return tf_Lookup(h.uv, g.dUVdx, g.dUVdy);
    return tf_Lookup(vec2(0.5), vec2(1e-4, 0.0), vec2(0.0, 1e-4));
}

#endif
