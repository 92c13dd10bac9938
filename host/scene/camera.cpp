// The movable camera (scene/camera.h): rotations in double from the scene's float-stored basis, so that a
// zero turn gives back the stored vectors exactly.
#include "scene/camera.h"
#include "harness/config.h"
#include "texture/error.h"
#include "core/numbers.h"
#include <optional>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace tf {

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double max_pitch = 89.0;        // turn() stops here: at 90 the yaw axis and forward coincide
constexpr double max_magnitude = 1e6;     // position (world units) and yaw (degrees): beyond is a typo
constexpr double max_target_distance = 100.0; // farther hits (a plane at grazing angles) make a useless centre
constexpr double default_target_distance = 4.0; // the facing quads' distance

const char* const field_names[5] = {"X", "Y", "Z", "YAW", "PITCH"};

// a turned by `degrees` towards b (b orthogonal to a, scaled to a's length): exactly a for 0, signed zeros
// included, which cos/sin arithmetic alone would not guarantee (-0 + 0 = +0).
glm::dvec3 turned(glm::dvec3 a, glm::dvec3 b, double degrees)
{
    if (degrees == 0.0)
        return a;
    double radians = degrees * pi / 180.0;
    return std::cos(radians) * a + std::sin(radians) * b;
}

// The camera's forward/right/up in double, scaled as the scene stores them (right and up by the half-fov
// tangents): yaw about the scene's up, then pitch about the turned right.
struct Basis {
    glm::dvec3 forward, right, up;
};

Basis rotated_basis(const SceneParams& scene, const Camera& camera)
{
    glm::dvec3 f(scene.forward), r(scene.right), u(scene.up);
    double lf = glm::length(f), lr = glm::length(r), lu = glm::length(u);
    glm::dvec3 f1 = turned(f, r * (lf / lr), camera.yaw);
    glm::dvec3 r1 = turned(r, -f * (lr / lf), camera.yaw);
    glm::dvec3 f2 = turned(f1, u * (lf / lu), camera.pitch);
    glm::dvec3 u2 = turned(u, -f1 * (lu / lf), camera.pitch);
    return {f2, r1, u2};
}

// The same frame made orthonormal (Gram-Schmidt from forward): moves and orbits keep lengths to double
// precision although the stored basis is orthogonal only to float precision.
Basis unit_frame(const SceneParams& scene, const Camera& camera)
{
    Basis b = rotated_basis(scene, camera);
    glm::dvec3 f = glm::normalize(b.forward);
    glm::dvec3 r = glm::normalize(b.right - glm::dot(b.right, f) * f);
    glm::dvec3 u = glm::normalize(b.up - glm::dot(b.up, f) * f - glm::dot(b.up, r) * r);
    return {f, r, u};
}

