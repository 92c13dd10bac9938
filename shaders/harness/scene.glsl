// Harness only: ray-casts the test scenes per pixel. The CPU twin is host/reference/scene_cast.cpp (in double).
#ifndef HARNESS_SCENE_GLSL
#define HARNESS_SCENE_GLSL

#include "config.h"

// tf::SceneParams (host/scene/scene.h) in std140: ten vec4s, HARNESS_SCENE_PARAMS_SIZE bytes.
struct SceneParams {
    vec4 origin;     // camera position
    vec4 forward;    // camera forward (unit)
    vec4 right;      // camera right scaled by tan(fov_x / 2)
    vec4 up;         // camera up scaled by tan(fov_y / 2)
    vec4 p0;         // plane: a point (uv = 0 there); cylinder: x radius, y length, z u-repeats, w v per unit
    vec4 axisU;      // plane: world vector of one unit of u
    vec4 axisV;      // plane: world vector of one unit of v
    vec4 extent;     // xy: half extents in uv around 0 (hit test), zw: uv offset added after (all scenes)
    vec4 background; // colour of pixels that hit nothing
    ivec4 kindSize;  // x: HARNESS_SCENE_*, y: width, z: height, w: triangle count
};

// The scene's uniform block: the parameters, then the triangles. The triangle arrays stay outside the
// struct that functions take by value: a by-value copy of 1.5 KB of arrays indexed in a loop took lavapipe
// ~10 s to compile per pipeline.
layout(set = 0, binding = HARNESS_BINDING_SCENE, std140) uniform SceneBlock {
    layout(offset = 0) SceneParams scene;
    layout(offset = HARNESS_SCENE_POSITIONS) vec4 trianglePositions[3 * HARNESS_MAX_TRIANGLES]; // corners (xyz)
    layout(offset = HARNESS_SCENE_UVS) vec4 triangleUVs[3 * HARNESS_MAX_TRIANGLES];             // corner uvs (xy)
};

struct Hit {
    bool hit;
    vec2 uv;     // defined even on a miss (the unbounded surface; triangles: 0), so quad derivatives stay defined
    float t;     // ray parameter of the hit (direction not normalised)
    vec3 normal; // surface frame for ray differentials
    vec3 dPdu;
    vec3 dPdv;
};

vec3 camera_ray(SceneParams scene, vec2 pixelCentre)
{
    vec2 size = vec2(scene.kindSize.yz);
    vec2 ndc = vec2(2.0 * pixelCentre.x / size.x - 1.0, 1.0 - 2.0 * pixelCentre.y / size.y);
    return scene.forward.xyz + ndc.x * scene.right.xyz + ndc.y * scene.up.xyz;
}

Hit hit_plane(SceneParams scene, vec3 o, vec3 d)
{
    vec3 n = cross(scene.axisU.xyz, scene.axisV.xyz);
    float t = dot(scene.p0.xyz - o, n) / dot(d, n);
    vec3 rel = o + t * d - scene.p0.xyz;
    vec2 st = vec2(dot(rel, scene.axisU.xyz) / dot(scene.axisU.xyz, scene.axisU.xyz),
                   dot(rel, scene.axisV.xyz) / dot(scene.axisV.xyz, scene.axisV.xyz));
    bool inside = t > 0.0 && abs(st.x) <= scene.extent.x && abs(st.y) <= scene.extent.y;
    return Hit(inside, st + scene.extent.zw, t, n, scene.axisU.xyz, scene.axisV.xyz);
}

Hit hit_cylinder(SceneParams scene, vec3 o, vec3 d)
{
    float radius = scene.p0.x, len = scene.p0.y;
    float a = dot(d.xy, d.xy), b = 2.0 * dot(o.xy, d.xy), c = dot(o.xy, o.xy) - radius * radius;
    float t = (-b + sqrt(b * b - 4.0 * a * c)) / (2.0 * a); // camera inside: c < 0, one positive root
    vec3 p = o + t * d;
    vec2 uv = vec2(atan(p.y, p.x) * (scene.p0.z / 6.283185307179586) + 0.5 * scene.p0.z, p.z * scene.p0.w);
    // u turns p0.z times around the axis, v runs p0.w per unit of z.
    vec3 dPdu = vec3(-p.y, p.x, 0.0) * (6.283185307179586 / scene.p0.z);
    return Hit(t > 0.0 && p.z < len, uv + scene.extent.zw, t, vec3(p.xy, 0.0), dPdu, vec3(0.0, 0.0, 1.0 / scene.p0.w));
}

