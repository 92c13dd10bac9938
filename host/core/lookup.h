#pragma once
// One point lookup, the unit every filter answers: what the GPU harness, the CPU reference and the
// lookups CSV all exchange.

#include <glm/vec3.hpp>

namespace tf {

// uv in [0,1] texture space, gradients per pixel (d(u,v)/dx and d(u,v)/dy) in uv units.
struct Lookup {
    double u = 0, v = 0;
    double dudx = 0, dvdx = 0, dudy = 0, dvdy = 0;
};

// One environment lookup (cube and lat-long maps, docs/ENVIRONMENT.md): a direction (any length but zero)
// and its derivatives per pixel, d(dir)/dx and d(dir)/dy, in the same units.
struct EnvLookup {
    glm::dvec3 dir{0.0, 0.0, 1.0};
    glm::dvec3 ddx{0.0}, ddy{0.0};
};

// Which environment map a scene's lookups read: a cube map (six faces, seamless) or one lat-long
// (equirectangular) 2D texture.
enum class EnvMap { cube, latlong };

} // namespace tf
