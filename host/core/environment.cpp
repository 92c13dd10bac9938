#include "core/environment.h"

#include <algorithm>
#include <cmath>

namespace tf {

int environment_size(const EnvironmentMap& env)
{
    return env.map == EnvMap::cube ? env.cube.size() : env.latlong.levels.empty() ? 0 : env.latlong.levels[0].width;
}

EnvMap parse_env_map(const std::string& name)
{
    if (name == "cube")
        return EnvMap::cube;
    if (name == "latlong")
        return EnvMap::latlong;
    throw Error("unknown environment map '" + name + "' (cube, latlong)");
}

std::string to_string(EnvMap map) { return map == EnvMap::cube ? "cube" : "latlong"; }

bool has_environment_form(const SamplerOptions& options)
{
    const Filter filter = options.filter;
    return filter != Filter::brilinear && filter != Filter::sat && filter != Filter::sat_assembly &&
           filter != Filter::ewa_fast;
}

void check_environment_filter(const SamplerOptions& options)
{
    const Filter filter = options.filter;
    if (!has_environment_form(options))
        throw Error("--filter " + to_string(filter) + " has no environment-map form (cube.glsl and latlong.glsl: "
                    "nearest, bilinear, nearest-mip, bilinear-mip, trilinear, aniso, ewa, bspline, catmull-rom, hw-*, "
                    "ground-truth, none)");
}

Image latlong_from_cube(const CubeMap& cube, int width)
{
    if (width < 2 || width % 2 != 0)
        throw Error("lat-long width " + std::to_string(width) + ": must be even and at least 2");
    const int height = width / 2, n = cube.size();
    const double pi = 3.14159265358979323846;
    Image out = make_image(width, height);
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            // The inverse of docs/ENVIRONMENT.md's mapping at the texel centre: phi from u, theta from v.
            const double phi = 2.0 * pi * ((i + 0.5) / width - 0.5), theta = pi * (j + 0.5) / height;
            const glm::dvec3 d(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
            const CubeFacePoint p = cube_face_point(d);
            const int x = std::clamp(int(std::floor(p.s * n)), 0, n - 1), y = std::clamp(int(std::floor(p.t * n)), 0, n - 1);
            out.at(i, j) = cube.faces[size_t(p.face)].levels[0].at(x, y);
        }
    return out;
}

} // namespace tf
