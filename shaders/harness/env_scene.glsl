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
//          sphere's normal derivative, on a hit.
// Cost:    a ray-sphere intersection and a few dozen multiply-adds; no loops, no texture access.
#ifndef HARNESS_ENV_SCENE_GLSL
#define HARNESS_ENV_SCENE_GLSL

#include "scene.glsl"

struct EnvHit {
    vec3 dir;    // the lookup direction (any length but zero)
    bool mirror; // reflect: the ray hit the sphere (dir is the reflected direction)
    vec3 dirDx;  // d(dir)/dx, one pixel right
    vec3 dirDy;  // d(dir)/dy, one pixel down
};

EnvHit env_hit(SceneParams scene, vec2 pixelCentre)
{
    vec3 d = camera_ray(scene, pixelCentre);
    vec3 dDdx = camera_ray_dx(scene), dDdy = camera_ray_dy(scene);
    if (scene.kindSize.x != HARNESS_SCENE_REFLECT)
        return EnvHit(d, false, dDdx, dDdy);

    // The nearer root of |o + t u - c| = r with u the unit ray: t = -b - sqrt(b^2 - (|o - c|^2 - r^2)).
    float len = length(d);
    vec3 u = d / len;
    vec3 oc = scene.origin.xyz - scene.p0.xyz;
    float radius = scene.p0.w;
    float b = dot(oc, u);
    float disc = b * b - (dot(oc, oc) - radius * radius);
    float t = -b - sqrt(max(disc, 0.0));
    if (disc < 0.0 || t <= 0.0)
        return EnvHit(d, false, dDdx, dDdy);

    vec3 p = scene.origin.xyz + t * u;
    vec3 n = (p - scene.p0.xyz) / radius;
    float un = dot(u, n);
    vec3 r = u - 2.0 * un * n;

    // Igehy's transfer: the unit ray's derivative, the hit point's (t changes so the point stays on the
    // sphere: dt = -t (du . n) / (u . n)), the normal's (dn = dp / radius on a sphere), then the reflection's.
    vec3 du[2] = vec3[2]((dDdx - u * dot(u, dDdx)) / len, (dDdy - u * dot(u, dDdy)) / len);
    vec3 dr[2];
    for (int k = 0; k < 2; ++k) {
        float dt = -t * dot(du[k], n) / un;
        vec3 dp = t * du[k] + dt * u;
        vec3 dn = dp / radius;
        dr[k] = du[k] - 2.0 * (un * dn + (dot(du[k], n) + dot(u, dn)) * n);
    }
    return EnvHit(r, true, dr[0], dr[1]);
}

#endif
