#pragma once
// A movable camera for every scene: what the viewer flies and orbits, and what `texfilter render --camera`
// reproduces. A Camera is a position and a yaw/pitch relative to the scene's own view (make_scene's camera),
// so it means the same on every backend and prints as five numbers that read back exactly.
//
// Use:     SceneParams moved = with_camera(scene, fly(camera_of(scene), scene, {0.0, 0.0, 0.5}));
// Options: yaw turns about the scene's own up vector (positive: towards the scene's right), pitch about the
//          turned right vector (positive: up), both in degrees; pitch stays inside (-90, 90).
// Keeps:   the field of view (the lengths of SceneParams::right/up) and everything else of the scene (plane,
//          cylinder, triangles, uv offset, size). with_camera(scene, camera_of(scene)) == scene bit for bit.
// Cost:    a few dozen double operations a call; no allocation but the strings.
// Order:   with_camera takes the scene as make_scene (and scene_at_frame, which only slides uv) made it, never
//          an already moved one: yaw and pitch are relative to the scene's own view, not accumulated.
// The mesh scene is rasterized with the same origin/forward/right/up (shaders/harness/mesh.vert.glsl): a
// moved camera works there too, but geometry nearer than its near plane (0.05) or beyond its far plane
// (1000) is clipped on the GPU and not by the CPU reference's ray cast.
#include "scene/scene.h"
#include <glm/glm.hpp>
#include <string>

namespace tf {

struct Camera {
    glm::dvec3 position{0.0};
    double yaw = 0.0, pitch = 0.0; // degrees, relative to the scene's own view
};

// The scene's own camera: its origin, yaw 0, pitch 0.
Camera camera_of(const SceneParams& scene);

// The scene seen from `camera` (origin, forward, right and up replaced; the rest kept). Throws tf::Error for a
// camera parse_camera would refuse (non-finite, |pitch| >= 90, huge).
SceneParams with_camera(const SceneParams& scene, const Camera& camera);

// Moves in the camera's own frame: x right, y up, z forward, in world units. Orientation kept.
Camera fly(const Camera& camera, const SceneParams& scene, glm::dvec3 move);

// Turns by the given degrees; position kept, pitch clamped to [-89, 89], yaw wrapped to [-180, 180].
Camera turn(const Camera& camera, double yaw_degrees, double pitch_degrees);

// Swings the camera around `target` as if the world turned under it: the same turn as turn(), and the
// position rotated with it, so the distance to the target and where the target appears on screen are kept.
Camera orbit(const Camera& camera, const SceneParams& scene, glm::dvec3 target, double yaw_degrees,
             double pitch_degrees);

// A sensible orbit centre: where the scene's central ray (origin + t forward) meets its surface within 100
// world units, else the point 4 units ahead. Works on a moved scene (it uses the scene's current camera).
glm::dvec3 look_target(const SceneParams& scene);

// "X,Y,Z,YAW,PITCH", each %.17g: parse_camera(to_string(c)) == c exactly (every bit, signed zeros too).
std::string to_string(const Camera& camera);

// Reads to_string's form (five comma-separated numbers, no spaces). Throws tf::Error naming what is wrong:
// the count, a field that is not a number, NaN/Inf, |PITCH| >= 90, or a position or yaw beyond 1e6.
Camera parse_camera(const std::string& text);

} // namespace tf
