#pragma once
// The test scenes: one description feeds the GPU (uniform buffer, shaders/harness/scene.glsl) and the
// CPU reference (scene.cpp, in double). Each pixel is ray-cast at its centre; uv derivatives are fine
// 2x2 quad differences, as dFdxFine/dFdyFine compute them.
#include "reference.h"
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace tf {

enum class SceneKind { plane, tunnel, zoom, minify, slanted };

SceneKind parse_scene(const std::string& name); // throws tf::Error listing the valid names
std::string to_string(SceneKind kind);
const std::vector<SceneKind>& all_scenes();

// std140 layout, mirrored by tf_SceneParams in scene.glsl.
struct SceneParams {
    glm::vec4 origin;
    glm::vec4 forward;
    glm::vec4 right;      // scaled by tan(fov_x / 2)
    glm::vec4 up;         // scaled by tan(fov_y / 2)
    glm::vec4 p0;         // plane point, or cylinder (radius, length, u repeats, v per world unit)
    glm::vec4 axis_u;
    glm::vec4 axis_v;
    glm::vec4 extent;     // xy half extents in uv (hit test), zw uv offset
    glm::vec4 background;
    glm::ivec4 kind_size; // TF_SCENE_*, width, height
};

// zoom and minify scale the quad so that one texel of a texture_width-wide texture spans 8 pixels
// (zoom) or 1/8 pixel (minify) at the image centre.
SceneParams make_scene(SceneKind kind, int width, int height, int texture_width);

struct PixelHit {
    bool hit = false;
    glm::dvec2 uv{0.0}; // defined on a miss too: the unbounded surface
};

PixelHit reference_hit(const SceneParams& scene, double px, double py);

// The lookups of a whole image, row-major: uv at the pixel centre and fine quad derivatives
// (dx = uv(x|1, y) - uv(x&~1, y), dy = uv(x, y|1) - uv(x, y&~1)). Width and height must be even.
struct PixelLookup {
    bool hit = false;
    Lookup lookup;
};
std::vector<PixelLookup> reference_quad_lookups(const SceneParams& scene);

} // namespace tf
