// Tier-1 tests of the environment reference (reference/environment.h) against docs/ENVIRONMENT.md and
// Vulkan's cube map rules. Expected texels and tables are written out here by hand, never by calling the
// rule under test.
#include "core/filter.h"
#include "reference/environment.h"
#include "reference/reference.h"
#include "support.h"
#include "texture/mip.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

using glm::dvec3;
using glm::dvec4;
using tf::Filter;

namespace {

constexpr int kPlusX = 0, kMinusX = 1, kPlusY = 2, kMinusY = 3, kPlusZ = 4, kMinusZ = 5;

// Every level of every face built texel by texel from `value(face, level, i, j, size)` (not downsampled).
template <typename Value>
tf::CubeMap make_cube(int n, Value value) {
    tf::CubeMap cube;
    for (int f = 0; f < tf::cube_face_count; ++f)
        for (int l = 0;; ++l) {
            const int size = std::max(1, n >> l);
            tf::Image image = tf::make_image(size, size);
            for (int j = 0; j < size; ++j)
                for (int i = 0; i < size; ++i) image.texels[size_t(j * size + i)] = glm::vec4(value(f, l, i, j, size));
            cube.faces[size_t(f)].levels.push_back(std::move(image));
            if (size == 1) break;
        }
    return cube;
}

// A texel that says where it is: (face, level, i, j), unique per texel, so a wrong read names itself.
dvec4 label(int face, int level, int i, int j) { return dvec4(face, level, i, j); }
tf::CubeMap labelled_cube(int n) {
    return make_cube(n, [](int f, int l, int i, int j, int) { return label(f, l, i, j); });
}

// Vulkan "Cube Map Edge Handling" written out by hand from the face table (sc, tc, ma): the texel one
// past an edge of `face` is the edge texel of the adjacent face at the same place along the edge. Edges:
// 0 left (i = -1), 1 right (i = n), 2 top (j = -1), 3 bottom (j = n); k is the position along the edge
// (j for left/right, i for top/bottom); m = n - 1.
struct FaceTexel {
    int face, i, j;
};
FaceTexel past_edge(int face, int edge, int k, int n) {
    const int m = n - 1;
    switch (face * 4 + edge) {
    case kPlusX * 4 + 0: return {kPlusZ, m, k};
    case kPlusX * 4 + 1: return {kMinusZ, 0, k};
    case kPlusX * 4 + 2: return {kPlusY, m, m - k};
    case kPlusX * 4 + 3: return {kMinusY, m, k};
    case kMinusX * 4 + 0: return {kMinusZ, m, k};
    case kMinusX * 4 + 1: return {kPlusZ, 0, k};
    case kMinusX * 4 + 2: return {kPlusY, 0, k};
    case kMinusX * 4 + 3: return {kMinusY, 0, m - k};
    case kPlusY * 4 + 0: return {kMinusX, k, 0};
    case kPlusY * 4 + 1: return {kPlusX, m - k, 0};
    case kPlusY * 4 + 2: return {kMinusZ, m - k, 0};
    case kPlusY * 4 + 3: return {kPlusZ, k, 0};
    case kMinusY * 4 + 0: return {kMinusX, m - k, m};
    case kMinusY * 4 + 1: return {kPlusX, k, m};
    case kMinusY * 4 + 2: return {kPlusZ, k, m};
    case kMinusY * 4 + 3: return {kMinusZ, m - k, m};
    case kPlusZ * 4 + 0: return {kMinusX, m, k};
    case kPlusZ * 4 + 1: return {kPlusX, 0, k};
    case kPlusZ * 4 + 2: return {kPlusY, k, m};
    case kPlusZ * 4 + 3: return {kMinusY, k, 0};
    case kMinusZ * 4 + 0: return {kPlusX, m, k};
    case kMinusZ * 4 + 1: return {kMinusX, 0, k};
    case kMinusZ * 4 + 2: return {kPlusY, m - k, 0};
    default: return {kMinusY, m - k, m}; // -Z bottom
    }
}

// The filters with an environment form, each configuration its own entry.
struct Config {
    const char* name;
    tf::SamplerOptions options;
};
std::vector<Config> environment_filters() {
    std::vector<Config> configs;
    const auto add = [&](const char* name, Filter filter, auto tweak) {
        tf::SamplerOptions o;
        o.filter = filter;
        tweak(o);
        configs.push_back({name, o});
    };
    const auto none = [](tf::SamplerOptions&) {};
    add("nearest", Filter::nearest, none);
    add("bilinear", Filter::bilinear, none);
    add("nearest-mip", Filter::nearest_mip, none);
    add("bilinear-mip", Filter::bilinear_mip, none);
    add("trilinear", Filter::trilinear, none);
    add("hw-nearest", Filter::hw_nearest, none);
    add("hw-bilinear", Filter::hw_bilinear, none);
    add("hw-trilinear", Filter::hw_trilinear, none);
    add("aniso-gpu", Filter::aniso, none);
    add("aniso-feline", Filter::aniso, [](tf::SamplerOptions& o) { o.aniso_shape = tf::AnisoShape::feline; });
    add("aniso-hw-taps", Filter::aniso, [](tf::SamplerOptions& o) { o.taps = tf::Taps::hardware; });
    add("ewa", Filter::ewa, none);
    add("ewa-hw-taps", Filter::ewa, [](tf::SamplerOptions& o) { o.taps = tf::Taps::hardware; });
    add("ewa-alpha3-aniso4", Filter::ewa, [](tf::SamplerOptions& o) { o.alpha = 3, o.max_aniso = 4; });
    add("bspline", Filter::bspline, none);
    add("catmull-rom", Filter::catmull_rom, none);
    add("bspline-hw-taps", Filter::bspline, [](tf::SamplerOptions& o) { o.taps = tf::Taps::hardware; });
    add("catmull-rom-hw-taps", Filter::catmull_rom, [](tf::SamplerOptions& o) { o.taps = tf::Taps::hardware; });
    add("aniso-hw-taps-magnify-bspline", Filter::aniso, [](tf::SamplerOptions& o) {
        o.taps = tf::Taps::hardware, o.magnify = tf::Reconstruction::bspline;
    });
    add("ewa-hw-taps-magnify-catmull-rom", Filter::ewa, [](tf::SamplerOptions& o) {
        o.taps = tf::Taps::hardware, o.magnify = tf::Reconstruction::catmull_rom;
    });
    return configs;
}

// Random lookups: directions anywhere, within a few thousandths of a face edge, and near corners, with
// derivatives from 2^-14 to 2^2 (direction units) in random directions, some zero, some degenerate.
std::vector<tf::EnvLookup> random_env_lookups(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), octave(-14.0, 2.0), eps(-0.004, 0.004);
    std::uniform_int_distribution<int> face(0, 5), kind(0, 3);
    const auto random_vector = [&] { return dvec3(unit(rng), unit(rng), unit(rng)); };
    std::vector<tf::EnvLookup> lookups;
    for (int k = 0; k < count; ++k) {
        tf::EnvLookup l;
        const int f = face(rng);
        switch (kind(rng)) {
        case 0: l.dir = random_vector(); break;
        case 1: l.dir = tf::cube_face_direction(f, unit(rng) < 0 ? eps(rng) : 1 + eps(rng), 0.5 * (unit(rng) + 1)); break;
        case 2: l.dir = tf::cube_face_direction(f, (unit(rng) < 0 ? 0 : 1) + eps(rng), (unit(rng) < 0 ? 0 : 1) + eps(rng)); break;
        default: l.dir = dvec3(eps(rng), unit(rng) < 0 ? -1 : 1, eps(rng)); break; // near a lat-long pole
        }
        if (k % 17 != 0) {
            l.ddx = std::exp2(octave(rng)) * random_vector();
            l.ddy = std::exp2(octave(rng)) * random_vector();
        }
        if (k % 29 == 5) l.ddx = l.ddy; // a degenerate (line) footprint
        lookups.push_back(l);
    }
    return lookups;
}