// Where the ray meets triangle i's plane: barycentrics (b1, b2) and t, unbounded (outside the triangle too).
vec3 triangle_plane(SceneParams scene, int i, vec3 o, vec3 d)
{
    vec3 a = trianglePositions[3 * i].xyz;
    vec3 e1 = trianglePositions[3 * i + 1].xyz - a, e2 = trianglePositions[3 * i + 2].xyz - a;
    vec3 n = cross(e1, e2);
    float t = dot(a - o, n) / dot(d, n);
    vec3 rel = o + t * d - a;
    float g11 = dot(e1, e1), g12 = dot(e1, e2), g22 = dot(e2, e2), r1 = dot(rel, e1), r2 = dot(rel, e2);
    float det = g11 * g22 - g12 * g12;
    return vec3((r1 * g22 - r2 * g12) / det, (r2 * g11 - r1 * g12) / det, t);
}

// Triangle i's hit record for barycentrics b (from triangle_plane), with the frame ray differentials need:
// [dPdu dPdv] maps uv changes to position changes on the triangle.
Hit triangle_hit(SceneParams scene, int i, vec3 b, bool inside)
{
    vec3 a = trianglePositions[3 * i].xyz;
    vec3 e1 = trianglePositions[3 * i + 1].xyz - a, e2 = trianglePositions[3 * i + 2].xyz - a;
    vec2 uv0 = triangleUVs[3 * i].xy, d1 = triangleUVs[3 * i + 1].xy - uv0, d2 = triangleUVs[3 * i + 2].xy - uv0;
    vec2 uv = uv0 + b.x * d1 + b.y * d2 + scene.extent.zw; // extent.zw: the camera path's slide (0 otherwise)
    float inverseDet = 1.0 / (d1.x * d2.y - d2.x * d1.y); // e = [dPdu dPdv] [d1 d2]
    vec3 dPdu = (e1 * d2.y - e2 * d1.y) * inverseDet, dPdv = (e2 * d1.x - e1 * d2.x) * inverseDet;
    return Hit(inside, uv, b.z, cross(e1, e2), dPdu, dPdv);
}

Hit hit_triangles(SceneParams scene, vec3 o, vec3 d)
{
    // Edges widened by HARNESS_EDGE_SLACK so that a ray along an edge shared by two triangles hits one of them
    // (barycentrics round differently in each): no holes. The nearer hit wins where both claim it.
    // Not unrolled, and the hit record built once after the loop: the code stays small to compile.
    int best = -1;
    vec3 bestB = vec3(0.0, 0.0, 1.0 / 0.0);
    [[dont_unroll]] for (int i = 0; i < min(scene.kindSize.w, HARNESS_MAX_TRIANGLES); ++i) {
        vec3 b = triangle_plane(scene, i, o, d);
        if (b.z > 0.0 && b.z < bestB.z && b.x >= -HARNESS_EDGE_SLACK && b.y >= -HARNESS_EDGE_SLACK &&
            b.x + b.y <= 1.0 + HARNESS_EDGE_SLACK) {
            best = i;
            bestB = b;
        }
    }
    if (best < 0)
        return Hit(false, vec2(0.0), 1.0 / 0.0, vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0));
    return triangle_hit(scene, best, bestB, true);
}

// The scene's kind as a constant where the pipeline is specialised to it (render: the host sets it from the scene),
// so that a frame holds one ray cast: with the kind read from the block, the no-texture frame of the plane took
// twice as long (lavapipe, compute, 512²: 3.2 ms against 1.6-1.7 ms), the other casts' code in it.
layout(constant_id = HARNESS_SPEC_SCENE) const int SCENE_ID = -1;

int scene_kind(SceneParams scene) { return SCENE_ID >= 0 ? SCENE_ID : scene.kindSize.x; }

Hit scene_hit(SceneParams scene, vec2 pixelCentre)
{
    vec3 d = camera_ray(scene, pixelCentre);
    int kind = scene_kind(scene);
    if (kind == HARNESS_SCENE_CYLINDER)
        return hit_cylinder(scene, scene.origin.xyz, d);
    if (kind == HARNESS_SCENE_TRIANGLES)
        return hit_triangles(scene, scene.origin.xyz, d);
    return hit_plane(scene, scene.origin.xyz, d);
}

// Camera ray direction change one pixel right and one pixel down (the ray differentials' dD/dx, dD/dy).
vec3 camera_ray_dx(SceneParams scene) { return scene.right.xyz * (2.0 / float(scene.kindSize.y)); }
vec3 camera_ray_dy(SceneParams scene) { return scene.up.xyz * (-2.0 / float(scene.kindSize.z)); }

// The ray cone's spread angle a pixel: atan(2 tan(fov_y / 2) / height), |up| being tan(fov_y / 2).
float camera_pixel_spread(SceneParams scene) { return atan(2.0 * length(scene.up.xyz) / float(scene.kindSize.z)); }

#endif
