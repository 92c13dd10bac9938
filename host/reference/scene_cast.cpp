// The CPU half of the scenes' ray casts (scene/scene.h describes the scenes): each pixel's hit and uv in
// double, and the whole image's lookups with quad (seam-free on the tunnel's u), ray-differential or ray-cone
// gradients.
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

namespace {

// A ray's hit on the scene's surface, with what ray cones need: distance and normal. triangle_only >= 0:
// that triangle's plane, unbounded (the footprint of a pixel that hit it stays on it).
struct SurfaceHit {
    PixelHit pixel;
    double t = 0;            // along d as given (not normalised)
    glm::dvec3 normal{0.0};  // not normalised
};

SurfaceHit surface_hit(const SceneParams& scene, glm::dvec3 o, glm::dvec3 d, int triangle_only = -1)
{
    glm::dvec2 offset(scene.extent.z, scene.extent.w);
    SurfaceHit result;
    if (scene.kind_size.x == HARNESS_SCENE_TRIANGLES) { // nearest hit inside a triangle; uv 0 on a miss
        auto frame = [&](int i) {
            glm::dvec3 a = d3(scene.positions[3 * i]);
            return glm::cross(d3(scene.positions[3 * i + 1]) - a, d3(scene.positions[3 * i + 2]) - a);
        };
        if (triangle_only >= 0) {
            double b1 = 0, b2 = 0, t = 0;
            if (triangle_plane_hit(scene, triangle_only, o, d, b1, b2, t))
                result = {{true, triangle_uv(scene, triangle_only, b1, b2), triangle_only}, t, frame(triangle_only)};
            return result;
        }
        double best = INFINITY;
        for (int i = 0; i < scene.kind_size.w; ++i) {
            double b1, b2, t;
            const double slack = HARNESS_EDGE_SLACK; // as the GPU: no holes along shared edges
            if (triangle_plane_hit(scene, i, o, d, b1, b2, t) && t > 0.0 && t < best && b1 >= -slack &&
                b2 >= -slack && b1 + b2 <= 1.0 + slack) {
                best = t;
                result = {{true, triangle_uv(scene, i, b1, b2), i}, t, frame(i)};
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
        result.pixel.uv = glm::dvec2(std::atan2(p.y, p.x) * repeats / (2.0 * pi) + 0.5 * repeats, p.z * double(scene.p0.w));
        result.pixel.uv += offset;
        result.pixel.hit = t > 0.0 && p.z < length;
        result.t = t;
        result.normal = glm::dvec3(p.x, p.y, 0.0);
        return result;
    }
    glm::dvec3 au = d3(scene.axis_u), av = d3(scene.axis_v), p0 = d3(scene.p0);
    glm::dvec3 n = glm::cross(au, av);
    double t = glm::dot(p0 - o, n) / glm::dot(d, n);
    glm::dvec3 rel = o + t * d - p0;
    glm::dvec2 st(glm::dot(rel, au) / glm::dot(au, au), glm::dot(rel, av) / glm::dot(av, av));
    result.pixel.hit = t > 0.0 && std::abs(st.x) <= scene.extent.x && std::abs(st.y) <= scene.extent.y;
    result.pixel.uv = st + offset;
    result.t = t;
    result.normal = n;
    return result;
}

// The scene's uv axes that wrap with period 1 (the tunnel's u: whole turns of the texture around the axis).
glm::bvec2 periodic_axes(const SceneParams& scene) { return {scene.kind_size.x == HARNESS_SCENE_CYLINDER, false}; }

// A difference of uv on the periodic axes taken as the period's representative nearest zero: the change
// without the whole periods a seam adds (exact while the true change is under half a period).
glm::dvec2 unwrap(const SceneParams& scene, glm::dvec2 difference)
{
    glm::bvec2 periodic = periodic_axes(scene);
    for (int k = 0; k < 2; ++k)
        if (periodic[k])
            difference[k] -= std::round(difference[k]);
    return difference;
}

// A unit vector perpendicular to unit v: v x the coordinate axis least aligned with v (ties: x, then y), the
// rule texfilter/derivatives.glsl's cones use where the plane of incidence is undefined.
glm::dvec3 any_perpendicular(glm::dvec3 v)
{
    glm::dvec3 a = glm::abs(v);
    glm::dvec3 axis = a.x <= a.y && a.x <= a.z ? glm::dvec3(1, 0, 0) : a.y <= a.z ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
    return glm::normalize(glm::cross(v, axis));
}

} // namespace

glm::dvec3 reference_incidence_side(glm::dvec3 d, glm::dvec3 n)
{
    glm::dvec3 side = glm::cross(glm::normalize(d), glm::normalize(n));
    double len = glm::length(side);
    return len > 1e-4 ? side / len : any_perpendicular(glm::normalize(d));
}

double reference_pixel_spread(const SceneParams& scene)
{
    return std::atan(2.0 * glm::length(d3(scene.up)) / double(scene.kind_size.z));
}

PixelHit reference_hit(const SceneParams& scene, double px, double py)
{
    return surface_hit(scene, d3(scene.origin), camera_ray(scene, px, py)).pixel;
}

glm::dvec2 reference_cone_axis_uv(const SceneParams& scene, double px, double py, glm::dvec3 offset, int triangle)
{
    glm::dvec3 o = d3(scene.origin), d = camera_ray(scene, px, py);
    const double h = 1.0 / 1024; // central differences of parallel rays: exact on planes, error ~h^2 on the tunnel
    glm::dvec2 ahead = surface_hit(scene, o + h * offset, d, triangle).pixel.uv;
    glm::dvec2 behind = surface_hit(scene, o - h * offset, d, triangle).pixel.uv;
    return unwrap(scene, ahead - behind) / (2.0 * h);
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
        dx = unwrap(scene, surface_uv(x + 0.5 + h, y + 0.5) - surface_uv(x + 0.5 - h, y + 0.5)) / (2 * h);
        dy = unwrap(scene, surface_uv(x + 0.5, y + 0.5 + h) - surface_uv(x + 0.5, y + 0.5 - h)) / (2 * h);
    } else if (gradients == Gradients::cone) {
        // The primary cone (width gamma x distance) as parallel rays offset across the plane of incidence and
        // within it (reference_cone_axis_uv), not the shader's projection onto the tangent plane.
        double px = x + 0.5, py = y + 0.5;
        glm::dvec3 d = camera_ray(scene, px, py);
        int triangle = triangles ? self.triangle : -1;
        SurfaceHit hit = surface_hit(scene, d3(scene.origin), d, triangle);
        if (triangles && !self.hit)
            hit = {};
        double width = reference_pixel_spread(scene) * hit.t * glm::length(d);
        glm::dvec3 side = hit.t > 0.0 ? reference_incidence_side(d, hit.normal) : glm::dvec3(0.0);
        glm::dvec3 along = glm::cross(side, glm::normalize(d));
        dx = width * reference_cone_axis_uv(scene, px, py, side, triangle);
        dy = width * reference_cone_axis_uv(scene, px, py, along, triangle);
        if (!(hit.t > 0.0))
            dx = dy = glm::dvec2(0.0); // behind the camera or a missed triangle: no footprint (the pixel is background)
    } else {
        int x0 = x & ~1, y0 = y & ~1;
        int ax = gradients == Gradients::coarse ? y0 : y; // the row dx is taken along
        int ay = gradients == Gradients::coarse ? x0 : x; // the column dy is taken down
        // Periodic axes (the tunnel's u): the seam's whole periods taken out (unwrap).
        dx = unwrap(scene, uv_at(x0 | 1, ax) - uv_at(x0, ax));
        dy = unwrap(scene, uv_at(ay, y0 | 1) - uv_at(ay, y0));
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