// f(d) = (d/|d| + 1)/2 per channel, alpha 1: smooth on the sphere, different on every face.
dvec4 smooth_value(const dvec3& d) { return dvec4(0.5 * (glm::normalize(d) + 1.0), 1.0); }
tf::CubeMap smooth_cube(int n) {
    return make_cube(n, [](int f, int, int i, int j, int size) {
        return smooth_value(tf::cube_face_direction(f, (i + 0.5) / size, (j + 0.5) / size));
    });
}

} // namespace

TEST_SUITE_BEGIN("reference");

TEST_CASE("face-selection")
{
    // (direction, face, s, t) from the table by hand: s = (sc/|ma| + 1)/2, t = (tc/|ma| + 1)/2.
    struct Known {
        dvec3 d;
        int face;
        double s, t;
    };
    const Known known[] = {
        {{2, 1, -0.5}, kPlusX, 0.625, 0.25},   // sc = -z = 0.5, tc = -y = -1, ma = 2
        {{-2, 1, -0.5}, kMinusX, 0.375, 0.25}, // sc = z = -0.5, tc = -y = -1
        {{0.5, 2, 1}, kPlusY, 0.625, 0.75},    // sc = x = 0.5, tc = z = 1
        {{0.5, -2, 1}, kMinusY, 0.625, 0.25},  // sc = x, tc = -z = -1
        {{0.5, 1, 2}, kPlusZ, 0.625, 0.25},    // sc = x, tc = -y = -1
        {{0.5, 1, -2}, kMinusZ, 0.375, 0.25},  // sc = -x = -0.5, tc = -y = -1
        {{1, 1, 1}, kPlusX, 0.0, 0.0},         // tie: x before y before z
        {{0, -1, 1}, kMinusY, 0.5, 0.0},       // tie y, z: y; sc = 0, tc = -z = -1
        {{-1, -1, -1}, kMinusX, 0.0, 1.0},     // tie: x; sc = z = -1, tc = -y = 1
        {{0.0, -0.0, 2}, kPlusZ, 0.5, 0.5},    // -0 in the minor axes changes nothing
    };
    for (const Known& k : known) {
        const tf::CubeFacePoint p = tf::cube_face_point(k.d);
        CHECK_EQ(p.face, k.face);
        CHECK_NEAR(p.s, k.s, 1e-15);
        CHECK_NEAR(p.t, k.t, 1e-15);
    }
    // cube_face_direction inverts it: the same face and (s, t), for directions strictly inside faces.
    std::mt19937 rng(15);
    std::uniform_real_distribution<double> st(0.001, 0.999);
    for (int f = 0; f < tf::cube_face_count; ++f)
        for (int k = 0; k < 50; ++k) {
            const double s = st(rng), t = st(rng);
            const tf::CubeFacePoint p = tf::cube_face_point(3.0 * tf::cube_face_direction(f, s, t));
            CHECK_EQ(p.face, f);
            CHECK_NEAR(p.s, s, 1e-14);
            CHECK_NEAR(p.t, t, 1e-14);
        }
}

