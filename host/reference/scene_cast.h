#pragma once
// The scenes ray-cast on the CPU, in double: what the GPU's ray casts and quad derivatives are checked
// against (shaders/harness/scene.glsl is the GPU half).
#include "core/lookup.h"
#include "scene/scene.h"
#include <glm/glm.hpp>
#include <vector>

namespace tf {

struct PixelHit {
    bool hit = false;
    glm::dvec2 uv{0.0}; // defined on a miss too: the unbounded surface (triangles: 0 on a miss)
    int triangle = -1;  // triangles: which one was hit
};

PixelHit reference_hit(const SceneParams& scene, double px, double py);

// uv where the ray through (px, py) meets the plane of triangle `triangle`, extrapolated beyond its edges:
// what a rasterizer's helper invocations compute next to a triangle's edge.
glm::dvec2 reference_triangle_plane_uv(const SceneParams& scene, int triangle, double px, double py);

// The lookups of a whole image, row-major: uv at the pixel centre and its gradients.
// fine: dx = uv(x|1, y) - uv(x&~1, y), dy = uv(x, y|1) - uv(x, y&~1); coarse: the quad's top-left pair
// for all four pixels; on a periodic axis (the tunnel's u) each difference less the whole periods nearest
// it (a seam's jump), which Tarini's selection on the GPU matches while the change is under half a period;
// ray: the exact derivative of uv with respect to the pixel position (central differences in double),
// which ray differentials approximate to first order; cone: the primary ray cone's footprint (width
// gamma·distance, gamma = reference_pixel_spread) from parallel rays offset by the cone's axes
// (reference_cone_axis_uv). rasterized (mesh): a pixel's quad neighbours take uv on the plane of the
// pixel's own triangle. Sides must be even.
struct PixelLookup {
    bool hit = false;
    Lookup lookup;
};
std::vector<PixelLookup> reference_lookups(const SceneParams& scene, Gradients gradients, bool rasterized);
// The ray cone's pieces, in double: gamma = atan(2 tan(fov_y / 2) / height); the unit axis across the plane
// of incidence (d x n normalised, or the include's fixed perpendicular of d within 1e-4 of normal incidence);
// d(uv)/ds of rays parallel to pixel (px, py)'s ray, their origins moved by s·offset (central differences;
// triangle >= 0: on that triangle's plane; the tunnel's u unwrapped).
double reference_pixel_spread(const SceneParams& scene);
glm::dvec3 reference_incidence_side(glm::dvec3 d, glm::dvec3 n);
glm::dvec2 reference_cone_axis_uv(const SceneParams& scene, double px, double py, glm::dvec3 offset, int triangle);

// One pixel's entry of reference_lookups (the same numbers), from its quad's four ray casts only.
PixelLookup reference_pixel_lookup(const SceneParams& scene, Gradients gradients, bool rasterized, int x, int y);

} // namespace tf
