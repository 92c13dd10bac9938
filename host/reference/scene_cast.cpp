// The CPU half of the scenes' ray casts (scene/scene.h describes the scenes): each pixel's hit and uv in
// double, and the whole image's lookups with quad or ray-differential gradients.
#include "reference/scene_cast.h"
#include "harness/config.h"
#include "texture/error.h"
#include <cmath>

namespace tf {

namespace {

constexpr double pi = 3.14159265358979323846;

glm::dvec3 d3(glm::vec4 v) { return glm::dvec3(v); }

glm::dvec3 camera_ray(const SceneParams& scene, double px, double py)
{
    double ndc_x = 2.0 * px / scene.kind_size.y - 1.0;
    double ndc_y = 1.0 - 2.0 * py / scene.kind_size.z;
    return d3(scene.forward) + ndc_x * d3(scene.right) + ndc_y * d3(scene.up);
}

// Barycentric coordinates (b1, b2) of where the ray meets the triangle's plane, and the distance t, by
// Moller-Trumbore (Cramer's rule on [-d e1 e2]); deliberately not the shader's Gram-matrix form.
bool triangle_plane_hit(const SceneParams& scene, int i, glm::dvec3 o, glm::dvec3 d, double& b1, double& b2, double& t)
{
    glm::dvec3 a = d3(scene.positions[3 * i]), e1 = d3(scene.positions[3 * i + 1]) - a,
               e2 = d3(scene.positions[3 * i + 2]) - a;
    glm::dvec3 p = glm::cross(d, e2);
    double det = glm::dot(e1, p);
    if (det == 0.0)
        return false; // the ray runs in the triangle's plane
    glm::dvec3 s = o - a, q = glm::cross(s, e1);
    b1 = glm::dot(s, p) / det;
    b2 = glm::dot(d, q) / det;
    t = glm::dot(e2, q) / det;
    return true;
}

glm::dvec2 triangle_uv(const SceneParams& scene, int i, double b1, double b2)
{
    glm::dvec2 uv0(scene.uvs[3 * i]), uv1(scene.uvs[3 * i + 1]), uv2(scene.uvs[3 * i + 2]);
    return (1.0 - b1 - b2) * uv0 + b1 * uv1 + b2 * uv2 + glm::dvec2(scene.extent.z, scene.extent.w);
}

} // namespace

glm::dvec2 reference_triangle_plane_uv(const SceneParams& scene, int triangle, double px, double py)
{
    double b1 = 0, b2 = 0, t = 0;
    if (!triangle_plane_hit(scene, triangle, d3(scene.origin), camera_ray(scene, px, py), b1, b2, t))
        return glm::dvec2(0.0);
    return triangle_uv(scene, triangle, b1, b2);
}

PixelHit reference_hit(const SceneParams& scene, double px, double py)
{
    glm::dvec3 o = d3(scene.origin);
    glm::dvec3 d = camera_ray(scene, px, py);
    glm::dvec2 offset(scene.extent.z, scene.extent.w);
    PixelHit result;
    if (scene.kind_size.x == HARNESS_SCENE_TRIANGLES) { // nearest hit inside a triangle; uv 0 on a miss
        double best = INFINITY;
        for (int i = 0; i < scene.kind_size.w; ++i) {
            double b1, b2, t;
            const double slack = HARNESS_EDGE_SLACK; // as the GPU: no holes along shared edges
            if (triangle_plane_hit(scene, i, o, d, b1, b2, t) && t > 0.0 && t < best && b1 >= -slack &&
                b2 >= -slack && b1 + b2 <= 1.0 + slack) {
                best = t;
                result = {true, triangle_uv(scene, i, b1, b2), i};
            }
        }
        return result;
    }
    if (scene.kind_size.x == HARNESS_SCENE_CYLINDER) {
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

namespace {

// Pixel (x, y)'s lookup, the ray casts of its quad from hit_at(x, y) (a whole image's, or just the quad's).
template <typename HitAt>
PixelLookup quad_lookup(const SceneParams& scene, Gradients gradients, bool rasterized, int x, int y, HitAt hit_at)
{
    bool triangles = scene.kind_size.x == HARNESS_SCENE_TRIANGLES;
    const PixelHit& self = hit_at(x, y);
    // uv of pixel (px, py) as seen from pixel `self`: a rasterizer's helper invocations stay on self's triangle.
    auto uv_at = [&](int px, int py) {
        if (rasterized && self.hit && triangles)
            return reference_triangle_plane_uv(scene, self.triangle, px + 0.5, py + 0.5);
        return hit_at(px, py).uv;
    };
    // Ray differentials' ideal: d(uv)/d(pixel) on the hit surface (its plane, for triangles).
    auto surface_uv = [&](double px, double py) {
        if (triangles)
            return self.hit ? reference_triangle_plane_uv(scene, self.triangle, px, py) : glm::dvec2(0.0);
        return reference_hit(scene, px, py).uv;
    };
    glm::dvec2 uv = self.uv, dx, dy;
    if (gradients == Gradients::ray) {
        const double h = 1.0 / 1024; // central differences: error ~h^2, far below float32's
        dx = (surface_uv(x + 0.5 + h, y + 0.5) - surface_uv(x + 0.5 - h, y + 0.5)) / (2 * h);
        dy = (surface_uv(x + 0.5, y + 0.5 + h) - surface_uv(x + 0.5, y + 0.5 - h)) / (2 * h);
    } else {
        int x0 = x & ~1, y0 = y & ~1;
        int ax = gradients == Gradients::coarse ? y0 : y; // the row dx is taken along
        int ay = gradients == Gradients::coarse ? x0 : x; // the column dy is taken down
        dx = uv_at(x0 | 1, ax) - uv_at(x0, ax);
        dy = uv_at(ay, y0 | 1) - uv_at(ay, y0);
    }
    PixelLookup p;
    p.hit = self.hit;
    p.lookup = {uv.x, uv.y, dx.x, dx.y, dy.x, dy.y};
    return p;
}

void check_even(const SceneParams& scene)
{
    int width = scene.kind_size.y, height = scene.kind_size.z;
    if (width % 2 != 0 || height % 2 != 0)
        throw Error("quad derivatives need an even image size, got " + std::to_string(width) + "x" +
                    std::to_string(height));
}

} // namespace

std::vector<PixelLookup> reference_lookups(const SceneParams& scene, Gradients gradients, bool rasterized)
{
    check_even(scene);
    int width = scene.kind_size.y, height = scene.kind_size.z;
    std::vector<PixelHit> hits(size_t(width) * size_t(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            hits[size_t(y) * width + x] = reference_hit(scene, x + 0.5, y + 0.5);
    auto hit_at = [&](int x, int y) -> const PixelHit& { return hits[size_t(y) * width + x]; };
    std::vector<PixelLookup> out(hits.size());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            out[size_t(y) * width + x] = quad_lookup(scene, gradients, rasterized, x, y, hit_at);
    return out;
}

PixelLookup reference_pixel_lookup(const SceneParams& scene, Gradients gradients, bool rasterized, int x, int y)
{
    check_even(scene);
    int width = scene.kind_size.y, height = scene.kind_size.z;
    if (x < 0 || y < 0 || x >= width || y >= height)
        throw Error("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                    std::to_string(width) + "x" + std::to_string(height) + " image");
    PixelHit quad[4];
    int x0 = x & ~1, y0 = y & ~1;
    for (int k = 0; k < 4; ++k)
        quad[k] = reference_hit(scene, x0 + (k & 1) + 0.5, y0 + (k >> 1) + 0.5);
    auto hit_at = [&](int px, int py) -> const PixelHit& { return quad[(px - x0) + 2 * (py - y0)]; };
    return quad_lookup(scene, gradients, rasterized, x, y, hit_at);
}

} // namespace tf