TEST_CASE("face-footprint")
{
    // The projected derivatives are the derivatives of the face uv: central differences of
    // cube_face_point along d(dir)/dx, d(dir)/dy (step 1e-6, error O(1e-12)) agree within 1e-8.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), st(0.05, 0.95);
    for (int f = 0; f < tf::cube_face_count; ++f)
        for (int k = 0; k < 20; ++k) {
            tf::EnvLookup l;
            l.dir = (1.5 + unit(rng)) * tf::cube_face_direction(f, st(rng), st(rng));
            l.ddx = dvec3(unit(rng), unit(rng), unit(rng));
            l.ddy = dvec3(unit(rng), unit(rng), unit(rng));
            int face = -1;
            const tf::Lookup uv = tf::cube_face_lookup(l, face);
            CHECK_EQ(face, f);
            const double h = 1e-6;
            for (int axis = 0; axis < 2; ++axis) {
                const dvec3 dd = axis == 0 ? l.ddx : l.ddy;
                const tf::CubeFacePoint a = tf::cube_face_point(l.dir + h * dd), b = tf::cube_face_point(l.dir - h * dd);
                CHECK_EQ(a.face, f);
                CHECK_NEAR(axis == 0 ? uv.dudx : uv.dudy, (a.s - b.s) / (2 * h), 1e-8);
                CHECK_NEAR(axis == 0 ? uv.dvdx : uv.dvdy, (a.t - b.t) / (2 * h), 1e-8);
            }
        }
}

