// The environment scenes' data (CPU only): cube textures (host/core/cube_textures.h) and the skybox and
// reflect scenes' ray casts (host/reference/env_cast.h). The cross layout unfolds the cube with no flips
// (every seam checked against Vulkan's face selection), the labelled cube tells every face and orientation
// apart, quad differences agree with the ray derivatives to first order, the mirror reflects, and the
// skybox looks across edges into a corner.
#include "support.h"
#include "core/cube_textures.h"
#include "core/procedural.h"
#include "reference/env_cast.h"
#include "scene/scene.h"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <set>
#include <tuple>
#include <vector>

using namespace tf;

namespace {

// A cross whose every texel has its own colour (its position), the gaps black.
Image numbered_cross(int size)
{
    Image cross = make_image(4 * size, 3 * size, glm::vec4(0.0f));
    for (int f = 0; f < cube_face_count; ++f) {
        CrossCell cell = cross_cell(f);
        for (int j = 0; j < size; ++j)
            for (int i = 0; i < size; ++i) {
                int x = cell.column * size + i, y = cell.row * size + j;
                cross.at(x, y) = glm::vec4(float(x), float(y), float(f), 1.0f);
            }
    }
    return cross;
}

// Which face's cell holds cross texel (x, y), -1 for the gaps.
int face_at(int x, int y, int size)
{
    for (int f = 0; f < cube_face_count; ++f) {
        CrossCell cell = cross_cell(f);
        if (x / size == cell.column && y / size == cell.row)
            return f;
    }
    return -1;
}

// Texels of two images that differ.
int differing_texels(const Image& a, const Image& b)
{
    int count = 0;
    for (size_t k = 0; k < a.texels.size(); ++k)
        count += a.texels[k] != b.texels[k] ? 1 : 0;
    return count;
}

// A face turned or mirrored: texel (i, j) of the result is texel map(i, j) of the face.
template <typename Map>
Image remapped(const Image& face, Map map)
{
    Image out = face;
    for (int j = 0; j < face.height; ++j)
        for (int i = 0; i < face.width; ++i) {
            auto [si, sj] = map(i, j, face.width - 1);
            out.at(i, j) = face.at(si, sj);
        }
    return out;
}

// d(dir)/d(pixel) at point (px, py) along `step`, by central differences (the point's own side of the
// silhouette: used on smooth pixels only).
glm::dvec3 derivative_at(const SceneParams& scene, double px, double py, glm::dvec2 step)
{
    const double h = 1.0 / 1024;
    return (reference_env_direction(scene, px + h * step.x, py + h * step.y) -
            reference_env_direction(scene, px - h * step.x, py - h * step.y)) / (2.0 * h);
}

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values.empty() ? NAN : values[values.size() / 2];
}

// Pixels whose whole 4x4 neighbourhood (their quad and a pixel around it) is of one kind, mirror or sky:
// where the direction is smooth on the pixel scale.
std::vector<bool> smooth_pixels(const SceneParams& scene)
{
    int w = scene.kind_size.y, h = scene.kind_size.z;
    std::vector<bool> mirror(size_t(w) * h), smooth(size_t(w) * h, false);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            mirror[size_t(y) * w + x] = reference_env_ray(scene, x + 0.5, y + 0.5).mirror;
    for (int y = 2; y < h - 2; ++y)
        for (int x = 2; x < w - 2; ++x) {
            bool same = true;
            for (int dy = -1; dy <= 2; ++dy)
                for (int dx = -1; dx <= 2; ++dx)
                    same = same && mirror[size_t((y & ~1) + dy) * w + (x & ~1) + dx] == mirror[size_t(y) * w + x];
            smooth[size_t(y) * w + x] = same;
        }
    return smooth;
}

