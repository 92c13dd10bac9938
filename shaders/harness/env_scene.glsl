// Harness only: the environment scenes' lookups (HARNESS_SCENE_SKYBOX, HARNESS_SCENE_REFLECT): a direction a
// pixel and its ray differentials. The CPU twin is host/reference/env_cast.cpp (in double).
//
// Use:     #include "env_scene.glsl" (after scene.glsl's SceneParams, which it includes);
//          EnvHit h = env_hit(scene, pixelCentre); then tf_X_cube(tex, h.dir, h.dirDx, h.dirDy, ...), or the
//          same direction's quad differences (dFdxFine(h.dir), ...) for fine and coarse gradients.
// Scenes:  skybox: the camera ray (not normalised: linear in the pixel position, so quad differences are
//          its exact derivatives). reflect: a mirror sphere (scene.p0.xyz centre, scene.p0.w radius) seen
//          from outside; a ray that hits it looks up reflect(d / |d|, n) (unit length), one that misses its
//          own camera ray (the sky behind).
// Output:  dirDx, dirDy are the exact derivatives of dir with respect to the pixel position (x right, y
//          down): the camera's per-pixel steps on a miss, Igehy's transfer through the reflection, with the
//          sphere's normal derivative, on a hit (tf_transfer_ray_differentials, tf_reflect_ray_differentials).
//          coneDx, coneDy: the ray cone's direction footprint (spread gamma = camera_pixel_spread; on a hit
//          the cone of width gamma t reflected by the sphere's curvature 1 / radius).
// Cost:    a ray-sphere intersection and about a hundred multiply-adds; no loops, no texture access.
#ifndef HARNESS_ENV_SCENE_GLSL
#define HARNESS_ENV_SCENE_GLSL

#include "scene.glsl"
#include "texfilter/derivatives.glsl" // the mirror's differential transfer and the ray cones

struct EnvHit {
    vec3 dir;    // the lookup direction (any length but zero)
    bool mirror; // reflect: the ray hit the sphere (dir is the reflected direction)
    vec3 dirDx;  // d(dir)/dx, one pixel right
    vec3 dirDy;  // d(dir)/dy, one pixel down
    vec3 coneDx; // the ray cone's direction footprint (texfilter/derivatives.glsl): across the plane of
    vec3 coneDy; // incidence and within it (reflect), along the camera's right and up (a sky pixel)
};

EnvHit env_hit(SceneParams scene, vec2 pixelCentre)
{
    vec3 d = camera_ray(scene, pixelCentre);
    vec3 dDdx = camera_ray_dx(scene), dDdy = camera_ray_dy(scene);
    float spread = camera_pixel_spread(scene);
    tf_DirGradients sky = tf_ray_cone_direction_gradients(d, scene.right.xyz, spread, spread);
    if (scene.kindSize.x != HARNESS_SCENE_REFLECT)
        return EnvHit(d, false, dDdx, dDdy, sky.dDirdx, sky.dDirdy);

    // The nearer root of |o + t u - c| = r with u the unit ray: t = -b - sqrt(b^2 - (|o - c|^2 - r^2)).
    float len = length(d);
    vec3 u = d / len;
    vec3 oc = scene.origin.xyz - scene.p0.xyz;
    float radius = scene.p0.w;
    float b = dot(oc, u);
    float disc = b * b - (dot(oc, oc) - radius * radius);
    float t = -b - sqrt(max(disc, 0.0));
    if (disc < 0.0 || t <= 0.0)
        return EnvHit(d, false, dDdx, dDdy, sky.dDirdx, sky.dDirdy);

    vec3 p = scene.origin.xyz + t * u;
    vec3 n = (p - scene.p0.xyz) / radius;
    vec3 r = u - 2.0 * dot(u, n) * n;

    // Igehy's transfer for the unit ray u (its derivative: the camera step without its part along u, over
    // |d|) to the hit, the sphere's normal derivative there (dN = dP / radius), then the reflection.
    tf_RayDifferentials camera = tf_RayDifferentials(vec3(0.0), vec3(0.0), (dDdx - u * dot(u, dDdx)) / len,
                                                     (dDdy - u * dot(u, dDdy)) / len);
    tf_RayDifferentials atHit = tf_transfer_ray_differentials(u, t, n, camera);
    tf_RayDifferentials reflected = tf_reflect_ray_differentials(u, n, atHit.dPdx / radius, atHit.dPdy / radius, atHit);
    // The primary cone (width gamma t at the hit), reflected by the sphere's curvature 1 / radius.
    tf_DirGradients cone = tf_ray_cone_reflect_direction_gradients(u, n, tf_RayCone(spread * t, spread), 1.0 / radius);
    return EnvHit(r, true, reflected.dDdx, reflected.dDdy, cone.dDirdx, cone.dDirdy);
}

#endif
