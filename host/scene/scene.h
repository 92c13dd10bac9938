#pragma once
// The test scenes: one description feeds the GPU (uniform buffer, shaders/harness/scene.glsl) and the
// CPU reference (reference/scene_cast.cpp, in double). Each pixel is ray-cast at its centre (the mesh scene is
// rasterized on the GPU, ray-cast here); uv derivatives are fine or coarse 2x2 quad differences, as
// dFdxFine/dFdxCoarse compute them, or ray differentials.
#include "core/filter.h"
#include "core/lookup.h"
#include "harness/config.h"
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace tf {

// The 2D scenes (a surface with uv) first, then the environment scenes (a direction a pixel, a cube or
// lat-long map: docs/ENVIRONMENT.md): skybox (the camera at the origin looking across the +X/+Y/+Z faces'
// edges into their corner) and reflect (a mirror sphere, SceneParams::p0 = centre xyz and radius w).
enum class SceneKind { plane, tunnel, zoom, minify, slanted, triangles, mesh, skybox, reflect };
// skybox and reflect: their lookups are EnvLookups (reference/env_cast.h, shaders/harness/env_scene.glsl),
// not uv; code that renders a 2D texture on every scene of all_scenes() skips them.
bool is_environment_scene(SceneKind kind);

// How uv gradients are made: fine or coarse 2x2 quad differences (seam-free where the scene's uv wraps: the
// tunnel's u), ray differentials or ray cones (ray-cast scenes; docs/DERIVATIVES.md).
enum class Gradients {
    fine = HARNESS_GRADIENTS_FINE,
    coarse = HARNESS_GRADIENTS_COARSE,
    ray = HARNESS_GRADIENTS_RAY,
    cone = HARNESS_GRADIENTS_CONE
};
Gradients parse_gradients(const std::string& name); // "fine", "coarse", "ray", "cone"
std::string to_string(Gradients gradients);

// Which pipeline renders: a fragment shader (or, for mesh, the raster pipeline) or a compute shader
// whose invocations form 2x2 quads through subgroup quad operations.
enum class Stage { fragment, compute };
Stage parse_stage(const std::string& name);
std::string to_string(Stage stage);

// What a render shows: the filtered colour, or a debug view of each pixel's lookup (shaders/texfilter/
// debug.glsl; docs/API.md): lod (the LOD the filter samples at, as the mipcolors palette), anisotropy (the
// footprint's major/minor axis ratio), fetches (texel fetches + hardware lookups, a heat map up to
// HARNESS_VIEW_FETCHES_MAX) or data (linear floats: R LOD, G ratio, B fetches + hardware lookups, A 1).
enum class DebugView {
    color = HARNESS_VIEW_COLOR,
    lod = HARNESS_VIEW_LOD,
    anisotropy = HARNESS_VIEW_ANISOTROPY,
    fetches = HARNESS_VIEW_FETCHES,
    data = HARNESS_VIEW_DATA
};
DebugView parse_view(const std::string& name); // throws tf::Error listing the valid names
std::string to_string(DebugView view);
// The scene-level filters (ground-truth, none) make no lookup to show: any view but color throws
// tf::Error naming the pair.
void check_view(Filter filter, DebugView view);

// The bench's yardstick (shaders/harness/minimal.glsl): the scene's ray cast, its gradients and one store, with
// nothing else (no_texture) or with the least a manual trilinear lookup needs (trilinear).
enum class MinimalPass { none, no_texture, trilinear };

struct RenderOptions {
    Stage stage = Stage::fragment;
    Gradients gradients = Gradients::fine;
    bool rasterize = false; // the mesh scene: triangles through the raster pipeline
    DebugView view = DebugView::color;
    int lookups = 1; // lookups a pixel, their mean shown (bench --lookups-per-pixel: timing only)
    MinimalPass minimal = MinimalPass::none; // bench, compute only: its minimal pass instead of the harness
};

// The render options a scene allows: mesh is rasterized (fragment stage, quad derivatives only);
// ray differentials and ray cones need a ray-cast scene. Throws tf::Error naming the conflict.
RenderOptions make_render_options(SceneKind kind, Stage stage, Gradients gradients);

SceneKind parse_scene(const std::string& name); // throws tf::Error listing the valid names
std::string to_string(SceneKind kind);
const std::vector<SceneKind>& all_scenes();

// The scene block of shaders/harness/scene.glsl (std140; checked in scene/shader_interface.h).
struct SceneParams {
    glm::vec4 origin;
    glm::vec4 forward;
    glm::vec4 right;      // scaled by tan(fov_x / 2)
    glm::vec4 up;         // scaled by tan(fov_y / 2)
    glm::vec4 p0;         // plane point, or cylinder (radius, length, u repeats, v per world unit), or the
                          // reflect scene's mirror sphere (centre xyz, radius w)
    glm::vec4 axis_u;
    glm::vec4 axis_v;
    glm::vec4 extent;     // xy half extents in uv (hit test), zw uv offset
    glm::vec4 background;
    glm::ivec4 kind_size; // HARNESS_SCENE_*, width, height, triangle count
    glm::vec4 positions[3 * HARNESS_MAX_TRIANGLES]; // triangles: xyz of each corner
    glm::vec4 uvs[3 * HARNESS_MAX_TRIANGLES];       // triangles: uv of each corner in xy
};

// zoom and minify scale the quad so that one texel of a texture_width-wide texture spans 8 pixels
// (zoom) or 1/8 pixel (minify) at the image centre. skybox: a 90-degree horizontal field of view, forward
// towards (1, 0.75, 0.9); reflect: a sphere of radius 1 three units ahead, 60 degrees vertical field of view,
// so that it fills about two thirds of the image's height with sky around it (texture_width unused by both).
SceneParams make_scene(SceneKind kind, int width, int height, int texture_width);
// The minify scene at another scale: texels_per_pixel level-0 texels across each pixel (the benchmark's
// footprint-size sweep).
SceneParams make_minified_scene(int width, int height, int texture_width, double texels_per_pixel);

// The benchmark's camera path: frame f of a glide across the surface, which slides the scene's uv by
// f * camera_step_texels level-0 texels (planes: the camera moves parallel to the plane; tunnel: along
// and around the axis; triangles and mesh: the texture slides across them). Sub-texel steps in both
// axes, so a filter that snaps to texels or levels shows it as flicker. skybox and reflect: the view turns
// (skybox: about the camera; reflect: the camera orbits the sphere's centre, which stays in view) by those
// fractions of a texel's mean angle (pi/2 / texture_width: texture_width is the cube face's side), about
// the world's y axis, then its x axis.
constexpr glm::dvec2 camera_step_texels{0.37, 0.23};
SceneParams scene_at_frame(const SceneParams& scene, int frame, int texture_width);

} // namespace tf
