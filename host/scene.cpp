#include "scene.h"
#include "../shaders/harness/config.h"
#include "error.h"
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
    scene.axis_u = glm::vec4(float(unit), 0.0f, 0.0f, 0.0f);
    scene.axis_v = glm::vec4(0.0f, float(-unit), 0.0f, 0.0f); // v grows down the screen, like rows
}

} // namespace

const std::vector<SceneKind>& all_scenes()
{
    static const std::vector<SceneKind> kinds = {SceneKind::plane, SceneKind::tunnel, SceneKind::zoom,
                                                 SceneKind::minify, SceneKind::slanted};
    return kinds;
}

std::string to_string(SceneKind kind)
{
    switch (kind) {
    case SceneKind::plane: return "plane";
    case SceneKind::tunnel: return "tunnel";
    case SceneKind::zoom: return "zoom";
    case SceneKind::minify: return "minify";
    case SceneKind::slanted: return "slanted";
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
    scene.kind_size = glm::ivec4(TF_SCENE_PLANE, width, height, 0);
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
        scene.kind_size.x = TF_SCENE_CYLINDER;
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
    }
    return scene;
}

PixelHit reference_hit(const SceneParams& scene, double px, double py)
{
    auto d3 = [](glm::vec4 v) { return glm::dvec3(v); };
    double ndc_x = 2.0 * px / scene.kind_size.y - 1.0;
    double ndc_y = 1.0 - 2.0 * py / scene.kind_size.z;
    glm::dvec3 o = d3(scene.origin);
    glm::dvec3 d = d3(scene.forward) + ndc_x * d3(scene.right) + ndc_y * d3(scene.up);
    glm::dvec2 offset(scene.extent.z, scene.extent.w);
    PixelHit result;
    if (scene.kind_size.x == TF_SCENE_CYLINDER) {
        double radius = scene.p0.x, length = scene.p0.y;
        double a = d.x * d.x + d.y * d.y, b = 2.0 * (o.x * d.x + o.y * d.y);
        double c = o.x * o.x + o.y * o.y - radius * radius;
        double t = (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
        glm::dvec3 p = o + t * d;
        double repeats = scene.p0.z;
        result.uv = glm::dvec2(std::atan2(p.y, p.x) * repeats / (2.0 * pi) + 0.5 * repeats, p.z * double(scene.p0.w));
        result.uv += offset;
        result.hit = t > 0.0 && p.z < length;
        return result;
    }
    glm::dvec3 au = d3(scene.axis_u), av = d3(scene.axis_v), p0 = d3(scene.p0);
    glm::dvec3 n = glm::cross(au, av);
    double t = glm::dot(p0 - o, n) / glm::dot(d, n);
    glm::dvec3 rel = o + t * d - p0;
    glm::dvec2 st(glm::dot(rel, au) / glm::dot(au, au), glm::dot(rel, av) / glm::dot(av, av));
    result.hit = t > 0.0 && std::abs(st.x) <= scene.extent.x && std::abs(st.y) <= scene.extent.y;
    result.uv = st + offset;
    return result;
}

std::vector<PixelLookup> reference_quad_lookups(const SceneParams& scene)
{
    int width = scene.kind_size.y, height = scene.kind_size.z;
    if (width % 2 != 0 || height % 2 != 0)
        throw Error("quad derivatives need an even image size, got " + std::to_string(width) + "x" +
                    std::to_string(height));
    std::vector<PixelHit> hits(size_t(width) * size_t(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            hits[size_t(y) * width + x] = reference_hit(scene, x + 0.5, y + 0.5);
    auto at = [&](int x, int y) { return hits[size_t(y) * width + x].uv; };
    std::vector<PixelLookup> out(hits.size());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            glm::dvec2 uv = at(x, y);
            glm::dvec2 dx = at(x | 1, y) - at(x & ~1, y);
            glm::dvec2 dy = at(x, y | 1) - at(x, y & ~1);
            PixelLookup& p = out[size_t(y) * width + x];
            p.hit = hits[size_t(y) * width + x].hit;
            p.lookup = {uv.x, uv.y, dx.x, dx.y, dy.x, dy.y};
        }
    return out;
}

} // namespace tf