TEST_CASE("latlong-mapping")
{
    // By hand: u = 1/2 + atan2(x, -z)/2pi, v = acos(y/|d|)/pi.
    const double r = 1 / std::sqrt(2.0);
    struct Known {
        dvec3 d;
        double u, v;
    };
    const Known known[] = {{{0, 0, -3}, 0.5, 0.5}, {{2, 0, 0}, 0.75, 0.5}, {{-1, 0, 0}, 0.25, 0.5},
                           {{0, 1, -1}, 0.5, 0.25}, {{r, -1, -r}, 0.625, 0.75}};
    for (const Known& k : known) {
        const tf::Lookup l = tf::latlong_lookup({k.d, dvec3(0.0), dvec3(0.0)});
        CHECK_NEAR(l.u, k.u, 1e-15);
        CHECK_NEAR(l.v, k.v, 1e-15);
    }
    // The gradients are the Jacobian of that map: central differences (step 1e-6) within 1e-8.
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int k = 0; k < 100; ++k) {
        tf::EnvLookup l{dvec3(unit(rng), 0.9 * unit(rng), unit(rng)), dvec3(unit(rng), unit(rng), unit(rng)),
                        dvec3(unit(rng), unit(rng), unit(rng))};
        if (std::hypot(l.dir.x, l.dir.z) < 0.2 || std::abs(l.dir.x) + std::abs(l.dir.z + 1) < 0.1) continue;
        const tf::Lookup uv = tf::latlong_lookup(l);
        const double h = 1e-6;
        for (int axis = 0; axis < 2; ++axis) {
            const dvec3 dd = axis == 0 ? l.ddx : l.ddy;
            const tf::Lookup a = tf::latlong_lookup({l.dir + h * dd, {}, {}}), b = tf::latlong_lookup({l.dir - h * dd, {}, {}});
            CHECK_NEAR(axis == 0 ? uv.dudx : uv.dudy, (a.u - b.u) / (2 * h), 1e-8);
            CHECK_NEAR(axis == 0 ? uv.dvdx : uv.dvdy, (a.v - b.v) / (2 * h), 1e-8);
        }
    }
}

TEST_CASE("edge-adjacency")
{
    // One texel past each of the 24 face edges, every position along it, on levels 0..2 (8, 4, 2 texels):
    // the texel Vulkan's edge table names, from the labelled cube (face, level, i, j): exact.
    const tf::CubeMap cube = labelled_cube(8);
    int checked = 0;
    for (int level = 0; level < 3; ++level) {
        const int n = 8 >> level;
        for (int f = 0; f < tf::cube_face_count; ++f)
            for (int edge = 0; edge < 4; ++edge)
                for (int k = 0; k < n; ++k) {
                    const long long i = edge == 0 ? -1 : edge == 1 ? n : k;
                    const long long j = edge == 2 ? -1 : edge == 3 ? n : k;
                    const FaceTexel want = past_edge(f, edge, k, n);
                    const dvec4 got = tf::cube_texel(cube, f, level, i, j);
                    CHECK(got == label(want.face, level, want.i, want.j),
                          "face " + std::to_string(f) + " edge " + std::to_string(edge) + " k " + std::to_string(k) +
                              " level " + std::to_string(level) + ": got " + tf::test::show(got));
                    ++checked;
                }
    }
    CHECK_EQ(checked, 24 * (8 + 4 + 2));
    // Inside the face: the face's own texel. A 1x1 level: the neighbour's one texel past every edge.
    CHECK(tf::cube_texel(cube, kMinusY, 1, 3, 2) == label(kMinusY, 1, 3, 2));
    CHECK(tf::cube_texel(cube, kPlusX, 3, -1, 0) == label(kPlusZ, 3, 0, 0));
    CHECK(tf::cube_texel(cube, kMinusZ, 3, 0, 1) == label(kMinusY, 3, 0, 0));
    // Farther out: the direction through the texel centre (N = 8, +X, i = -2, j = 0): it meets +Z at
    // s = (8/11 + 1)/2 -> column floor(6.91) = 6, t = (-7/8 / (11/8) + 1)/2 = 2/11 -> row floor(1.45) = 1.
    CHECK(tf::cube_texel(cube, kPlusX, 0, -2, 0) == label(kPlusZ, 0, 6, 1));
    // Bad face or level: a message naming it.
    CHECK_THROWS_WITH(tf::cube_texel(cube, 6, 0, 0, 0), "cube face 6 is not 0..5");
    CHECK_THROWS_WITH(tf::cube_texel(cube, 0, 4, 0, 0), "level 4 is not 0..3");
}

