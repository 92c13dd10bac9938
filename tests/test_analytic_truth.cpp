// The analytic ground truth (--truth analytic): the procedural textures' continuous definitions
// (core/analytic_texture.h) against the texels procedural.cpp writes, their wrap modes, the names refused,
// the truth they give (sharp checker edges where the texels' truth is blurred), and the GPU's twin
// (shaders/harness/analytic_texture.glsl) against the CPU reference on one small render. 64x64 images,
// 16 samples a pixel; every expected value comes from the definitions written out in the comments.
#include "support.h"
#include "core/analytic_texture.h"
#include "core/filter.h"
#include "core/procedural.h"
#include "reference/ground_truth.h"
#include "scene/scene.h"
#include "vulkan/backend.h"
#include "vulkan/render.h"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

using namespace tf;

namespace {

const double unit_roundoff = 0x1p-24; // float32

double rgba_diff(const glm::dvec4& a, const glm::dvec4& b) { return test::max_channel_diff(a, b); }

// The texel centre (x + 1/2, y + 1/2) / size in uv.
glm::dvec2 centre(int x, int y, int size) { return {(x + 0.5) / size, (y + 0.5) / size}; }

// The largest difference over every texel centre between the definition and procedural.cpp's level 0.
double worst_at_centres(const std::string& name, int size)
{
    const Image level0 = make_procedural(name, size).levels[0];
    const AnalyticTexture texture = analytic_texture(name, size);
    double worst = 0.0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            worst = std::max(worst, rgba_diff(analytic_value(texture, centre(x, y, size), Wrap::repeat),
                                              glm::dvec4(level0.at(x, y))));
    return worst;
}

SamplerOptions truth_options(Truth truth, AnalyticKind kind, Wrap wrap = Wrap::repeat)
{
    SamplerOptions options;
    options.filter = Filter::ground_truth;
    options.truth_side = 4; // 16 samples a pixel
    options.truth = truth;
    options.analytic = kind;
    options.wrap = wrap;
    return options;
}

// A box-pixel truth over a two-valued function with n samples a pixel is (k a + (n - k) b) / n for a
// whole k: returns k for `value` (channel c), and in `off` how far value is from that mean.
int sample_count(double value, double a, double b, int n, double& off)
{
    const int k = int(std::lround((value - b) / (a - b) * n));
    off = std::fabs(value - (k * a + (n - k) * b) / n);
    return k;
}

} // namespace

TEST_SUITE_BEGIN("reference");

// 1. At every texel centre the definitions give the texel: checker and grid exactly (the same float
//    levels, and a centre is half a texel from every cell and line edge), zoneplate within the rounding of
//    its texel to float (u = 2^-24 relative, values <= 1) plus the double's own phase error (~1e-13).
//    Sizes: multiples of 8 (checker) and 16 (grid), the grid's 2-texel lines from 512 on; any size for the
//    zoneplate. Off those multiples the checker's cells fall inside texels, and the check sees it.
TEST_CASE("texel-centres")
{
    for (int size : {8, 64, 256}) {
        const double worst = worst_at_centres("checker", size);
        std::printf("  checker %d: worst |definition - texel| %.3g\n", size, worst);
        CHECK(worst == 0.0, "checker " + std::to_string(size) + ": " + test::show(worst));
    }
    for (int size : {16, 64, 512}) {
        const double worst = worst_at_centres("grid", size);
        std::printf("  grid %d: worst |definition - texel| %.3g\n", size, worst);
        CHECK(worst == 0.0, "grid " + std::to_string(size) + ": " + test::show(worst));
    }
    for (int size : {17, 64, 256}) {
        const double worst = worst_at_centres("zoneplate", size), bound = unit_roundoff + 1e-12;
        std::printf("  zoneplate %d: worst |definition - texel| %.3g (bound %.3g)\n", size, worst, bound);
        CHECK(worst <= bound, "zoneplate " + std::to_string(size) + ": " + test::show(worst));
    }
    // The premise matters: a 12-texel checker's cells are 1.5 texels, so some texel's centre lies in the
    // next cell from the texel's own first corner (texel 1: floor(8/12) = 0 but floor(8 * 1.5 / 12) = 1).
    CHECK(worst_at_centres("checker", 12) > 0.8, "a 12-texel checker disagrees somewhere");
}

