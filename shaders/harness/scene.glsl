// Harness only: ray-casts the test scenes per pixel. The CPU twin is host/scene.cpp (in double).
#ifndef TF_HARNESS_SCENE_GLSL
#define TF_HARNESS_SCENE_GLSL

#include "config.h"

// std140 mirror of tf::SceneParams (host/scene.h).
struct tf_SceneParams {
    vec4 origin;     // camera position
    vec4 forward;    // camera forward (unit)
    vec4 right;      // camera right scaled by tan(fov_x / 2)
    vec4 up;         // camera up scaled by tan(fov_y / 2)
    vec4 p0;         // plane: a point (uv = 0 there); cylinder: x radius, y length, z u-repeats, w v per unit
    vec4 axisU;      // plane: world vector of one unit of u
    vec4 axisV;      // plane: world vector of one unit of v
    vec4 extent;     // xy: half extents in uv around 0 (hit test), zw: uv offset added after
    vec4 background; // colour of pixels that hit nothing
    ivec4 kindSize;  // x: TF_SCENE_*, y: width, z: height
};

struct tf_Hit {
    bool hit;
    vec2 uv; // defined even on a miss (the unbounded surface), so quad derivatives stay defined
};

vec3 tf_camera_ray(tf_SceneParams scene, vec2 pixelCentre)
{
    vec2 size = vec2(scene.kindSize.yz);
    vec2 ndc = vec2(2.0 * pixelCentre.x / size.x - 1.0, 1.0 - 2.0 * pixelCentre.y / size.y);
    return scene.forward.xyz + ndc.x * scene.right.xyz + ndc.y * scene.up.xyz;
}

tf_Hit tf_hit_plane(tf_SceneParams scene, vec3 o, vec3 d)
{
    vec3 n = cross(scene.axisU.xyz, scene.axisV.xyz);
    float t = dot(scene.p0.xyz - o, n) / dot(d, n);
    vec3 rel = o + t * d - scene.p0.xyz;
    vec2 st = vec2(dot(rel, scene.axisU.xyz) / dot(scene.axisU.xyz, scene.axisU.xyz),
                   dot(rel, scene.axisV.xyz) / dot(scene.axisV.xyz, scene.axisV.xyz));
    bool inside = t > 0.0 && abs(st.x) <= scene.extent.x && abs(st.y) <= scene.extent.y;
    return tf_Hit(inside, st + scene.extent.zw);
}

tf_Hit tf_hit_cylinder(tf_SceneParams scene, vec3 o, vec3 d)
{
    float radius = scene.p0.x, len = scene.p0.y;
    float a = dot(d.xy, d.xy), b = 2.0 * dot(o.xy, d.xy), c = dot(o.xy, o.xy) - radius * radius;
    float t = (-b + sqrt(b * b - 4.0 * a * c)) / (2.0 * a); // camera inside: c < 0, one positive root
    vec3 p = o + t * d;
    vec2 uv = vec2(atan(p.y, p.x) * (scene.p0.z / 6.283185307179586) + 0.5 * scene.p0.z, p.z * scene.p0.w);
    return tf_Hit(t > 0.0 && p.z < len, uv + scene.extent.zw);
}

tf_Hit tf_scene_hit(tf_SceneParams scene, vec2 pixelCentre)
{
    vec3 d = tf_camera_ray(scene, pixelCentre);
    if (scene.kindSize.x == TF_SCENE_CYLINDER)
        return tf_hit_cylinder(scene, scene.origin.xyz, d);
    return tf_hit_plane(scene, scene.origin.xyz, d);
}

#endif
