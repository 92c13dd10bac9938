#include "scene/scene.h"
#include "harness/config.h"
#include "scene/shader_interface.h" // its static_asserts hold the interface in every build
#include "texture/error.h"
#include <array>
#include <cmath>

namespace tf {

namespace {

constexpr double pi = 3.14159265358979323846;

struct Camera {
    glm::dvec3 origin, forward, up_hint;
    double fov_y_degrees;
};

void set_camera(SceneParams& scene, const Camera& camera, int width, int height)
{
    glm::dvec3 f = glm::normalize(camera.forward);
    glm::dvec3 r = glm::normalize(glm::cross(f, camera.up_hint));
    glm::dvec3 u = glm::cross(r, f);
    double tan_y = std::tan(camera.fov_y_degrees * pi / 360.0);
    double tan_x = tan_y * double(width) / double(height);
    scene.origin = glm::vec4(glm::vec3(camera.origin), 0.0f);
    scene.forward = glm::vec4(glm::vec3(f), 0.0f);
    scene.right = glm::vec4(glm::vec3(r * tan_x), 0.0f);
    scene.up = glm::vec4(glm::vec3(u * tan_y), 0.0f);
}

// A screen-facing quad at distance 4 whose uv changes by `uv_per_pixel` per pixel at the centre.
void set_facing_quad(SceneParams& scene, int height, double uv_per_pixel)
{
    const double distance = 4.0;
    double pixel_world = 2.0 * distance * double(scene.up.y) / double(height); // up is (0, tan_y, 0)
    double unit = pixel_world / uv_per_pixel;                                  // world length of one uv
    scene.p0 = glm::vec4(0.0f, 0.0f, float(distance), 0.0f);
    // u grows to the right of the screen (the camera's right is world -x: forward x up with forward +z, up +y)
    // and v down it, like rows: an image reads as it does in a viewer, not mirrored.
    scene.axis_u = glm::vec4(float(-unit), 0.0f, 0.0f, 0.0f);
    scene.axis_v = glm::vec4(0.0f, float(-unit), 0.0f, 0.0f);
}

// The triangles scene's mesh: a floor and a wall seen at grazing angles, a panel facing the camera whose
// two triangles carry different uv offsets (a seam along its diagonal), and a steeply tilted triangle.
struct Corner {
    glm::dvec3 position;
    glm::dvec2 uv;
};

std::vector<std::array<Corner, 3>> mesh_triangles()
{
    auto floor_uv = [](glm::dvec3 p) { return glm::dvec2(p.x / 1.5, p.z / 1.5); };
    auto wall_uv = [](glm::dvec3 p) { return glm::dvec2(p.z / 1.5, (2.0 - p.y) / 1.5); };
    auto panel_uv = [](glm::dvec3 p, glm::dvec2 offset) { return glm::dvec2(p.x - 0.2, 1.2 - p.y) * 0.5 + offset; };
    auto tri = [](glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, auto uv) {
        return std::array<Corner, 3>{Corner{a, uv(a)}, Corner{b, uv(b)}, Corner{c, uv(c)}};
    };
    glm::dvec3 f0(-3, -1, 1.5), f1(3, -1, 1.5), f2(3, -1, 30), f3(-3, -1, 30);
    glm::dvec3 w0(-3, -1, 1.5), w1(-3, -1, 30), w2(-3, 2, 30), w3(-3, 2, 1.5);
    glm::dvec3 p0(0.2, -0.8, 6), p1(2.2, -0.8, 6), p2(2.2, 1.2, 6), p3(0.2, 1.2, 6);
    glm::dvec2 seam(0.37, 0.21);
    return {tri(f0, f1, f2, floor_uv),
            tri(f0, f2, f3, floor_uv),
            tri(w0, w1, w2, wall_uv),
            tri(w0, w2, w3, wall_uv),
            tri(p0, p1, p2, [&](glm::dvec3 p) { return panel_uv(p, glm::dvec2(0.0)); }),
            tri(p0, p2, p3, [&](glm::dvec3 p) { return panel_uv(p, seam); }),
            tri({-0.5, -1.0, 4.0}, {-2.0, -1.0, 10.0}, {-1.0, 1.0, 8.0},
                [](glm::dvec3 p) { return glm::dvec2(p.x * 0.8, p.y * 0.8 + p.z * 0.3); })};
}

} // namespace

std::string to_string(Gradients gradients)
{
    switch (gradients) {
    case Gradients::fine: return "fine";
    case Gradients::coarse: return "coarse";
    case Gradients::ray: return "ray";
    case Gradients::cone: return "cone";
    }
    return "?";
}

Gradients parse_gradients(const std::string& name)
{
    for (Gradients g : {Gradients::fine, Gradients::coarse, Gradients::ray, Gradients::cone})
        if (to_string(g) == name)
            return g;
    throw Error("unknown derivatives '" + name + "' (expected one of: fine, coarse, ray, cone)");
}

std::string to_string(Stage stage) { return stage == Stage::compute ? "compute" : "fragment"; }

Stage parse_stage(const std::string& name)
{
    if (name == "fragment")
        return Stage::fragment;
    if (name == "compute")
        return Stage::compute;
    throw Error("unknown stage '" + name + "' (expected one of: fragment, compute)");
}

std::string to_string(DebugView view)
{
    switch (view) {
    case DebugView::color: return "color";
    case DebugView::lod: return "lod";
    case DebugView::anisotropy: return "anisotropy";
    case DebugView::fetches: return "fetches";
    case DebugView::data: return "data";
    }
    return "?";
}

DebugView parse_view(const std::string& name)
{
    for (DebugView v : {DebugView::color, DebugView::lod, DebugView::anisotropy, DebugView::fetches, DebugView::data})
        if (to_string(v) == name)
            return v;
    throw Error("unknown view '" + name + "' (expected one of: color, lod, anisotropy, fetches, data)");
}

void check_view(Filter filter, DebugView view)
{
    if (view != DebugView::color && is_scene_level(filter))
        throw Error("--view " + to_string(view) + " shows a lookup's LOD, anisotropy and fetches; --filter " +
                    to_string(filter) + " makes no lookup (use --view color)");
}

RenderOptions make_render_options(SceneKind kind, Stage stage, Gradients gradients)
{
    bool mesh = kind == SceneKind::mesh;
    if (mesh && stage == Stage::compute)
        throw Error("the mesh scene is rasterized by the graphics pipeline; for the compute stage use --scene triangles "
                    "(the same triangles, ray-cast)");
    if (mesh && (gradients == Gradients::ray || gradients == Gradients::cone))
        throw Error(std::string(gradients == Gradients::ray ? "ray differentials" : "ray cones") +
                    " need a ray-cast scene; the mesh scene is rasterized (use fine or coarse)");
    if (is_environment_scene(kind) && stage == Stage::compute)
        throw Error("the environment scenes (skybox, reflect) render in the fragment stage only: use --stage fragment");
    return {stage, gradients, mesh};
}

const std::vector<SceneKind>& all_scenes()
{
    static const std::vector<SceneKind> kinds = {SceneKind::plane,   SceneKind::tunnel,    SceneKind::zoom,
                                                 SceneKind::minify,  SceneKind::slanted,   SceneKind::triangles,
                                                 SceneKind::mesh,    SceneKind::skybox,    SceneKind::reflect};
    return kinds;
}

bool is_environment_scene(SceneKind kind) { return kind == SceneKind::skybox || kind == SceneKind::reflect; }

std::string to_string(SceneKind kind)
{
    switch (kind) {
    case SceneKind::plane: return "plane";
    case SceneKind::tunnel: return "tunnel";
    case SceneKind::zoom: return "zoom";
    case SceneKind::minify: return "minify";
    case SceneKind::slanted: return "slanted";
    case SceneKind::triangles: return "triangles";
    case SceneKind::mesh: return "mesh";
    case SceneKind::skybox: return "skybox";
    case SceneKind::reflect: return "reflect";
    }
    return "?";
}

SceneKind parse_scene(const std::string& name)
{
    std::string valid;
    for (SceneKind kind : all_scenes()) {
        if (to_string(kind) == name)
            return kind;
        valid += (valid.empty() ? "" : ", ") + to_string(kind);
    }
    throw Error("unknown scene '" + name + "' (expected one of: " + valid + ")");
}

SceneParams make_scene(SceneKind kind, int width, int height, int texture_width)
{
    SceneParams scene{};
    scene.kind_size = glm::ivec4(HARNESS_SCENE_PLANE, width, height, 0);
    scene.background = glm::vec4(0.02f, 0.02f, 0.03f, 1.0f);
    const float unbounded = 1e30f;
    // Offsets keep texel edges off pixel centres, so nearest lookups are not decided by rounding.
    scene.extent = glm::vec4(unbounded, unbounded, 0.1234f, 0.0567f);
    switch (kind) {
    case SceneKind::plane: // ground plane to the horizon, camera 1 unit up, yawed 20 degrees
        set_camera(scene, {{0.0, 1.0, 0.0}, {std::sin(0.35), -0.28, std::cos(0.35)}, {0.0, 1.0, 0.0}, 60.0},
                   width, height);
        scene.p0 = glm::vec4(0.0f);
        scene.axis_u = glm::vec4(4.0f, 0.0f, 0.0f, 0.0f); // one texture repeat every 4 units
        scene.axis_v = glm::vec4(0.0f, 0.0f, 4.0f, 0.0f);
        break;
    case SceneKind::tunnel: // cylinder of radius 1 and length 40, camera just off the axis
        set_camera(scene, {{0.25, 0.1, 0.0}, {0.0, 0.0, 1.0}, {0.0, 1.0, 0.0}, 90.0}, width, height);
        scene.kind_size.x = HARNESS_SCENE_CYLINDER;
        // 2 repeats around; texels stay square: v per unit = repeats / circumference.
        scene.p0 = glm::vec4(1.0f, 40.0f, 2.0f, float(2.0 / (2.0 * pi)));
        break;
    case SceneKind::zoom:
    case SceneKind::minify:
        set_camera(scene, {{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, {0.0, 1.0, 0.0}, 40.0}, width, height);
        set_facing_quad(scene, height, kind == SceneKind::zoom ? 1.0 / (8.0 * texture_width) : 8.0 / texture_width);
        scene.extent.z = kind == SceneKind::zoom ? 0.5f : 0.1234f; // zoom: look at the texture's centre
        scene.extent.w = kind == SceneKind::zoom ? 0.5f : 0.0567f;
        scene.extent.z += 0.3f / float(texture_width);
        scene.extent.w += 0.2f / float(texture_width);
        break;
    case SceneKind::slanted: { // a 3x3-uv quad, tilted 70 degrees away and rolled 30 degrees
        set_camera(scene, {{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, {0.0, 1.0, 0.0}, 50.0}, width, height);
        double tilt = 70.0 * pi / 180.0, roll = 30.0 * pi / 180.0;
        glm::dvec3 across(std::cos(roll), std::sin(roll), 0.0);                   // stays facing the camera
        glm::dvec3 in_screen(-std::sin(roll), std::cos(roll), 0.0);              // tilts away
        glm::dvec3 away = std::cos(tilt) * in_screen + std::sin(tilt) * glm::dvec3(0.0, 0.0, 1.0);
        scene.p0 = glm::vec4(0.0f, 0.0f, 4.0f, 0.0f);
        scene.axis_u = glm::vec4(glm::vec3(across * 1.2), 0.0f);
        scene.axis_v = glm::vec4(glm::vec3(away * 1.2), 0.0f);
        scene.extent.x = 1.5f;
        scene.extent.y = 1.5f;
        break;
    }
    case SceneKind::triangles:
    case SceneKind::mesh: { // the same triangles: ray-cast (triangles) or rasterized (mesh)
        set_camera(scene, {{0.0, 0.3, 0.0}, {0.1, -0.15, 1.0}, {0.0, 1.0, 0.0}, 55.0}, width, height);
        std::vector<std::array<Corner, 3>> mesh = mesh_triangles();
        scene.kind_size.x = HARNESS_SCENE_TRIANGLES;
        if (mesh.size() > HARNESS_MAX_TRIANGLES)
            throw Error("the triangles scene has " + std::to_string(mesh.size()) +
                        " triangles; the scene block holds " + std::to_string(HARNESS_MAX_TRIANGLES));
        scene.kind_size.w = int(mesh.size());
        scene.extent = glm::vec4(0.0f);
        for (size_t t = 0; t < mesh.size(); ++t)
            for (size_t k = 0; k < 3; ++k) {
                scene.positions[3 * t + k] = glm::vec4(glm::vec3(mesh[t][k].position), 1.0f);
                scene.uvs[3 * t + k] = glm::vec4(glm::vec2(mesh[t][k].uv), 0.0f, 0.0f);
            }
        break;
    }
    case SceneKind::skybox: { // across the edges of +X, +Y and +Z and into their corner (1, 1, 1)
        double fov_y = 2.0 * std::atan(double(height) / double(width)) * 180.0 / pi; // tan(fov_x / 2) = 1
        set_camera(scene, {{0.0, 0.0, 0.0}, {1.0, 0.75, 0.9}, {0.0, 1.0, 0.0}, fov_y}, width, height);
        scene.kind_size.x = HARNESS_SCENE_SKYBOX;
        scene.extent = glm::vec4(0.0f);
        break;
    }
    case SceneKind::reflect: { // a mirror ball of radius 1, three units ahead, seen a little from above
        glm::dvec3 forward = glm::normalize(glm::dvec3(0.25, -0.3, 1.0));
        set_camera(scene, {{0.0, 0.0, 0.0}, forward, {0.0, 1.0, 0.0}, 60.0}, width, height);
        scene.kind_size.x = HARNESS_SCENE_REFLECT;
        scene.p0 = glm::vec4(glm::vec3(3.0 * forward), 1.0f);
        scene.extent = glm::vec4(0.0f);
        break;
    }
    }
    return scene;
}

SceneParams make_minified_scene(int width, int height, int texture_width, double texels_per_pixel)
{
    SceneParams scene = make_scene(SceneKind::minify, width, height, texture_width);
    set_facing_quad(scene, height, texels_per_pixel / texture_width);
    return scene;
}

namespace {

// v turned by `radians` about the unit axis (Rodrigues).
glm::dvec3 rotated(glm::dvec3 v, glm::dvec3 axis, double radians)
{
    return v * std::cos(radians) + glm::cross(axis, v) * std::sin(radians) +
           axis * glm::dot(axis, v) * (1.0 - std::cos(radians));
}

// The environment scenes' camera path: the view and the camera's offset from the pivot turned together.
SceneParams turned_view(const SceneParams& scene, glm::dvec3 pivot, double yaw, double pitch)
{
    auto turn = [&](glm::vec4 v, bool point) {
        glm::dvec3 x = glm::dvec3(v) - (point ? pivot : glm::dvec3(0.0));
        x = rotated(rotated(x, {0.0, 1.0, 0.0}, yaw), {1.0, 0.0, 0.0}, pitch);
        return glm::vec4(glm::vec3(x + (point ? pivot : glm::dvec3(0.0))), v.w);
    };
    SceneParams moved = scene;
    moved.origin = turn(scene.origin, true);
    moved.forward = turn(scene.forward, false);
    moved.right = turn(scene.right, false);
    moved.up = turn(scene.up, false);
    return moved;
}

} // namespace

SceneParams scene_at_frame(const SceneParams& scene, int frame, int texture_width)
{
    if (scene.kind_size.x == HARNESS_SCENE_SKYBOX || scene.kind_size.x == HARNESS_SCENE_REFLECT) {
        if (frame == 0)
            return scene;
        const double texel = 0.5 * pi / texture_width; // a face's 90 degrees over its texels
        const glm::dvec3 pivot = scene.kind_size.x == HARNESS_SCENE_REFLECT ? glm::dvec3(scene.p0) : glm::dvec3(0.0);
        return turned_view(scene, pivot, frame * camera_step_texels.x * texel, frame * camera_step_texels.y * texel);
    }
    SceneParams moved = scene;
    moved.extent.z += float(frame * camera_step_texels.x / texture_width);
    moved.extent.w += float(frame * camera_step_texels.y / texture_width);
    return moved;
}

} // namespace tf