TEST_CASE("corner-rule")
{
    // The four diagonal neighbours past each face's corners: the mean of the face's corner texel and the
    // two edge neighbours (the table above), the corner rule of docs/ENVIRONMENT.md.
    const tf::CubeMap cube = labelled_cube(8);
    for (int level : {0, 2}) {
        const int n = 8 >> level, m = n - 1;
        for (int f = 0; f < tf::cube_face_count; ++f)
            for (int corner = 0; corner < 4; ++corner) {
                const bool right = corner & 1, bottom = corner & 2;
                const int ic = right ? m : 0, jc = bottom ? m : 0;
                const FaceTexel across_i = past_edge(f, right ? 1 : 0, jc, n);  // (i past, jc)
                const FaceTexel across_j = past_edge(f, bottom ? 3 : 2, ic, n); // (ic, j past)
                const dvec4 want = (label(f, level, ic, jc) + label(across_i.face, level, across_i.i, across_i.j) +
                                    label(across_j.face, level, across_j.i, across_j.j)) /
                                   3.0;
                const dvec4 got = tf::cube_texel(cube, f, level, right ? n : -1, bottom ? n : -1);
                CHECK_NEAR(got, want, 1e-15);
            }
    }
}

TEST_CASE("constant-cube")
{
    // Every level of every face the constant c: every filter returns c. Each result is a weighted mean
    // of c with weights summing to 1 (ewa's fit is clamped to the texels' range), so it is c up to the
    // rounding of at most 2 x 95^2 double products and sums: 2 * 95^2 * 2^-53 < 2.1e-12 relative.
    const dvec4 c(glm::vec4(0.3f, 0.6f, -0.2f, 1.0f)); // exact in the float texels
    const tf::CubeMap cube = make_cube(16, [&](int, int, int, int, int) { return c; });
    for (const Config& config : environment_filters()) {
        INFO(std::string(config.name));
        tf::test::limit_failure_lines(5);
        for (const tf::EnvLookup& l : random_env_lookups(300, 11))
            CHECK_NEAR(tf::reference_cube_sample(cube, config.options, l), c, 2.1e-12);
    }
    for (const tf::EnvLookup& l : random_env_lookups(100, 12))
        CHECK_NEAR(tf::reference_cube_bilinear0(cube, l.dir), c, 2.1e-12);
}

TEST_CASE("constant-latlong")
{
    // The same for a 32x16 lat-long map (and a 15x8 one: odd width), near the poles and the seam too.
    const dvec4 c(glm::vec4(0.3f, 0.6f, -0.2f, 1.0f)); // exact in the float texels
    for (int w : {32, 15}) {
        tf::MipChain chain = tf::build_mip_chain(tf::make_image(w, w == 32 ? 16 : 8));
        for (tf::Image& level : chain.levels)
            std::fill(level.texels.begin(), level.texels.end(), glm::vec4(c));
        for (const Config& config : environment_filters()) {
            INFO(std::string(config.name));
            tf::test::limit_failure_lines(5);
            for (const tf::EnvLookup& l : random_env_lookups(300, 21))
                CHECK_NEAR(tf::reference_latlong_sample(chain, config.options, l), c, 2.1e-12);
        }
        for (const tf::EnvLookup& l : random_env_lookups(100, 22))
            CHECK_NEAR(tf::reference_latlong_bilinear0(chain, l.dir), c, 2.1e-12);
    }
}