// |quad difference - ray derivative| / |ray derivative| at every smooth pixel (reflect: smooth mirror
// pixels; the sky is linear), both axes.
std::vector<double> relative_errors(const SceneParams& scene, Gradients gradients)
{
    std::vector<EnvLookup> quads = reference_env_lookups(scene, gradients);
    std::vector<EnvLookup> rays = reference_env_lookups(scene, Gradients::ray);
    std::vector<bool> smooth = smooth_pixels(scene);
    const bool reflect = scene.kind_size.x == HARNESS_SCENE_REFLECT;
    const int w = scene.kind_size.y;
    std::vector<double> errors;
    for (size_t k = 0; k < quads.size(); ++k)
        if (smooth[k] && (!reflect || reference_env_ray(scene, double(k % w) + 0.5, double(k / w) + 0.5).mirror)) {
            errors.push_back(glm::length(quads[k].ddx - rays[k].ddx) / glm::length(rays[k].ddx));
            errors.push_back(glm::length(quads[k].ddy - rays[k].ddy) / glm::length(rays[k].ddy));
        }
    return errors;
}

} // namespace

TEST_SUITE_BEGIN("reference");

// 1. The horizontal cross: faces copied as they are, and across every seam the cross shows (the three in
//    row 1, the wrap from -Z back to -X, +Y over +Z over -Y), the texel one past a face's edge on its
//    extended plane is, by Vulkan's face selection (cube_face_point), the cross's neighbouring texel:
//    the layout unfolds the cube with no flips. Bad sizes are refused, naming the file.
TEST_CASE("cross-seams")
{
    const int n = 8;
    Image cross = numbered_cross(n);
    CubeMap cube = cube_from_cross(cross, "numbered.exr");
    CHECK_EQ(cube.size(), n);
    for (int f = 0; f < cube_face_count; ++f) {
        CrossCell cell = cross_cell(f);
        CHECK_EQ(differing_texels(cube.faces[f].levels[0],
                                  [&] {
                                      Image face = make_image(n, n);
                                      for (int j = 0; j < n; ++j)
                                          for (int i = 0; i < n; ++i)
                                              face.at(i, j) = cross.at(cell.column * n + i, cell.row * n + j);
                                      return face;
                                  }()),
                 0);
        CHECK_EQ(int(cube.faces[f].levels.size()), mip_level_count(n, n));
    }
    int seams_checked = 0;
    std::set<std::pair<int, int>> face_pairs;
    for (int y = 0; y < 3 * n; ++y)
        for (int x = 0; x < 4 * n; ++x)
            for (auto [sx, sy] : {std::pair{1, 0}, std::pair{0, 1}}) {
                int a = face_at(x, y, n);
                int nx = (x + sx) % (4 * n), ny = y + sy; // row 1 wraps from -Z to -X
                if (a < 0 || ny >= 3 * n || (sx == 1 && x + 1 == 4 * n && y / n != 1))
                    continue;
                int b = face_at(nx, ny, n);
                if (b < 0 || b == a)
                    continue;
                // Both ways across the seam: from a's texel one step on, from b's one step back.
                for (int way = 0; way < 2; ++way) {
                    int from = way == 0 ? a : b, to = way == 0 ? b : a;
                    int fx = way == 0 ? x : nx, fy = way == 0 ? y : ny, tx = way == 0 ? nx : x, ty = way == 0 ? ny : y;
                    int step = way == 0 ? 1 : -1;
                    CrossCell cf = cross_cell(from), ct = cross_cell(to);
                    int i = fx - cf.column * n + step * sx, j = fy - cf.row * n + step * sy; // off the face
                    CubeFacePoint p = cube_face_point(cube_face_direction(from, (i + 0.5) / n, (j + 0.5) / n));
                    int pi = std::clamp(int(std::floor(p.s * n)), 0, n - 1);
                    int pj = std::clamp(int(std::floor(p.t * n)), 0, n - 1);
                    int ei = tx - ct.column * n, ej = ty - ct.row * n;
                    CHECK(p.face == to && pi == ei && pj == ej,
                          "from face " + std::to_string(from) + " texel (" + std::to_string(i) + ", " +
                              std::to_string(j) + "): face " + std::to_string(p.face) + " (" + std::to_string(pi) +
                              ", " + std::to_string(pj) + "), the cross shows face " + std::to_string(to) + " (" +
                              std::to_string(ei) + ", " + std::to_string(ej) + ")");
                    CHECK(cube.faces[p.face].levels[0].at(pi, pj) == cross.at(tx, ty));
                    ++seams_checked;
                }
                face_pairs.insert({std::min(a, b), std::max(a, b)});
            }
    std::printf("cross: %d texel steps across %zu seams\n", seams_checked, face_pairs.size());
    CHECK_EQ(face_pairs.size(), 6); // -X|+Z, +Z|+X, +X|-Z, -Z|-X, +Y|+Z, +Z|-Y
    CHECK_EQ(seams_checked, 6 * 2 * n);

    CHECK_THROWS_WITH(cube_from_cross(make_image(64, 50), "sky.png"),
                      "cube map sky.png: 64x50 is not a horizontal cross");
    CHECK_THROWS_WITH(cube_from_cross(make_image(30, 24), "odd.png"), "odd.png");   // 4:3 with 7.5-texel faces
    CHECK_THROWS_WITH(cube_from_cross(make_image(48, 48), "square.png"), "square.png");
    CHECK_THROWS_WITH(cube_from_cross(Image{}, "empty.png"), "empty.png");
}