// 2. The wrap modes act on uv first: repeat has period 1, mirror reflects about every integer, clamp
//    holds the edge value outside [0,1] (u = 1 itself in the last cell, as clamp-to-edge holds the last
//    texel). Points off the cell edges by at least 1e-3, so that nothing depends on rounding there.
TEST_CASE("wrap-modes")
{
    const AnalyticTexture checker = analytic_texture("checker", 64), grid = analytic_texture("grid", 64);
    const AnalyticTexture zoneplate = analytic_texture("zoneplate", 64);
    const glm::dvec2 points[] = {{0.0123, 0.3456}, {0.4321, 0.9876}, {0.7777, 0.0613}, {0.999, 0.5011}};
    double repeat = 0.0, mirror = 0.0, clamp = 0.0;
    for (const AnalyticTexture* t : {&checker, &grid, &zoneplate})
        for (const glm::dvec2 p : points) {
            const glm::dvec4 here = analytic_value(*t, p, Wrap::repeat);
            for (const glm::dvec2 shift : {glm::dvec2(1, 0), glm::dvec2(-3, 2), glm::dvec2(5, -7)})
                repeat = std::max(repeat, rgba_diff(analytic_value(*t, p + shift, Wrap::repeat), here));
            // Mirror: u in [1, 2) reads 2 - u, u in [-1, 0) reads -u, and the period is 2.
            mirror = std::max(mirror, rgba_diff(analytic_value(*t, {2.0 - p.x, p.y}, Wrap::mirror), here));
            mirror = std::max(mirror, rgba_diff(analytic_value(*t, {-p.x, -p.y}, Wrap::mirror), here));
            mirror = std::max(mirror, rgba_diff(analytic_value(*t, {p.x + 4.0, 2.0 - p.y}, Wrap::mirror), here));
            clamp = std::max(clamp, rgba_diff(analytic_value(*t, p, Wrap::clamp), here));
        }
    CHECK(repeat < 1e-9, "repeat: " + test::show(repeat)); // u + k - floor rounds (~1e-16; zoneplate's slope)
    CHECK(mirror < 1e-9, "mirror: " + test::show(mirror));
    CHECK(clamp == 0.0, "clamp inside the square: " + test::show(clamp));
    // Clamp outside: the nearest point of the square. u = 1 and beyond read the last cell (checker cell 7,
    // odd with v's cell 0: dark), u < 0 the first (cell 0: light).
    const double dark = double(0.05f), light = double(0.9f);
    CHECK_EQ(analytic_value(checker, {1.0, 0.01}, Wrap::clamp).x, dark);
    CHECK_EQ(analytic_value(checker, {3.5, 0.01}, Wrap::clamp).x, dark);
    CHECK_EQ(analytic_value(checker, {-2.0, 0.01}, Wrap::clamp).x, light);
    CHECK_EQ(analytic_value(checker, {1.0, 0.01}, Wrap::mirror).x, dark); // u = 1 reflects onto itself
    CHECK_EQ(analytic_value(checker, {1.0, 0.01}, Wrap::repeat).x, light); // u = 1 is u = 0
    // And mirror is not repeat: u = 1.01 mirrors to 0.99 (cell 7, dark) but repeats to 0.01 (light).
    CHECK_EQ(analytic_value(checker, {1.01, 0.01}, Wrap::mirror).x, dark);
    CHECK_EQ(analytic_value(checker, {1.01, 0.01}, Wrap::repeat).x, light);
}

// 3. Names: only checker, zoneplate and grid have a definition; the others are refused with the texture
//    named, and --truth takes texels or analytic only.
TEST_CASE("names")
{
    CHECK(analytic_texture("checker", 256).kind == AnalyticKind::checker);
    CHECK(analytic_texture("zoneplate", 100).kind == AnalyticKind::zoneplate);
    CHECK(analytic_texture("grid", 512).size == 512);
    for (const char* name : {"noise", "mipcolors", "dynamic", "photo.png"})
        CHECK_THROWS_WITH(analytic_texture(name, 64), std::string("texture '") + name + "' has no analytic definition "
                                                      "(--truth analytic needs checker, zoneplate or grid)");
    CHECK_THROWS_WITH(analytic_texture("checker", 0), "size 0");
    CHECK(parse_truth("texels") == Truth::texels && parse_truth("analytic") == Truth::analytic);
    CHECK_THROWS_WITH(parse_truth("bogus"), "unknown truth 'bogus' (expected one of: texels, analytic)");
    SamplerOptions options = truth_options(Truth::analytic, AnalyticKind::none);
    resolve_analytic_truth(options, "grid");
    CHECK(options.analytic == AnalyticKind::grid);
    CHECK_THROWS_WITH(resolve_analytic_truth(options, "noise"), "texture 'noise'");
    // Unresolved (a caller that set Truth::analytic but no kind): refused, never the texels' truth.
    const MipChain chain = make_procedural("checker", 8);
    CHECK_THROWS_WITH(reference_ground_truth(make_scene(SceneKind::zoom, 8, 8, 8), chain,
                                             truth_options(Truth::analytic, AnalyticKind::none)),
                      "without an analytic texture");
}