TEST_CASE("degenerate-and-unsupported")
{
    const tf::CubeMap cube = labelled_cube(4);
    const tf::MipChain latlong = tf::build_mip_chain(tf::make_image(8, 4));
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    for (const Config& config : environment_filters())
        for (const dvec3& d : {dvec3(0.0), dvec3(-0.0, 0.0, -0.0), dvec3(nan, 1, 0), dvec3(inf, 0, 0)}) {
            const tf::EnvLookup l{d, dvec3(0.1), dvec3(0.1)};
            CHECK(tf::reference_cube_sample(cube, config.options, l) == dvec4(0.0), config.name);
            CHECK(tf::reference_latlong_sample(latlong, config.options, l) == dvec4(0.0), config.name);
            CHECK(tf::reference_cube_bilinear0(cube, d) == dvec4(0.0));
            CHECK(tf::reference_latlong_bilinear0(latlong, d) == dvec4(0.0));
        }
    // Non-finite derivatives: the 2D rule, the coarsest level; ewa reads a 1x1 level's one texel.
    tf::SamplerOptions ewa, trilinear, coarsest;
    ewa.filter = Filter::ewa;
    coarsest.lod_min = 1000;
    const tf::EnvLookup nan_footprint{dvec3(1, 0.1, 0.2), dvec3(nan), dvec3(0.0)};
    CHECK(tf::reference_cube_sample(cube, ewa, nan_footprint) == label(kPlusX, 2, 0, 0));
    CHECK(tf::reference_cube_sample(cube, trilinear, nan_footprint) ==
          tf::reference_cube_sample(cube, coarsest, {nan_footprint.dir, {}, {}}));
    for (Filter f : {Filter::brilinear, Filter::sat, Filter::sat_assembly, Filter::hw_aniso, Filter::ground_truth}) {
        tf::SamplerOptions o;
        o.filter = f;
        const std::string want = f == Filter::hw_aniso       ? "hw-aniso has no CPU reference"
                                 : f == Filter::ground_truth ? "ground-truth integrates over a pixel"
                                                             : "--filter " + tf::to_string(f) + " has no environment-map form";
        CHECK_THROWS_WITH(tf::reference_cube_sample(cube, o, tf::EnvLookup{}), want);
        CHECK_THROWS_WITH(tf::reference_latlong_sample(latlong, o, tf::EnvLookup{}), want);
    }
}

namespace {

// A texel source that is the cube's rule except on +X's left edge (i = -1), where it reads a wrong texel:
// the edge mirrored along its length, or the right place on the wrong face (-Z). The seam check must
// catch both.
struct Sabotage {
    const tf::CubeMap* cube;
    int mode; // 1 mirrored along the edge, 2 wrong face
};
dvec4 sabotaged_read(const void* map, int level, long long i, long long j) {
    const auto& s = *static_cast<const Sabotage*>(map);
    const int n = s.cube->faces[0].levels[size_t(level)].width;
    if (i == -1 && j >= 0 && j < n)
        return s.mode == 1 ? tf::cube_texel(*s.cube, kPlusZ, level, n - 1, n - 1 - j)
                           : tf::cube_texel(*s.cube, kMinusZ, level, 0, j);
    return tf::cube_texel(*s.cube, kPlusX, level, i, j);
}

// The largest excess, over a path of 401 directions from a to b, of the change of the filtered value
// between neighbouring directions over the change of the smooth function itself (per channel).
// Derivatives fixed in direction space: g along the path, g/4 across it.
double path_excess(const tf::CubeMap& cube, const tf::SamplerOptions& options, dvec3 a, dvec3 b, double g,
                   int sabotage) {
    double worst = 0;
    dvec4 previous_out(0.0), previous_f(0.0);
    for (int k = 0; k <= 400; ++k) {
        const dvec3 d = glm::normalize(glm::mix(a, b, k / 400.0));
        const dvec3 along = glm::normalize((b - a) - glm::dot(b - a, d) * d);
        const tf::EnvLookup l{d, g * along, 0.25 * g * glm::cross(d, along)};
        dvec4 out;
        int face = 0;
        const tf::Lookup uv = tf::cube_face_lookup(l, face);
        if (sabotage != 0 && face == kPlusX) {
            const Sabotage map{&cube, sabotage};
            tf::SamplerOptions face_options = options;
            face_options.wrap = tf::Wrap::clamp;
            out = tf::reference_sample_texels(cube.faces[kPlusX], face_options, uv, {sabotaged_read, &map});
        } else {
            out = tf::reference_cube_sample(cube, options, l);
        }
        const dvec4 f = smooth_value(d);
        if (k > 0)
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::abs(out[c] - previous_out[c]) - std::abs(f[c] - previous_f[c]));
        previous_out = out, previous_f = f;
    }
    return worst;
}

} // namespace