// 2. cube-labels: every face differs from every other in most texels, and from its own rotations, flips
//    and transpose in at least the texels the bar leaves and covers (2 (n/16) (n - n/16) when it turns onto
//    a side, 2 (n/16) n when it moves to the bottom: the smaller is the bound); the face's index reads as
//    the count of squares at t = 0.75, and the bar and the dot are where the header says.
TEST_CASE("labels")
{
    const int n = 64;
    CubeMap cube = make_procedural_cube("cube-labels", n);
    for (int a = 0; a < cube_face_count; ++a)
        for (int b = a + 1; b < cube_face_count; ++b) {
            int diff = differing_texels(cube.faces[a].levels[0], cube.faces[b].levels[0]);
            CHECK(diff > n * n / 2, "faces " + std::to_string(a) + " and " + std::to_string(b) + " differ in " +
                                        std::to_string(diff) + " texels");
        }
    using Map = std::pair<int, int> (*)(int, int, int);
    const std::pair<const char*, Map> transforms[] = {
        {"rotated 90", [](int i, int j, int m) { return std::pair{j, m - i}; }},
        {"rotated 180", [](int i, int j, int m) { return std::pair{m - i, m - j}; }},
        {"rotated 270", [](int i, int j, int m) { return std::pair{m - j, i}; }},
        {"flipped in s", [](int i, int j, int m) { return std::pair{m - i, j}; }},
        {"flipped in t", [](int i, int j, int m) { return std::pair{i, m - j}; }},
        {"transposed", [](int i, int j, int) { return std::pair{j, i}; }},
    };
    int fewest = n * n;
    for (int f = 0; f < cube_face_count; ++f) {
        const Image& face = cube.faces[f].levels[0];
        for (auto [what, map] : transforms) {
            int diff = differing_texels(face, remapped(face, map));
            fewest = std::min(fewest, diff);
            CHECK(diff >= 2 * (n / 16) * (n - n / 16),
                  "face " + std::to_string(f) + " " + what + ": " + std::to_string(diff) + " texels differ");
        }
        int squares = 0;
        const int row = 3 * n / 4;
        for (int i = 1; i < n; ++i)
            squares += face.at(i, row) == glm::vec4(1.0f) && face.at(i - 1, row) != glm::vec4(1.0f) ? 1 : 0;
        CHECK_EQ(squares, f + 1);
        for (int i = 0; i < n; ++i)
            CHECK(face.at(i, 0) == glm::vec4(1.0f) && face.at(i, n / 16 - 1) == glm::vec4(1.0f));
        CHECK(face.at(n / 16, n / 2) != glm::vec4(1.0f));
        CHECK(face.at(n / 4, n / 4) == glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
        CHECK(face.at(3 * n / 4, n / 4) != glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    }
    std::printf("labels: a face and its own turns or flips differ in >= %d of %d texels\n", fewest, n * n);
}

// 3. cube-hash: every texel of the cube its own colour; cube-smooth: the direction through the texel's
//    centre; any 2D pattern: six tinted copies; bad names and sizes refused.
TEST_CASE("procedural-cubes")
{
    const int n = 32;
    CubeMap hash = make_procedural_cube("cube-hash", n);
    std::set<std::tuple<float, float, float>> colours;
    for (int f = 0; f < cube_face_count; ++f)
        for (const glm::vec4& t : hash.faces[f].levels[0].texels)
            colours.insert({t.r, t.g, t.b});
    CHECK_EQ(colours.size(), 6 * n * n);

    CubeMap smooth = make_procedural_cube("cube-smooth", n);
    double worst = 0;
    for (int f = 0; f < cube_face_count; ++f)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                glm::dvec3 d = glm::normalize(cube_face_direction(f, (i + 0.5) / n, (j + 0.5) / n));
                glm::dvec4 want(0.5 * (d + 1.0), 1.0);
                worst = std::max(worst, test::max_channel_diff(glm::dvec4(smooth.faces[f].levels[0].at(i, j)), want));
                // The texel's face is the one its direction selects: a face in the wrong slot would not be.
                CHECK_EQ(cube_face_point(d).face, f);
            }
    CHECK(worst <= 6e-8, "largest difference from 0.5 (d/|d| + 1): " + test::show(worst)); // float rounding

    for (std::string name : {"checker", "noise", "mipcolors"}) {
        MipChain pattern = make_procedural(name, n);
        CubeMap cube = make_procedural_cube(name, n);
        for (int f = 0; f < cube_face_count; ++f) {
            CHECK_EQ(cube.faces[f].levels.size(), pattern.levels.size());
            for (size_t l = 0; l < pattern.levels.size(); l += pattern.levels.size() - 1) { // level 0 and 1x1
                const Image& level = cube.faces[f].levels[l];
                glm::vec4 want = pattern.levels[l].texels[0] * cube_face_tint(f);
                CHECK(glm::all(glm::lessThanEqual(glm::abs(level.texels[0] - want), glm::vec4(2e-7f))),
                      name + " face " + std::to_string(f) + " level " + std::to_string(l));
            }
            for (int g = f + 1; g < cube_face_count; ++g)
                CHECK(cube_face_tint(f) != cube_face_tint(g));
        }
    }
    CHECK(is_procedural_cube("cube-labels") && is_procedural_cube("zoneplate") && !is_procedural_cube("cube"));
    CHECK_THROWS_WITH(make_procedural_cube("cube-lables", 16), "unknown procedural cube texture 'cube-lables'");
    CHECK_THROWS_WITH(make_procedural_cube("cube-lables", 16), "cube-labels, cube-hash, cube-smooth, checker");
    CHECK_THROWS_WITH(make_procedural_cube("cube-hash", 0), "face size 0 out of range [1, 16384]");
    CHECK_THROWS_WITH(make_procedural_cube("checker", 16385), "out of range");
}

// 4. The scene names, and the camera path turning the view by a fraction of a texel a frame.
TEST_CASE("scene-names-and-frames")
{
    CHECK(parse_scene("skybox") == SceneKind::skybox && parse_scene("reflect") == SceneKind::reflect);
    CHECK(to_string(SceneKind::skybox) == "skybox" && to_string(SceneKind::reflect) == "reflect");
    int environment = 0;
    for (SceneKind kind : all_scenes())
        environment += is_environment_scene(kind) ? 1 : 0;
    CHECK_EQ(environment, 2);
    CHECK(!is_environment_scene(SceneKind::plane) && !is_environment_scene(SceneKind::mesh));
    CHECK_THROWS_WITH(reference_env_lookups(make_scene(SceneKind::plane, 8, 8, 64), Gradients::fine),
                      "not an environment scene");

    const int face = 128;
    const double texel = 0.5 * 3.14159265358979323846 / face;
    for (SceneKind kind : {SceneKind::skybox, SceneKind::reflect}) {
        SceneParams scene = make_scene(kind, 64, 48, face);
        SceneParams same = scene_at_frame(scene, 0, face);
        CHECK(std::memcmp(&same, &scene, sizeof scene) == 0);
        SceneParams next = scene_at_frame(scene, 1, face);
        glm::dvec3 f0 = glm::normalize(glm::dvec3(scene.forward)), f1 = glm::normalize(glm::dvec3(next.forward));
        double turned = std::acos(std::min(1.0, glm::dot(f0, f1)));
        std::printf("%s: frame 1 turns the view %.3f texels\n", to_string(kind).c_str(), turned / texel);
        CHECK(turned > 0.1 * texel && turned < texel, "turned " + test::show(turned / texel) + " texels");
        if (kind == SceneKind::reflect) { // orbits the sphere: its distance and place in view kept
            glm::dvec3 c(scene.p0);
            CHECK_NEAR(glm::length(glm::dvec3(next.origin) - c), glm::length(glm::dvec3(scene.origin) - c), 1e-6);
            CHECK_NEAR(glm::dot(glm::normalize(c - glm::dvec3(next.origin)), f1), 1.0, 1e-9);
        } else {
            CHECK(glm::dvec3(next.origin) == glm::dvec3(0.0));
        }
    }
}

// 5. The skybox: its pixels' directions select at least three faces, the cube's corner (1, 1, 1) is in view,
//    and its directions are linear in the pixel position, so fine and coarse quad differences are its
//    exact derivatives (to double rounding).
TEST_CASE("skybox-view")
{
    SceneParams scene = make_scene(SceneKind::skybox, 64, 48, 64);
    std::vector<EnvLookup> fine = reference_env_lookups(scene, Gradients::fine);
    std::vector<EnvLookup> coarse = reference_env_lookups(scene, Gradients::coarse);
    std::vector<EnvLookup> ray = reference_env_lookups(scene, Gradients::ray);
    int faces[cube_face_count] = {};
    double worst = 0;
    for (size_t k = 0; k < fine.size(); ++k) {
        ++faces[cube_face_point(fine[k].dir).face];
        for (const EnvLookup* q : {&fine[k], &coarse[k]})
            worst = std::max({worst, glm::length(q->ddx - ray[k].ddx) / glm::length(ray[k].ddx),
                              glm::length(q->ddy - ray[k].ddy) / glm::length(ray[k].ddy)});
        CHECK(!reference_env_ray(scene, 0.5 + double(k % 64), 0.5 + double(k / 64)).mirror);
    }
    int seen = 0;
    for (int f = 0; f < cube_face_count; ++f)
        seen += faces[f] > 0 ? 1 : 0;
    std::printf("skybox: pixels a face %d %d %d %d %d %d; quad vs ray derivative, relative: %.3g\n", faces[0],
                faces[1], faces[2], faces[3], faces[4], faces[5], worst);
    CHECK(seen >= 3 && faces[0] > 0 && faces[2] > 0 && faces[4] > 0);
    CHECK(worst < 1e-9, test::show(worst)); // linear: central differences exact up to rounding
    // The corner in view: (1, 1, 1) = forward + a right + b up with |a|, |b| < 1 after scaling to the
    // camera's image plane.
    glm::dvec3 f(scene.forward), r(scene.right), u(scene.up), corner(1.0);
    glm::dvec3 p = corner / glm::dot(corner, f); // on the plane forward . x = 1 (forward is unit)
    double a = glm::dot(p - f, r) / glm::dot(r, r), b = glm::dot(p - f, u) / glm::dot(u, u);
    CHECK(std::abs(a) < 0.9 && std::abs(b) < 0.9, "corner at ndc (" + test::show(a) + ", " + test::show(b) + ")");
}

// 6. reflect: a mirror pixel's ray meets the sphere (its point on the surface, the ray arriving from
//    outside), and its lookup direction is the reflection: angle in = angle out, in the plane of the ray
//    and the normal, unit length; a pixel that misses looks up its own ray. The sphere fills a good part
//    of the image with sky around it.
TEST_CASE("reflect-mirror")
{
    SceneParams scene = make_scene(SceneKind::reflect, 64, 64, 64);
    glm::dvec3 centre(scene.p0);
    double radius = scene.p0.w;
    int mirrors = 0, border_mirrors = 0;
    double worst_angle = 0, worst_plane = 0, worst_surface = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            EnvRay ray = reference_env_ray(scene, x + 0.5, y + 0.5);
            if (!ray.mirror) {
                CHECK(ray.dir == ray.ray);
                continue;
            }
            ++mirrors;
            border_mirrors += x == 0 || y == 0 || x == 63 || y == 63 ? 1 : 0;
            glm::dvec3 in = glm::normalize(ray.ray), out = ray.dir, n = ray.normal;
            worst_surface = std::max(worst_surface, std::abs(glm::length(ray.point - centre) - radius));
            CHECK(glm::dot(in, n) < 0.0);
            worst_angle = std::max({worst_angle, std::abs(glm::dot(out, n) + glm::dot(in, n)),
                                    std::abs(glm::length(out) - 1.0)});
            worst_plane = std::max(worst_plane, std::abs(glm::dot(glm::cross(in, n), out)));
            // The point is on the camera's ray.
            glm::dvec3 to_point = glm::normalize(ray.point - glm::dvec3(scene.origin));
            CHECK_NEAR(glm::dot(to_point, in), 1.0, 1e-12);
        }
    std::printf("reflect: %d of 4096 pixels mirror; |cos in - cos out| <= %.3g, off-plane <= %.3g, off-surface "
                "<= %.3g\n",
                mirrors, worst_angle, worst_plane, worst_surface);
    CHECK(mirrors > 4096 / 5 && mirrors < 4096 * 3 / 5);
    CHECK_EQ(border_mirrors, 0);
    CHECK(worst_angle < 1e-12 && worst_plane < 1e-12 && worst_surface < 1e-12);
}