// 4. Zoom on an 8-texel checker (8 pixels a texel, one texel a cell): the analytic truth has sharp edges.
//    Box pixels of 16 samples over a two-valued function are (k 0.9 + (16 - k) 0.05) / 16 for a whole k,
//    exactly (16 equal doubles sum and divide exactly), and a pixel inside one cell is 0.9 or 0.05: the
//    edges run 2.4 px into a cell (the scene's 0.3-texel offset), so 7 of every 8 pixels per axis, ~77 %.
//    The texels' truth reconstructs bilinearly between alternating texels: a ramp across every texel, so
//    (almost) no pixel keeps a checker value and most are no such mean.
TEST_CASE("sharp-edges")
{
    const int size = 8, n = 16;
    const MipChain chain = make_procedural("checker", size);
    const SceneParams scene = make_scene(SceneKind::zoom, 64, 64, size);
    const Image analytic = reference_ground_truth(scene, chain, truth_options(Truth::analytic, AnalyticKind::checker));
    const Image texels = reference_ground_truth(scene, chain, truth_options(Truth::texels, AnalyticKind::none));
    const double light = double(0.9f), dark = double(0.05f);
    int analytic_flat = 0, texels_flat = 0, texels_means = 0;
    double worst_off = 0.0;
    for (size_t i = 0; i < analytic.texels.size(); ++i) {
        double off = 0.0;
        const int k = sample_count(analytic.texels[i].x, light, dark, n, off);
        worst_off = std::max(worst_off, off);
        analytic_flat += k == 0 || k == n;
        const int kt = sample_count(texels.texels[i].x, light, dark, n, off);
        texels_flat += off <= unit_roundoff && (kt == 0 || kt == n);
        texels_means += off <= unit_roundoff;
    }
    const double pixels = double(analytic.texels.size());
    std::printf("  analytic: %.1f %% of pixels 0.9 or 0.05, worst distance from a k/16 mean %.3g; texels: %.1f %% "
                "flat, %.1f %% k/16 means\n",
                100 * analytic_flat / pixels, worst_off, 100 * texels_flat / pixels, 100 * texels_means / pixels);
    // The float store of the exact mean: within half a float ulp of values below 1.
    CHECK(worst_off <= unit_roundoff, "every analytic pixel is a k/16 mean: " + test::show(worst_off));
    CHECK(analytic_flat >= 0.7 * pixels, std::to_string(analytic_flat) + " flat analytic pixels"); // ~77 %
    CHECK(texels_flat <= 0.05 * pixels, std::to_string(texels_flat) + " flat texel-truth pixels");
    CHECK(texels_means <= 0.5 * pixels, std::to_string(texels_means) + " texel-truth pixels are k/16 means");
}

TEST_SUITE_END();

TEST_SUITE_BEGIN("gpu");

// 5. The GPU's analytic truth against the CPU reference's, zoom scene, 64x64, 16 samples a pixel, every wrap
//    mode (the view crosses u = 1 at its right edge, where they differ): an 8-texel checker and a 64-texel
//    grid, both two-valued. The backends take the same samples; a sample's value differs only where the
//    float ray cast puts it across an edge from the double one, which moves its pixel by exactly the
//    contrast / 16. So each pixel's difference is a whole number of such flips, up to the GPU's float sum
//    (gamma_16 of the largest value: 16 u / (1 - 16 u) ~ 1e-6), and flips are rare: a sample must lie
//    within the ray cast's float error (~1e-6 px here) of an edge: at most 0.1 % of the 65536 samples.
TEST_CASE("gpu-vs-reference")
{
    VulkanContext context = create_context(test::test_context_options());
    {
        RenderPipelineCache cache;
        struct Case {
            const char* name;
            int size;
            AnalyticKind kind;
            double high, low; // channel 0's two values
        };
        for (const Case& c : {Case{"checker", 8, AnalyticKind::checker, double(0.9f), double(0.05f)},
                              Case{"grid", 64, AnalyticKind::grid, double(0.9f), double(0.02f)}}) {
            const MipChain chain = make_procedural(c.name, c.size);
            const SceneParams scene = make_scene(SceneKind::zoom, 64, 64, c.size);
            GpuTexture texture = upload_texture(context, chain, false);
            for (Wrap wrap : {Wrap::repeat, Wrap::clamp, Wrap::mirror}) {
                const SamplerOptions options = truth_options(Truth::analytic, c.kind, wrap);
                const Image gpu = gpu_render(context, texture, scene, options, RenderOptions{}, &cache);
                const Image cpu = reference_ground_truth(scene, chain, options);
                const double step = (c.high - c.low) / 16, sum_bound = 16 * unit_roundoff / (1 - 16 * unit_roundoff);
                long flips = 0;
                double worst_residual = 0.0, worst = 0.0;
                for (size_t i = 0; i < gpu.texels.size(); ++i) {
                    const double d = std::fabs(double(gpu.texels[i].x) - double(cpu.texels[i].x));
                    const long k = std::lround(d / step);
                    flips += k;
                    worst = std::max(worst, d);
                    worst_residual = std::max(worst_residual, std::fabs(d - k * step));
                }
                const long samples = long(gpu.texels.size()) * 16;
                std::printf("  %s %s: max |GPU - CPU| %.3g, %ld flipped samples of %ld, residual %.3g (bound %.3g)\n",
                            c.name, to_string(wrap).c_str(), worst, flips, samples, worst_residual,
                            sum_bound * c.high + unit_roundoff);
                CHECK(worst_residual <= sum_bound * c.high + unit_roundoff,
                      std::string(c.name) + " " + to_string(wrap) + ": " + test::show(worst_residual));
                CHECK(flips * 1000 <= samples, std::string(c.name) + " " + to_string(wrap) + ": " +
                                                   std::to_string(flips) + " flipped samples");
            }
            destroy_texture(context, texture);
        }
    }
    destroy_context(context);
    CHECK_EQ(validation_message_count(), 0);
}

TEST_SUITE_END();