TEST_CASE("seamless")
{
    // A 32-texel cube whose texels are f(d) = (d/|d| + 1)/2 at their centre directions. Paths: across the
    // +X/+Z edge a quarter of the way along it, past the +X/+Y/+Z corner, across the -Y/-Z edge. Level 0
    // (lod_max 0), footprint g = 0.03 along the path (about 1.2 texels on the face plane), g/4 across.
    //
    // Bound. Every family here returns sum_k w_k f(c_k), weights summing to 1, whose positions p_k on
    // the face plane average to the lookup's p (bilinear, probes symmetric about p, ewa's taps shifted
    // to centre and its fit exact on linear data); c_k = p_k except off the face, where the rule reads
    // the neighbour texel containing p_k's direction, at most half a texel from it (h/2, h = 2/N in plane
    // units, which bound angles). With f's per-channel slope <= 1/2 per radian and second derivative
    // <= 2 along the plane (|d^2(p/|p|)/dq^2| <= 4/|p|^2, |p| >= 1), |out - f(p)| <= h/4 + r^2, r^2 the
    // largest squared distance of a weighted texel: ewa's support R^2 (a^2 + 1) h^2, R^2 = 2, a the major
    // semi-axis in texels <= 2.45 g / h (the projection stretches derivatives by at most sqrt(2) sqrt(3)).
    // Two directions: |change| <= |f's change| + h/2 + 2 r^2 = 0.0685 for N = 32, g = 0.03.
    // Measured: <= 1e-3 for the right rule; the sabotaged reads step by >= 0.147 (mirrored) and >= 0.31
    // (wrong face): a wrong-face or wrong-orientation read is far above the bound.
    const int n = 32;
    const double g = 0.03, h = 2.0 / n, a = 2.45 * g / h;
    const double bound = h / 2 + 2 * (2 * (a * a + 1) * h * h);
    const tf::CubeMap cube = smooth_cube(n);
    struct Path {
        dvec3 a, b;
    };
    const Path paths[] = {{{1, 0.4, 0.8}, {0.8, 0.45, 1}}, {{1, 0.8, 0.9}, {0.9, 1.2, 1.1}}, {{0.3, -1, -0.8}, {0.35, -0.8, -1}}};
    std::vector<Config> configs;
    for (const Config& c : environment_filters())
        if (c.options.filter == Filter::trilinear || c.options.filter == Filter::aniso || c.options.filter == Filter::ewa ||
            c.options.filter == Filter::bspline || c.options.filter == Filter::catmull_rom)
            configs.push_back(c);
    for (Config& config : configs) {
        config.options.lod_max = 0;
        double worst = 0;
        for (const Path& p : paths) worst = std::max(worst, path_excess(cube, config.options, p.a, p.b, g, 0));
        CHECK(worst <= bound, std::string(config.name) + ": excess " + tf::test::show(worst) + " > " + tf::test::show(bound));
        // The check can fail: the same path with a wrong read on +X's edge to +Z steps far above the bound.
        for (int sabotage : {1, 2}) {
            const double wrong = path_excess(cube, config.options, paths[0].a, paths[0].b, g, sabotage);
                CHECK(wrong > bound, std::string(config.name) + " sabotage " + std::to_string(sabotage) + ": excess " +
                                     tf::test::show(wrong) + " not above " + tf::test::show(bound));
        }
    }
}

TEST_CASE("latlong-seam")
{
    // A lookup straddling u = 0/1 equals the same lookup turned about +y by k whole texels (u + k/W) on
    // the texture turned by k columns (T'(i) = T(i - k)). Both sides differ only by the rounding of the
    // turned direction and of atan2 (a few 2^-53 in u: 1e-14 texel), so every filter agrees within 1e-11
    // of texel values of size <= 1 (weights move by at most that per unit of contrast, per level).
    const int w = 32, h = 16, shift = 16; // whole texels on every level but the 1x1 one
    tf::Image base = tf::make_image(w, h), turned = tf::make_image(w, h);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> value(0.0, 1.0);
    for (auto& t : base.texels) t = glm::vec4(float(value(rng)), float(value(rng)), float(value(rng)), 1.0f);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) turned.texels[size_t(j * w + (i + shift) % w)] = base.texels[size_t(j * w + i)];
    const tf::MipChain chain = tf::build_mip_chain(std::move(base)), chain_turned = tf::build_mip_chain(std::move(turned));
    // Turning by phi about +y: atan2(x, -z) grows by phi (x' = x cos - z sin, z' = z cos + x sin).
    const double phi = 2 * std::numbers::pi * shift / w;
    const auto turn = [&](const dvec3& v) {
        return dvec3(v.x * std::cos(phi) - v.z * std::sin(phi), v.y, v.z * std::cos(phi) + v.x * std::sin(phi));
    };
    std::uniform_real_distribution<double> unit(-1.0, 1.0), near_seam(-0.05, 0.05), octave(-8.0, -1.0);
    for (const Config& config : environment_filters()) {
        INFO(std::string(config.name));
        tf::test::limit_failure_lines(5);
        for (int k = 0; k < 40; ++k) {
            // Near +z (u = 0/1): x small, z > 0, within a quarter texel of the seam.
            const dvec3 d(near_seam(rng), 0.8 * unit(rng), 1.0);
            const tf::EnvLookup l{d, std::exp2(octave(rng)) * dvec3(unit(rng), unit(rng), unit(rng)),
                                  std::exp2(octave(rng)) * dvec3(unit(rng), unit(rng), unit(rng))};
            const tf::EnvLookup lt{turn(l.dir), turn(l.ddx), turn(l.ddy)};
            const tf::Lookup uv = tf::latlong_lookup(l), uvt = tf::latlong_lookup(lt);
            CHECK(uv.u < 0.05 || uv.u > 0.95, "u " + tf::test::show(uv.u)); // on the seam
            CHECK_NEAR(uvt.u, uv.u + double(shift) / w - (uv.u > 0.5 ? 1.0 : 0.0), 1e-14);
            CHECK_NEAR(tf::reference_latlong_sample(chain, config.options, l),
                       tf::reference_latlong_sample(chain_turned, config.options, lt), 1e-11);
        }
    }
}