// 7. Quad differences vs the exact derivative (ray) on both scenes, to first order: on the skybox they are
//    equal (the direction is linear); on reflect their difference is the derivative's change across the
//    quad, O(one pixel): the same view at 4x the resolution shrinks it about 4x (the relative error of a
//    first-order difference scales with the step).
TEST_CASE("quad-vs-ray")
{
    for (Gradients g : {Gradients::fine, Gradients::coarse}) {
        double skybox = 0;
        for (double e : relative_errors(make_scene(SceneKind::skybox, 64, 64, 64), g))
            skybox = std::max(skybox, e);
        std::vector<double> low = relative_errors(make_scene(SceneKind::reflect, 64, 64, 64), g);
        std::vector<double> high = relative_errors(make_scene(SceneKind::reflect, 256, 256, 64), g);
        double m_low = median(low), m_high = median(high);
        double max_low = *std::max_element(low.begin(), low.end());
        double max_high = *std::max_element(high.begin(), high.end());
        std::printf("%s: skybox max %.3g; reflect median %.4f (64^2) %.4f (256^2), ratio %.2f; max %.3f %.3f\n",
                    to_string(g).c_str(), skybox, m_low, m_high, m_low / m_high, max_low, max_high);
        CHECK(skybox < 1e-9, test::show(skybox));
        CHECK(m_low / m_high > 3.0 && m_low / m_high < 5.0, "ratio " + test::show(m_low / m_high));

        // A quad difference is the derivative at the midpoint of its two pixel centres up to second order:
        // the error left there is a small fraction of the first-order error at the pixel's own centre.
        SceneParams scene = make_scene(SceneKind::reflect, 64, 64, 64);
        std::vector<EnvLookup> quads = reference_env_lookups(scene, g);
        std::vector<bool> smooth = smooth_pixels(scene);
        std::vector<double> ratios;
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) {
                size_t k = size_t(y) * 64 + x;
                if (!smooth[k] || !reference_env_ray(scene, x + 0.5, y + 0.5).mirror)
                    continue;
                int x0 = x & ~1, y0 = y & ~1;
                int ax = g == Gradients::coarse ? y0 : y, ay = g == Gradients::coarse ? x0 : x;
                glm::dvec3 own_x = derivative_at(scene, x + 0.5, y + 0.5, {1.0, 0.0});
                glm::dvec3 mid_x = derivative_at(scene, x0 + 1.0, ax + 0.5, {1.0, 0.0});
                glm::dvec3 own_y = derivative_at(scene, x + 0.5, y + 0.5, {0.0, 1.0});
                glm::dvec3 mid_y = derivative_at(scene, ay + 0.5, y0 + 1.0, {0.0, 1.0});
                ratios.push_back(glm::length(quads[k].ddx - mid_x) / glm::length(quads[k].ddx - own_x));
                ratios.push_back(glm::length(quads[k].ddy - mid_y) / glm::length(quads[k].ddy - own_y));
            }
        std::printf("%s: reflect, |quad - d'(midpoint)| / |quad - d'(centre)| median %.4f over %zu\n",
                    to_string(g).c_str(), median(ratios), ratios.size());
        CHECK(median(ratios) < 0.1, test::show(median(ratios)));
    }
}

TEST_SUITE_END();
