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

#endif