std::string show(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

void check_camera(const Camera& camera)
{
    double values[5] = {camera.position.x, camera.position.y, camera.position.z, camera.yaw, camera.pitch};
    for (int i = 0; i < 5; ++i) {
        std::string name = std::string("camera ") + field_names[i];
        if (!std::isfinite(values[i]))
            throw Error(name + " is " + show(values[i]) + " (every value must be finite)");
        if (i < 4 && std::abs(values[i]) > max_magnitude)
            throw Error(name + " = " + show(values[i]) + " is too large (at most 1e6 " +
                        (i < 3 ? "world units" : "degrees") + " either way)");
    }
    if (std::abs(camera.pitch) >= 90.0)
        throw Error("camera PITCH = " + show(camera.pitch) +
                    " degrees: must be inside (-90, 90) (at 90 the view looks along the yaw axis)");
}

glm::dvec3 d3(glm::vec4 v) { return glm::dvec3(v); }

// The nearest t > 0 where o + t d meets the scene's surface as the renders see it; infinity on a miss.
double central_hit(const SceneParams& scene, glm::dvec3 o, glm::dvec3 d)
{
    if (scene.kind_size.x == HARNESS_SCENE_TRIANGLES) {
        double best = INFINITY;
        for (int i = 0; i < std::min(scene.kind_size.w, HARNESS_MAX_TRIANGLES); ++i) {
            glm::dvec3 a = d3(scene.positions[3 * i]);
            glm::dvec3 e1 = d3(scene.positions[3 * i + 1]) - a, e2 = d3(scene.positions[3 * i + 2]) - a;
            glm::dvec3 p = glm::cross(d, e2);
            double det = glm::dot(e1, p);
            if (det == 0.0)
                continue;
            glm::dvec3 s = o - a, q = glm::cross(s, e1);
            double b1 = glm::dot(s, p) / det, b2 = glm::dot(d, q) / det, t = glm::dot(e2, q) / det;
            if (t > 0.0 && t < best && b1 >= 0.0 && b2 >= 0.0 && b1 + b2 <= 1.0)
                best = t;
        }
        return best;
    }
    if (scene.kind_size.x == HARNESS_SCENE_CYLINDER) { // the far root: the wall the renders show
        double radius = scene.p0.x, length = scene.p0.y;
        double a = d.x * d.x + d.y * d.y, b = 2.0 * (o.x * d.x + o.y * d.y), c = o.x * o.x + o.y * o.y - radius * radius;
        double t = (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
        return std::isfinite(t) && t > 0.0 && (o + t * d).z < length ? t : INFINITY;
    }
    glm::dvec3 au = d3(scene.axis_u), av = d3(scene.axis_v), p0 = d3(scene.p0), n = glm::cross(au, av);
    double t = glm::dot(p0 - o, n) / glm::dot(d, n);
    glm::dvec3 rel = o + t * d - p0;
    double s = glm::dot(rel, au) / glm::dot(au, au), v = glm::dot(rel, av) / glm::dot(av, av);
    return std::isfinite(t) && t > 0.0 && std::abs(s) <= scene.extent.x && std::abs(v) <= scene.extent.y ? t : INFINITY;
}

} // namespace

Camera camera_of(const SceneParams& scene) { return {d3(scene.origin), 0.0, 0.0}; }

SceneParams with_camera(const SceneParams& scene, const Camera& camera)
{
    check_camera(camera);
    Basis b = rotated_basis(scene, camera);
    SceneParams moved = scene;
    moved.origin = glm::vec4(glm::vec3(camera.position), scene.origin.w);
    moved.forward = glm::vec4(glm::vec3(b.forward), scene.forward.w);
    moved.right = glm::vec4(glm::vec3(b.right), scene.right.w);
    moved.up = glm::vec4(glm::vec3(b.up), scene.up.w);
    return moved;
}

Camera fly(const Camera& camera, const SceneParams& scene, glm::dvec3 move)
{
    Basis frame = unit_frame(scene, camera);
    Camera moved = camera;
    moved.position += move.x * frame.right + move.y * frame.up + move.z * frame.forward;
    return moved;
}

Camera turn(const Camera& camera, double yaw_degrees, double pitch_degrees)
{
    Camera turned_camera = camera;
    turned_camera.yaw = std::remainder(camera.yaw + yaw_degrees, 360.0); // exact; |x| <= 180 stays x
    turned_camera.pitch = std::clamp(camera.pitch + pitch_degrees, -max_pitch, max_pitch);
    return turned_camera;
}

Camera orbit(const Camera& camera, const SceneParams& scene, glm::dvec3 target, double yaw_degrees,
             double pitch_degrees)
{
    // The offset from the target in the old frame's coordinates, rebuilt in the new frame: a rotation, so
    // the distance is kept, and the target stays where it was in view.
    Basis before = unit_frame(scene, camera);
    glm::dvec3 offset = camera.position - target;
    glm::dvec3 local(glm::dot(offset, before.right), glm::dot(offset, before.up), glm::dot(offset, before.forward));
    Camera orbited = turn(camera, yaw_degrees, pitch_degrees);
    Basis after = unit_frame(scene, orbited);
    orbited.position = target + local.x * after.right + local.y * after.up + local.z * after.forward;
    return orbited;
}

glm::dvec3 look_target(const SceneParams& scene)
{
    glm::dvec3 o = d3(scene.origin), d = d3(scene.forward);
    double t = central_hit(scene, o, d);
    if (t * glm::length(d) <= max_target_distance)
        return o + t * d;
    return o + glm::normalize(d) * default_target_distance;
}

std::string to_string(const Camera& camera)
{
    char text[5 * 26];
    std::snprintf(text, sizeof text, "%.17g,%.17g,%.17g,%.17g,%.17g", camera.position.x, camera.position.y,
                  camera.position.z, camera.yaw, camera.pitch);
    return text;
}

Camera parse_camera(const std::string& text)
{
    std::vector<std::string> fields(1);
    for (char c : text) {
        if (c == ',')
            fields.emplace_back();
        else
            fields.back() += c;
    }
    if (fields.size() != 5)
        throw Error("expected 5 comma-separated numbers X,Y,Z,YAW,PITCH, got " + std::to_string(fields.size()) +
                    " field" + (fields.size() == 1 ? "" : "s") + " in '" + text + "'");
    double values[5];
    for (int i = 0; i < 5; ++i) {
        const std::string& field = fields[size_t(i)];
        const std::optional<double> value = parse_real_number(field); // decimal and finite (core/numbers.h)
        if (!value)
            throw Error(std::string("camera ") + field_names[i] + " '" + field + "' is not a number");
        values[i] = *value;
    }
    Camera camera{{values[0], values[1], values[2]}, values[3], values[4]};
    check_camera(camera);
    return camera;
}

} // namespace tf
