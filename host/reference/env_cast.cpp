// The CPU half of the environment scenes' ray casts (reference/env_cast.h), written from the geometry in
// double, independently of shaders/harness/env_scene.glsl (which transfers analytic ray differentials; here
// derivatives are central differences of the direction itself).
#include "reference/env_cast.h"
#include "reference/scene_cast.h"
#include "harness/config.h"
#include "texture/error.h"
#include <cmath>
#include <string>

namespace tf {

namespace {

glm::dvec3 d3(glm::vec4 v) { return glm::dvec3(v); }

void check_environment(const SceneParams& scene)
{
    int kind = scene.kind_size.x;
    if (kind != HARNESS_SCENE_SKYBOX && kind != HARNESS_SCENE_REFLECT)
        throw Error("scene id " + std::to_string(kind) +
                    " is not an environment scene (expected skybox or reflect): it has no lookup directions");
}

void check_even(const SceneParams& scene)
{
    int width = scene.kind_size.y, height = scene.kind_size.z;
    if (width <= 0 || height <= 0 || width % 2 != 0 || height % 2 != 0)
        throw Error("quad derivatives need an even image size, got " + std::to_string(width) + "x" +
                    std::to_string(height));
}

} // namespace

EnvRay reference_env_ray(const SceneParams& scene, double px, double py)
{
    check_environment(scene);
    EnvRay out;
    double ndc_x = 2.0 * px / scene.kind_size.y - 1.0;
    double ndc_y = 1.0 - 2.0 * py / scene.kind_size.z;
    out.ray = d3(scene.forward) + ndc_x * d3(scene.right) + ndc_y * d3(scene.up);
    out.dir = out.ray;
    if (scene.kind_size.x != HARNESS_SCENE_REFLECT)
        return out;
    // Solve |o + t d - c|^2 = r^2 for the ray as given (a t^2 + 2 h t + k = 0), the nearer root by the
    // cancellation-free form t = k / (-h + sqrt(h^2 - a k)) for a camera outside the sphere (k > 0).
    glm::dvec3 o = d3(scene.origin), c(scene.p0.x, scene.p0.y, scene.p0.z), d = out.ray;
    double radius = scene.p0.w;
    double a = glm::dot(d, d), h = glm::dot(o - c, d), k = glm::dot(o - c, o - c) - radius * radius;
    double disc = h * h - a * k;
    if (!(disc >= 0.0) || !(k > 0.0) || !(h < 0.0))
        return out; // a miss, the sphere behind the camera, or the camera inside it: the sky
    double t = k / (-h + std::sqrt(disc));
    out.mirror = true;
    out.point = o + t * d;
    out.normal = glm::normalize(out.point - c);
    glm::dvec3 incident = glm::normalize(d);
    out.dir = incident - 2.0 * glm::dot(incident, out.normal) * out.normal;
    return out;
}

glm::dvec3 reference_env_direction(const SceneParams& scene, double px, double py)
{
    return reference_env_ray(scene, px, py).dir;
}

namespace {

// d(dir)/d(pixel) along `step` (one pixel right or down) at (px, py), on the centre's side of the silhouette:
// central differences at h and h/2, Richardson-extrapolated (error ~h^4: the mirror's curvature near its
// silhouette left plain central differences at h = 1/1024 off by up to 8e-5, more than float32's rounding).
glm::dvec3 ray_derivative(const SceneParams& scene, double px, double py, glm::dvec2 step)
{
    const double h = 1.0 / 1024;
    auto at = [&](double offset) { return reference_env_ray(scene, px + offset * step.x, py + offset * step.y); };
    EnvRay centre = at(0.0), ahead = at(h), behind = at(-h), near_ahead = at(0.5 * h), near_behind = at(-0.5 * h);
    bool ahead_same = ahead.mirror == centre.mirror, behind_same = behind.mirror == centre.mirror;
    if (ahead_same && behind_same && near_ahead.mirror == centre.mirror && near_behind.mirror == centre.mirror) {
        glm::dvec3 wide = (ahead.dir - behind.dir) / (2.0 * h), narrow = (near_ahead.dir - near_behind.dir) / h;
        return (4.0 * narrow - wide) / 3.0;
    }
    if (ahead_same)
        return (ahead.dir - centre.dir) / h;
    if (behind_same)
        return (centre.dir - behind.dir) / h;
    return glm::dvec3(0.0); // a silhouette thinner than 2h: no derivative to speak of
}

// The ray cone's direction footprint at (px, py) (texfilter/derivatives.glsl's model, in double): sky: a circle
// of angular diameter gamma around the camera ray, axes along the camera's right (made perpendicular) and
// across it; mirror: the primary cone (width gamma x distance at the hit) reflected by the sphere's curvature
// 1/radius: gamma + 2 w |cos theta| / radius across the plane of incidence, gamma + 2 w / (|cos theta| radius)
// within it. Each axis scaled by |dir|.
EnvLookup cone_lookup(const SceneParams& scene, double px, double py)
{
    EnvRay ray = reference_env_ray(scene, px, py);
    double gamma = reference_pixel_spread(scene);
    EnvLookup l;
    l.dir = ray.dir;
    glm::dvec3 d = glm::normalize(ray.dir);
    if (!ray.mirror) {
        glm::dvec3 right = d3(scene.right);
        glm::dvec3 side = glm::normalize(right - glm::dot(right, d) * d);
        double scale = gamma * glm::length(ray.dir);
        l.ddx = scale * side;
        l.ddy = scale * glm::cross(d, side);
        return l;
    }
    glm::dvec3 incident = glm::normalize(ray.ray);
    double width = gamma * glm::length(ray.point - d3(scene.origin));
    double c = std::abs(glm::dot(incident, ray.normal)), curvature = 1.0 / double(scene.p0.w);
    glm::dvec3 side = reference_incidence_side(incident, ray.normal);
    l.ddx = (gamma + 2.0 * curvature * width * c) * side;
    l.ddy = (gamma + 2.0 * curvature * width / c) * glm::cross(d, side);
    return l;
}

} // namespace

std::vector<EnvLookup> reference_env_lookups(const SceneParams& scene, Gradients gradients)
{
    check_environment(scene);
    check_even(scene);
    int width = scene.kind_size.y, height = scene.kind_size.z;
    std::vector<glm::dvec3> dirs(size_t(width) * size_t(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            dirs[size_t(y) * width + x] = reference_env_direction(scene, x + 0.5, y + 0.5);
    auto dir_at = [&](int x, int y) { return dirs[size_t(y) * width + x]; };
    std::vector<EnvLookup> out(dirs.size());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            EnvLookup& l = out[size_t(y) * width + x];
            l.dir = dir_at(x, y);
            if (gradients == Gradients::cone) {
                l = cone_lookup(scene, x + 0.5, y + 0.5);
                continue;
            }
            if (gradients == Gradients::ray) {
                l.ddx = ray_derivative(scene, x + 0.5, y + 0.5, {1.0, 0.0});
                l.ddy = ray_derivative(scene, x + 0.5, y + 0.5, {0.0, 1.0});
                continue;
            }
            int x0 = x & ~1, y0 = y & ~1;
            int ax = gradients == Gradients::coarse ? y0 : y; // the row dx is taken along
            int ay = gradients == Gradients::coarse ? x0 : x; // the column dy is taken down
            l.ddx = dir_at(x0 | 1, ax) - dir_at(x0, ax);
            l.ddy = dir_at(ay, y0 | 1) - dir_at(ay, y0);
        }
    return out;
}

} // namespace tf
