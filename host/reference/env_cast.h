#pragma once
// The environment scenes' ray casts on the CPU, in double (scene/scene.h: skybox, reflect): each pixel's
// lookup direction and its derivatives, what shaders/harness/env_scene.glsl's ray differentials and the
// GPU's quad differences are checked against.
//
// Use:   std::vector<EnvLookup> lookups = reference_env_lookups(make_scene(SceneKind::reflect, 64, 64, 64),
//                                                               Gradients::fine);
// Cost:  one ray-sphere test a pixel (fine, coarse), nine for ray gradients (central differences).
#include "core/lookup.h"
#include "scene/scene.h"
#include <glm/glm.hpp>
#include <vector>

namespace tf {

// The ray through pixel point (px, py) (pixel centres at +0.5): skybox: dir is the camera ray itself (not
// normalised). reflect: on a hit (mirror), the unit ray's reflection about the sphere's normal at the
// nearer hit point; on a miss the camera ray. Throws tf::Error for a scene that is not an environment scene.
struct EnvRay {
    glm::dvec3 dir{0.0, 0.0, 1.0}; // the lookup direction
    bool mirror = false;           // reflect: the ray hit the sphere
    glm::dvec3 ray{0.0};           // the camera ray (not normalised)
    glm::dvec3 point{0.0}, normal{0.0}; // mirror: the hit point and the sphere's unit outward normal there
};
EnvRay reference_env_ray(const SceneParams& scene, double px, double py);
glm::dvec3 reference_env_direction(const SceneParams& scene, double px, double py);

// Per pixel, row-major: the lookup at the pixel centre, its derivatives: fine: dx = d(x|1, y) - d(x&~1, y),
// dy = d(x, y|1) - d(x, y&~1); coarse: the quad's top-left pair for all four pixels (as reference_lookups
// does for uv); ray: the exact derivative with respect to the pixel position by central differences in
// double, Richardson-extrapolated (measured within 3e-8 of the analytic transfer, relative; one-sided and
// first order within 1/1024 pixel of the sphere's silhouette); cone: the ray cone's direction footprint
// (texfilter/derivatives.glsl: the camera's pixel spread gamma around a sky ray; the primary cone reflected
// by the sphere's curvature on the mirror), two vectors perpendicular to dir. Sides must be even.
std::vector<EnvLookup> reference_env_lookups(const SceneParams& scene, Gradients gradients);

} // namespace tf
