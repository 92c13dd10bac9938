// Environment lookups in double, from docs/ENVIRONMENT.md (not from cube.glsl / latlong.glsl): the
// direction becomes a 2D lookup (face + projected derivatives, or lat-long uv + the mapping's Jacobian),
// and the 2D family runs on it with a TexelSource that reads the map's seamless rule.
#include "reference/environment.h"

#include "core/environment.h"

#include "reference/reference.h"
#include "reference/stochastic.h"
#include "texture/error.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <glm/geometric.hpp>

namespace tf {

namespace {

// The face table (Vulkan "Cube Map Face Selection") as linear forms of d: sc = dot(sc_of[f], d),
// tc = dot(tc_of[f], d), |ma| = dot(ma_of[f], d) on the face the direction selects.
const glm::dvec3 sc_of[cube_face_count] = {{0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {-1, 0, 0}};
const glm::dvec3 tc_of[cube_face_count] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
const glm::dvec3 ma_of[cube_face_count] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

bool usable_direction(const glm::dvec3& d) {
    return std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z) && (d.x != 0 || d.y != 0 || d.z != 0);
}

const MipChain& face_chain(const CubeMap& cube, int face, const char* who) {
    if (face < 0 || face >= cube_face_count)
        throw Error(std::string(who) + ": cube face " + std::to_string(face) + " is not 0..5");
    const MipChain& chain = cube.faces[size_t(face)];
    if (chain.levels.empty()) throw Error(std::string(who) + ": cube face " + std::to_string(face) + " has no levels");
    return chain;
}

const Image& level_of(const MipChain& chain, int level, const char* who) {
    if (level < 0 || level >= int(chain.levels.size()))
        throw Error(std::string(who) + ": level " + std::to_string(level) + " is not 0.." +
                    std::to_string(int(chain.levels.size()) - 1));
    return chain.levels[size_t(level)];
}

// The texel the direction through texel (i, j)'s centre on `face`'s (extended) plane hits.
glm::dvec4 cube_texel_through_centre(const CubeMap& cube, int face, int level, long long i, long long j) {
    const double n = cube.faces[size_t(face)].levels[size_t(level)].width;
    const CubeFacePoint hit = cube_face_point(cube_face_direction(face, (double(i) + 0.5) / n, (double(j) + 0.5) / n));
    const Image& image = level_of(face_chain(cube, hit.face, "cube_texel"), level, "cube_texel");
    const int x = int(std::clamp(std::floor(hit.s * n), 0.0, n - 1));
    const int y = int(std::clamp(std::floor(hit.t * n), 0.0, n - 1));
    return glm::dvec4(image.at(x, y));
}

struct CubeFace {
    const CubeMap* cube;
    int face;
};

glm::dvec4 read_cube_face(const void* map, int level, long long i, long long j) {
    const auto& f = *static_cast<const CubeFace*>(map);
    return cube_texel(*f.cube, f.face, level, i, j);
}

glm::dvec4 read_latlong(const void* map, int level, long long i, long long j) {
    return latlong_texel(*static_cast<const MipChain*>(map), level, i, j);
}

// A cube's hardware tap at face coordinates (u, v) of `level`: the device's seamless bilinear at the direction
// through that point (docs/ENVIRONMENT.md, "Hardware taps"): re-projected onto the face it hits, filtered there.
glm::dvec4 tap_cube_face(const void* map, int level, double u, double v) {
    const auto& f = *static_cast<const CubeFace*>(map);
    const CubeFacePoint p = cube_face_point(cube_face_direction(f.face, u, v));
    const CubeFace hit{f.cube, p.face};
    return reference_bilinear(f.cube->faces[size_t(p.face)], level, p.s, p.t, Wrap::clamp, {read_cube_face, &hit});
}

// A lat-long map's hardware tap: the device's sampler repeats in u and clamps in v (no pole crossing).
glm::dvec4 read_latlong_sampler(const void* map, int level, long long i, long long j) {
    const Image& image = static_cast<const MipChain*>(map)->levels.at(size_t(level));
    const long long w = image.width, h = image.height;
    return glm::dvec4(image.at(int(((i % w) + w) % w), int(std::clamp(j, 0LL, h - 1))));
}

glm::dvec4 tap_latlong(const void* map, int level, double u, double v) {
    const MipChain& chain = *static_cast<const MipChain*>(map);
    // Only u is periodic: a tap past the -y pole (v > 1) must clamp there, not come back round to v = 0 as a
    // whole-period reduction of v would take it (repeat's reduce_uv maps 1.02 to -0.98).
    return reference_bilinear(chain, level, reduce_uv(u, Wrap::repeat), v, Wrap::clamp, {read_latlong_sampler, &chain});
}

// The filters a lookup has on an environment map; the others throw, naming the filter.
void check_lookup_filter(const SamplerOptions& options) {
    const Filter filter = options.filter;
    check_environment_filter(options); // brilinear and the SAT filters: no environment form
    if (filter == Filter::hw_aniso)
        throw Error("hw-aniso has no CPU reference: anisotropic filtering is implementation-defined in Vulkan");
    if (filter == Filter::ground_truth)
        throw Error("ground-truth integrates over a pixel of a scene, not around one lookup: render it");
}

// `none` (the benchmark's baseline, no texture): the unit direction as a colour, as render_env.frag.glsl shows it.
glm::dvec4 none_color(const glm::dvec3& dir) { return glm::dvec4(0.5 * glm::normalize(dir) + 0.5, 1.0); }

// The 2D lookup a direction lookup becomes, with the texture it runs on, the uv reduction (a face's uv is in
// [0, 1]: clamp's is a no-op there and keeps far probes bounded; lat-long repeats) and the map's texel source:
// run(chain, reduction, lookup, texels). The direction must be usable.
template <typename Run>
auto on_cube_face(const CubeMap& cube, const EnvLookup& lookup, Run run) {
    int face = 0;
    const Lookup l = cube_face_lookup(lookup, face);
    const CubeFace map{&cube, face};
    return run(cube.faces[size_t(face)], Wrap::clamp, l, TexelSource{read_cube_face, &map, tap_cube_face});
}
template <typename Run>
auto on_latlong(const MipChain& chain, const EnvLookup& lookup, Run run) {
    return run(chain, Wrap::repeat, latlong_lookup(lookup), TexelSource{read_latlong, &chain, tap_latlong});
}

// The options of the 2D family on the map: the sampler's wrap mode replaced by the map's uv reduction.
SamplerOptions on_map(const SamplerOptions& options, Wrap reduction) {
    SamplerOptions two_d = options;
    two_d.wrap = reduction;
    return two_d;
}

void check_cube(const CubeMap& cube, const char* who) {
    for (int f = 0; f < cube_face_count; ++f) face_chain(cube, f, who);
}

} // namespace

glm::dvec4 cube_texel(const CubeMap& cube, int face, int level, long long i, long long j) {
    const Image& image = level_of(face_chain(cube, face, "cube_texel"), level, "cube_texel");
    const long long n = image.width;
    const bool i_in = i >= 0 && i < n, j_in = j >= 0 && j < n;
    if (i_in && j_in) return glm::dvec4(image.at(int(i), int(j)));
    if (!i_in && !j_in && (i == -1 || i == n) && (j == -1 || j == n)) { // a bilinear corner: three faces meet
        const long long ic = std::clamp(i, 0LL, n - 1), jc = std::clamp(j, 0LL, n - 1);
        return (glm::dvec4(image.at(int(ic), int(jc))) + cube_texel_through_centre(cube, face, level, i, jc) +
                cube_texel_through_centre(cube, face, level, ic, j)) /
               3.0;
    }
    return cube_texel_through_centre(cube, face, level, i, j);
}

glm::dvec4 latlong_texel(const MipChain& chain, int level, long long i, long long j) {
    const Image& image = level_of(chain, level, "latlong_texel");
    const long long w = image.width, h = image.height;
    long long row = ((j % (2 * h)) + 2 * h) % (2 * h); // rows repeat every 2H: over both poles and back
    long long column = ((i % w) + w) % w;
    if (row >= h) { // past a pole: the row mirrored, the column on the other side (exact for even widths)
        row = 2 * h - 1 - row;
        column = (column + w / 2) % w;
    }
    return glm::dvec4(image.at(int(column), int(row)));
}

Lookup cube_face_lookup(const EnvLookup& lookup, int& face) {
    const CubeFacePoint p = cube_face_point(lookup.dir);
    face = p.face;
    const glm::dvec3 &a = sc_of[face], &b = tc_of[face], &c = ma_of[face];
    const double sc = glm::dot(a, lookup.dir), tc = glm::dot(b, lookup.dir), m = glm::dot(c, lookup.dir);
    Lookup l;
    l.u = p.s, l.v = p.t;
    // d(s) = (d(sc) m - sc d(m)) / (2 m^2), the same for t: the derivatives projected onto the face.
    const auto project = [&](const glm::dvec3& dd, double& ds, double& dt) {
        const double dm = glm::dot(c, dd);
        ds = 0.5 * (glm::dot(a, dd) * m - sc * dm) / (m * m);
        dt = 0.5 * (glm::dot(b, dd) * m - tc * dm) / (m * m);
    };
    project(lookup.ddx, l.dudx, l.dvdx);
    project(lookup.ddy, l.dudy, l.dvdy);
    return l;
}

Lookup latlong_lookup(const EnvLookup& lookup) {
    const glm::dvec3& d = lookup.dir;
    const double pi = std::numbers::pi;
    const double rho2 = d.x * d.x + d.z * d.z, rho = std::sqrt(rho2);
    const double r2 = rho2 + d.y * d.y, r = std::sqrt(r2);
    Lookup l;
    l.u = 0.5 + (rho2 > 0 ? std::atan2(d.x, -d.z) : 0.0) / (2 * pi); // an exact pole: longitude 0 (as the shader)
    l.v = std::acos(std::clamp(d.y / r, -1.0, 1.0)) / pi;
    const auto jacobian = [&](const glm::dvec3& dd, double& du, double& dv) {
        du = (-d.z * dd.x + d.x * dd.z) / (2 * pi * rho2);
        dv = -(dd.y - d.y * glm::dot(d, dd) / r2) / (pi * rho);
    };
    jacobian(lookup.ddx, l.dudx, l.dvdx);
    jacobian(lookup.ddy, l.dudy, l.dvdy);
    return l;
}

glm::dvec4 reference_cube_sample(const CubeMap& cube, const SamplerOptions& options, const EnvLookup& lookup) {
    check_lookup_filter(options);
    check_cube(cube, "reference_cube_sample");
    if (!usable_direction(lookup.dir)) return glm::dvec4(0.0);
    if (options.filter == Filter::none) return none_color(lookup.dir);
    return on_cube_face(cube, lookup, [&](const MipChain& chain, Wrap reduction, const Lookup& l, const TexelSource& t) {
        return reference_sample_texels(chain, on_map(options, reduction), l, t);
    });
}

glm::dvec4 reference_latlong_sample(const MipChain& chain, const SamplerOptions& options, const EnvLookup& lookup) {
    check_lookup_filter(options);
    if (chain.levels.empty()) throw Error("reference_latlong_sample: empty MIP chain");
    if (!usable_direction(lookup.dir)) return glm::dvec4(0.0);
    if (options.filter == Filter::none) return none_color(lookup.dir);
    return on_latlong(chain, lookup, [&](const MipChain& c, Wrap reduction, const Lookup& l, const TexelSource& t) {
        return reference_sample_texels(c, on_map(options, reduction), l, t);
    });
}

glm::dvec4 reference_cube_stochastic_mean(const CubeMap& cube, const SamplerOptions& options, const EnvLookup& lookup,
                                          int px, int py) {
    check_reference_stochastic(options);
    check_cube(cube, "reference_cube_stochastic_mean");
    if (!usable_direction(lookup.dir)) return glm::dvec4(0.0);
    return on_cube_face(cube, lookup, [&](const MipChain& chain, Wrap reduction, const Lookup& l, const TexelSource& t) {
        return reference_stochastic_mean(chain, on_map(options, reduction), l, px, py, 0u, t);
    });
}

glm::dvec4 reference_latlong_stochastic_mean(const MipChain& chain, const SamplerOptions& options,
                                             const EnvLookup& lookup, int px, int py) {
    check_reference_stochastic(options);
    if (chain.levels.empty()) throw Error("reference_latlong_stochastic_mean: empty MIP chain");
    if (!usable_direction(lookup.dir)) return glm::dvec4(0.0);
    return on_latlong(chain, lookup, [&](const MipChain& c, Wrap reduction, const Lookup& l, const TexelSource& t) {
        return reference_stochastic_mean(c, on_map(options, reduction), l, px, py, 0u, t);
    });
}

StochasticMoments reference_cube_stochastic_moments(const CubeMap& cube, const SamplerOptions& options,
                                                    const EnvLookup& lookup) {
    check_reference_stochastic(options);
    check_cube(cube, "reference_cube_stochastic_moments");
    if (!usable_direction(lookup.dir)) return {};
    return on_cube_face(cube, lookup, [&](const MipChain& chain, Wrap reduction, const Lookup& l, const TexelSource& t) {
        return reference_stochastic_moments(chain, on_map(options, reduction), l, t);
    });
}

StochasticMoments reference_latlong_stochastic_moments(const MipChain& chain, const SamplerOptions& options,
                                                       const EnvLookup& lookup) {
    check_reference_stochastic(options);
    if (chain.levels.empty()) throw Error("reference_latlong_stochastic_moments: empty MIP chain");
    if (!usable_direction(lookup.dir)) return {};
    return on_latlong(chain, lookup, [&](const MipChain& c, Wrap reduction, const Lookup& l, const TexelSource& t) {
        return reference_stochastic_moments(c, on_map(options, reduction), l, t);
    });
}

glm::dvec4 reference_cube_bilinear0(const CubeMap& cube, const glm::dvec3& dir) {
    check_cube(cube, "reference_cube_bilinear0");
    if (!usable_direction(dir)) return glm::dvec4(0.0);
    const CubeFacePoint p = cube_face_point(dir);
    const CubeFace map{&cube, p.face};
    return reference_bilinear(cube.faces[size_t(p.face)], 0, p.s, p.t, Wrap::clamp, {read_cube_face, &map});
}

glm::dvec4 reference_latlong_bilinear0(const MipChain& chain, const glm::dvec3& dir) {
    if (chain.levels.empty()) throw Error("reference_latlong_bilinear0: empty MIP chain");
    if (!usable_direction(dir)) return glm::dvec4(0.0);
    const Lookup l = latlong_lookup({dir, glm::dvec3(0.0), glm::dvec3(0.0)});
    return reference_bilinear(chain, 0, l.u, l.v, Wrap::repeat, {read_latlong, &chain});
}

} // namespace tf