TEST_CASE("latlong-poles")
{
    // latlong_texel by hand on an 8x4 level: past the +y pole (j < 0) row -1 - j, column + 4; past the
    // -y pole (j >= 4) row 7 - j, column + 4; columns mod 8; rows repeat every 8.
    tf::Image image = tf::make_image(8, 4);
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 8; ++i) image.texels[size_t(j * 8 + i)] = glm::vec4(float(i), float(j), 0.0f, 1.0f);
    const tf::MipChain chain = tf::build_mip_chain(std::move(image));
    struct Known {
        long long i, j;
        int column, row;
    };
    const Known known[] = {{2, 1, 2, 1},   {-1, 0, 7, 0},  {9, 3, 1, 3},  {2, -1, 6, 0}, {7, -2, 3, 1},
                           {0, -4, 4, 3},  {5, 4, 1, 3},   {5, 5, 1, 2},  {3, 7, 7, 0},  {3, 8, 3, 0},
                           {3, -5, 3, 3},  {-13, -1, 7, 0}};
    for (const Known& k : known)
        CHECK(tf::latlong_texel(chain, 0, k.i, k.j) == dvec4(k.column, k.row, 0, 1),
              "(" + std::to_string(k.i) + ", " + std::to_string(k.j) + ") read " +
                  tf::test::show(tf::latlong_texel(chain, 0, k.i, k.j)));
    CHECK_THROWS_WITH(tf::latlong_texel(chain, 4, 0, 0), "level 4 is not 0..3");

    // A bilinear footprint over the +y pole: u at column 1's centre (u = 1.5/8), v = 1/16 so that
    // y = v*4 - 1/2 = -1/4: rows -1 and 0 weigh 1/4 and 3/4; row -1 is row 0 of column 1 + 4 = 5.
    // Expected by hand: (1/4)(5, 0) + (3/4)(1, 0) = (2, 0). Near the -y pole (v = 1 - 1/16): rows 3 and
    // 4 (= row 3 of column 5) weigh 3/4, 1/4: the same (2, 3).
    const auto direction = [](double u, double v) {
        const double theta = 2 * std::numbers::pi * (u - 0.5), polar = std::numbers::pi * v;
        return dvec3(std::sin(polar) * std::sin(theta), std::cos(polar), -std::sin(polar) * std::cos(theta));
    };
    CHECK_NEAR(tf::reference_latlong_bilinear0(chain, direction(1.5 / 8, 1.0 / 16)), dvec4(2, 0, 0, 1), 1e-12);
    CHECK_NEAR(tf::reference_latlong_bilinear0(chain, direction(1.5 / 8, 1 - 1.0 / 16)), dvec4(2, 3, 0, 1), 1e-12);
    // The full filter reads the same there: bilinear, and trilinear with a footprint that stays on level 0.
    tf::SamplerOptions bilinear;
    bilinear.filter = Filter::bilinear;
    CHECK_NEAR(tf::reference_latlong_sample(chain, bilinear, {direction(1.5 / 8, 1.0 / 16), {}, {}}), dvec4(2, 0, 0, 1),
               1e-12);
}

TEST_SUITE_END();
