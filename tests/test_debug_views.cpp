// The debug views (shaders/texfilter/debug.glsl, `render --view`) against the CPU reference's own
// footprint (reference/footprint.h, double, written separately) and `sample --stats`; the palettes at exact
// points against the procedural mipcolors texture; the combinations that make no sense refused.
//
// The GPU's own lookup at a pixel is read back exactly: the `none` filter writes fract(uv) (exact in float)
// and the reference's uv gives the whole part, so the quad's fine differences are those the shader made
// (one float subtraction each). Tolerances then follow from the math: the LOD and ratio the reference finds
// at the GPU's lookup differ from those at its own lookup by the ray casts' rounding (measured per pixel,
// not assumed), and the shader evaluates them in float: log2 to 3 ULP (Vulkan's precision for log2), a few
// roundings of products and sums. The LOD shown is computed by the shader, not the sampler, so the device's
// mipmapPrecisionBits do not enter it.
#include "support.h"
#include "core/procedural.h"
#include "reference/debug_view.h"
#include "reference/footprint.h"
#include "reference/render.h"
#include "scene/scene.h"
#include "vulkan/backend.h"
#include "vulkan/render.h"
#include "vulkan/textures.h"
#include <cmath>
#include <cstdio>

using namespace tf;

namespace {

constexpr int kSize = 64;

// The test device with validation on; at the end, no validation message.
struct Gpu {
    VulkanContext context = create_context(test::test_context_options());
    ~Gpu()
    {
        destroy_context(context);
        CHECK_EQ(validation_message_count(), 0);
    }
};

SamplerOptions filter_options(Filter filter, AnisoShape shape = AnisoShape::gpu)
{
    SamplerOptions o;
    o.filter = filter;
    o.aniso_shape = shape;
    return o;
}

RenderOptions view_options(SceneKind kind, DebugView view)
{
    RenderOptions r = make_render_options(kind, Stage::fragment, Gradients::fine);
    r.view = view;
    return r;
}

std::string flags_of(const SamplerOptions& o)
{
    return "--filter " + to_string(o.filter) + (o.filter == Filter::aniso ? " --aniso-shape " + to_string(o.aniso_shape) : "");
}

// A pixel whose quad hits the surface: its lookups on both sides.
struct Probe {
    glm::ivec2 pixel;
    Lookup reference; // the reference's ray casts and quads (double)
    Lookup gpu;       // what the shader filtered (float), from the `none` render
};

// The GPU's uv at pixel p: whole part from the reference, fraction from `none` (fract(uv), exact).
glm::dvec2 gpu_uv(const Image& none, const SceneParams& scene, int x, int y)
{
    glm::dvec2 ref = reference_hit(scene, x + 0.5, y + 0.5).uv;
    glm::dvec2 frac(none.at(x, y).x, none.at(x, y).y);
    return glm::round(ref - frac) + frac;
}

// The tunnel's u is periodic: where a quad's plain u difference jumps (over half a period, at the seam) the
// shader takes that of fract(u + 0.5) instead if smaller (texfilter/derivatives.glsl), in float.
double shader_u_difference(const SceneParams& scene, double u1, double u0)
{
    double plain = u1 - u0;
    if (scene.kind_size.x != HARNESS_SCENE_CYLINDER || std::abs(plain) <= 0.5)
        return plain;
    auto shift = [](double u) {
        float s = float(u) + 0.5f;
        return double(s - std::floor(s));
    };
    double shifted = shift(u1) - shift(u0);
    return std::abs(shifted) < std::abs(plain) ? shifted : plain;
}

// Pixels on a grid (odd offsets: both quad positions), every one whose quad is all hit.
std::vector<Probe> probes_of(const SceneParams& scene, const Image& none)
{
    std::vector<Probe> out;
    const std::vector<PixelLookup> lookups = reference_lookups(scene, Gradients::fine, false);
    for (int y = 3; y < kSize; y += 6)
        for (int x = 2; x < kSize; x += 7) {
            int x0 = x & ~1, y0 = y & ~1;
            bool quad_hit = true;
            for (int k = 0; k < 4; ++k)
                quad_hit = quad_hit && lookups[size_t(y0 + (k >> 1)) * kSize + size_t(x0 + (k & 1))].hit;
            if (!quad_hit)
                continue;
            glm::dvec2 uv = gpu_uv(none, scene, x, y);
            glm::dvec2 dx = gpu_uv(none, scene, x0 | 1, y) - gpu_uv(none, scene, x0, y);
            glm::dvec2 dy = gpu_uv(none, scene, x, y0 | 1) - gpu_uv(none, scene, x, y0);
            dx.x = shader_u_difference(scene, gpu_uv(none, scene, x0 | 1, y).x, gpu_uv(none, scene, x0, y).x);
            dy.x = shader_u_difference(scene, gpu_uv(none, scene, x, y0 | 1).x, gpu_uv(none, scene, x, y0).x);
            Lookup g{uv.x, uv.y, dx.x, dx.y, dy.x, dy.y};
            out.push_back({{x, y}, lookups[size_t(y) * kSize + size_t(x)].lookup, test::as_float(g)});
        }
    return out;
}

// One scene's probes and each filter's `data` render, on the GPU.
struct SceneData {
    SceneKind kind;
    SceneParams scene;
    std::vector<Probe> probes;
    std::vector<Image> data; // one per filter of debug_filters()
};

const std::vector<SamplerOptions>& debug_filters()
{
    static const std::vector<SamplerOptions> filters = {filter_options(Filter::trilinear), filter_options(Filter::aniso),
                                                        filter_options(Filter::aniso, AnisoShape::feline),
                                                        filter_options(Filter::ewa)};
    return filters;
}

std::vector<SceneData> render_scenes(Gpu& gpu, const MipChain& chain)
{
    std::vector<SceneData> out;
    GpuTexture texture = upload_texture(gpu.context, chain, false);
    for (SceneKind kind : {SceneKind::plane, SceneKind::tunnel, SceneKind::slanted, SceneKind::minify}) {
        SceneData d{kind, make_scene(kind, kSize, kSize, chain.levels[0].width), {}, {}};
        Image none = gpu_render(gpu.context, texture, d.scene, filter_options(Filter::none),
                                view_options(kind, DebugView::color));
        d.probes = probes_of(d.scene, none);
        for (const SamplerOptions& o : debug_filters())
            d.data.push_back(gpu_render(gpu.context, texture, d.scene, o, view_options(kind, DebugView::data)));
        CHECK(d.probes.size() >= 20, to_string(kind) + ": " + std::to_string(d.probes.size()) + " pixels");
        out.push_back(std::move(d));
    }
    destroy_texture(gpu.context, texture);
    return out;
}

// What the shader's float evaluation may add: three log2 calls (3 ULP each at |lod| < 16, ulp 2^-19) and
// the roundings of the sums around them.
constexpr double kLodFloat = 12.0 * 0x1p-19;

// Relative, no credit for errors that cancel: the ratio takes about a dozen float operations (products,
// sums, the sqrt inside length, one division), each allowed up to 2.5 ULP by Vulkan's precision table
// (division 2.5, sqrt inherited from 1/inversesqrt: 4.5, counted twice), so 32 ULP of 2^-24; det J's
// cancellation scales its own error by (|ad| + |bc|) / |ad - bc|. Measured on lavapipe: up to 31 ULP at
// a cond of 1 (plane), which a first-order count of the same operations (about 18) did not cover.
double ratio_float_error(const MipChain& chain, const Lookup& l)
{
    const double w = chain.levels[0].width, h = chain.levels[0].height;
    const double a = l.dudx * w, b = l.dudy * w, c = l.dvdx * h, d = l.dvdy * h;
    const double cond = (std::abs(a * d) + std::abs(b * c)) / std::abs(a * d - b * c);
    return 0x1p-24 * (32.0 + 4.0 * cond);
}

} // namespace

TEST_SUITE_BEGIN("gpu");

// The `data` view's LOD and anisotropy at chosen pixels of four scenes and four filters vs pixel_footprint.
TEST_CASE("data-vs-reference")
{
    Gpu gpu;
    const MipChain chain = make_procedural("checker", 256);
    test::limit_failure_lines(20);
    int checked = 0;
    double worst_lod = 0, worst_ratio = 0;
    for (const SceneData& d : render_scenes(gpu, chain))
        for (size_t f = 0; f < debug_filters().size(); ++f) {
            const SamplerOptions& o = debug_filters()[f];
            const RenderOptions render = view_options(d.kind, DebugView::data);
            for (const Probe& p : d.probes) {
                const PixelFootprint ref = pixel_footprint(d.scene, chain, o, render, p.pixel);
                const PixelFootprint at_gpu = lookup_footprint(chain, o, p.gpu);
                const glm::vec4 shown = d.data[f].at(p.pixel.x, p.pixel.y);
                const std::string where = to_string(d.kind) + " " + flags_of(o) + " pixel (" +
                                          std::to_string(p.pixel.x) + ", " + std::to_string(p.pixel.y) + ")";
                CHECK(ref.hit, where);
                const double lod_tol = std::abs(at_gpu.lod - ref.lod) + kLodFloat;
                CHECK(std::abs(shown.x - ref.lod) <= lod_tol,
                      where + ": lod " + test::show(shown.x) + " vs " + test::show(ref.lod) + " (at the GPU's lookup " +
                          test::show(at_gpu.lod) + ")");
                const double ratio_tol =
                    std::abs(at_gpu.anisotropy - ref.anisotropy) + ratio_float_error(chain, p.gpu) * ref.anisotropy;
                CHECK(std::abs(shown.y - ref.anisotropy) <= ratio_tol,
                      where + ": ratio " + test::show(shown.y) + " vs " + test::show(ref.anisotropy));
                worst_lod = std::max(worst_lod, std::abs(shown.x - at_gpu.lod));
                worst_ratio = std::max(worst_ratio, std::abs(shown.y - at_gpu.anisotropy) / at_gpu.anisotropy);
                ++checked;
            }
        }
    std::printf("%d pixels: at the GPU's own lookup, lod within %.3g, ratio within %.3g relative\n", checked, worst_lod,
                worst_ratio);
    CHECK(checked >= 4 * 4 * 20);
}

// The `data` view's B: this pixel's texel fetches + hardware lookups, as `sample --stats` counts them for the
// same (float) lookup.
TEST_CASE("data-fetches-vs-sample-stats")
{
    Gpu gpu;
    const MipChain chain = make_procedural("checker", 256);
    const std::filesystem::path& work = test::work_dir();
    test::limit_failure_lines(20);
    const std::vector<SceneData> scenes = render_scenes(gpu, chain);
    for (size_t f = 0; f < debug_filters().size(); ++f) {
        const SamplerOptions& o = debug_filters()[f];
        std::vector<Lookup> lookups;
        std::vector<double> shown;
        for (const SceneData& d : scenes)
            for (const Probe& p : d.probes) {
                lookups.push_back(p.gpu);
                shown.push_back(d.data[f].at(p.pixel.x, p.pixel.y).z);
            }
        const std::string csv = (work / ("lookups-" + std::to_string(f) + ".csv")).string();
        test::write_lookups_csv(csv, lookups);
        const test::SampleResult r =
            test::run_sample("--texture checker " + flags_of(o), csv, true);
        CHECK_EQ(r.stats.size(), lookups.size());
        double most = 0;
        for (size_t i = 0; i < std::min(r.stats.size(), lookups.size()); ++i) {
            const double counted = double(r.stats[i].texel_fetches) + double(r.stats[i].hardware_lookups);
            CHECK(shown[i] == counted, flags_of(o) + " lookup " + std::to_string(i) + ": view " + test::show(shown[i]) +
                                           ", sample --stats " + test::show(counted));
            most = std::max(most, counted);
        }
        std::printf("%s: %zu lookups, up to %g fetches\n", flags_of(o).c_str(), lookups.size(), most);
        CHECK(most > 8 || o.filter == Filter::trilinear); // aniso and ewa really took more than one trilinear
    }
}

// The LOD palette at exact points: lod_min = lod_max = k pins every pixel's LOD to k, so the lod view shows
// the mipcolors texture's level k colour (k + 1/2: the mean of levels k and k + 1), on the GPU and the
// reference alike. A 2048x2 texture: twelve levels, the whole palette.
TEST_CASE("lod-palette-is-mipcolors")
{
    Gpu gpu;
    const MipChain mipcolors = make_procedural("mipcolors", 2048);
    const MipChain narrow = build_mip_chain(make_image(2048, 2, glm::vec4(0.5f)));
    CHECK_EQ(narrow.levels.size(), 12);
    CHECK_EQ(mipcolors.levels.size(), 12);
    GpuTexture texture = upload_texture(gpu.context, narrow, false);
    SceneParams scene = make_scene(SceneKind::minify, 16, 16, 2048);
    SamplerOptions o = filter_options(Filter::trilinear);
    const RenderOptions render = view_options(SceneKind::minify, DebugView::lod);
    std::unique_ptr<GpuRenderer> renderer = create_renderer(gpu.context, texture, scene, o, render);
    for (int half = 0; half < 2; ++half)
        for (int k = 0; k + half < 12; ++k) {
            const float lod = float(k) + 0.5f * float(half);
            renderer->push.lod_min = renderer->push.lod_max = lod;
            o.lod_min = o.lod_max = lod;
            const glm::dvec4 level_k(mipcolors.levels[size_t(k)].at(0, 0));
            const glm::dvec4 expected = half ? 0.5 * (level_k + glm::dvec4(mipcolors.levels[size_t(k) + 1].at(0, 0))) : level_k;
            const Image shown = render_frame(*renderer, scene);
            const Image reference = reference_render(scene, narrow, o, render);
            const glm::dvec4 gpu_pixel(shown.at(8, 8)), ref_pixel(reference.at(8, 8));
            CHECK_NEAR(gpu_pixel, expected, 0.0);
            CHECK_NEAR(ref_pixel, expected, 0.0);
            CHECK_NEAR(glm::dvec4(debug_lod_color(lod), 1.0), expected, 0.0);
        }
    renderer.reset();
    destroy_texture(gpu.context, texture);
}

// The anisotropy and fetches views are the documented palettes of the data view's numbers (the GLSL and
// C++ palettes agree): float mixing of the stops, 2^-20 per channel.
TEST_CASE("view-colors-are-the-palettes")
{
    Gpu gpu;
    const MipChain chain = make_procedural("checker", 256);
    GpuTexture texture = upload_texture(gpu.context, chain, false);
    int checked = 0;
    for (SceneKind kind : {SceneKind::plane, SceneKind::slanted}) {
        SceneParams scene = make_scene(kind, kSize, kSize, 256);
        for (const SamplerOptions& o : {filter_options(Filter::aniso), filter_options(Filter::ewa)}) {
            const Image data = gpu_render(gpu.context, texture, scene, o, view_options(kind, DebugView::data));
            const Image aniso = gpu_render(gpu.context, texture, scene, o, view_options(kind, DebugView::anisotropy));
            const Image fetches = gpu_render(gpu.context, texture, scene, o, view_options(kind, DebugView::fetches));
            const std::vector<PixelLookup> lookups = reference_lookups(scene, Gradients::fine, false);
            for (size_t i = 0; i < lookups.size(); i += 37) {
                if (!lookups[i].hit)
                    continue;
                const glm::vec4 n = data.texels[i];
                const double eps = 0x1p-20 + 0x1p-19 * 4.0; // the ratio ramp's log2 (3 ULP) times its slope
                CHECK_NEAR(glm::dvec4(aniso.texels[i]), glm::dvec4(debug_anisotropy_color(n.y), 1.0), eps);
                CHECK_NEAR(glm::dvec4(fetches.texels[i]),
                           glm::dvec4(debug_heat(n.z, HARNESS_VIEW_FETCHES_MAX), 1.0), 0x1p-20);
                ++checked;
            }
            // Background pixels keep the background in every view.
            for (size_t i = 0; i < lookups.size(); ++i)
                if (!lookups[i].hit && kind == SceneKind::slanted) {
                    CHECK_NEAR(glm::dvec4(aniso.texels[i]), glm::dvec4(scene.background), 0.0);
                    break;
                }
        }
    }
    CHECK(checked > 100);
    destroy_texture(gpu.context, texture);
}

TEST_SUITE_END();

// The palettes' documented stops (CPU).
TEST_CASE("palette-stops")
{
    CHECK_NEAR(glm::dvec4(debug_anisotropy_color(1.0), 1.0), glm::dvec4(0.2, 0.2, 0.2, 1.0), 0.0);
    CHECK_NEAR(glm::dvec4(debug_anisotropy_color(16.0), 1.0), glm::dvec4(1.0, 0.05, 0.05, 1.0), 1e-15);
    CHECK_NEAR(glm::dvec4(debug_anisotropy_color(INFINITY), 1.0), glm::dvec4(1.0, 0.05, 0.05, 1.0), 1e-15);
    CHECK_NEAR(glm::dvec4(debug_anisotropy_color(NAN), 1.0), glm::dvec4(0.2, 0.2, 0.2, 1.0), 0.0);
    CHECK_NEAR(glm::dvec4(debug_heat(0.0, 128.0), 1.0), glm::dvec4(0.0, 0.0, 0.0, 1.0), 0.0);
    CHECK_NEAR(glm::dvec4(debug_heat(128.0, 128.0), 1.0), glm::dvec4(1.0, 1.0, 1.0, 1.0), 0.0);
    CHECK_NEAR(glm::dvec4(debug_heat(1e9, 128.0), 1.0), glm::dvec4(1.0, 1.0, 1.0, 1.0), 0.0);
    CHECK_NEAR(glm::dvec4(debug_heat(0.0, 0.0), 1.0), glm::dvec4(0.0, 0.0, 0.0, 1.0), 0.0);
    CHECK_NEAR(glm::dvec4(debug_lod_color(12.0), 1.0), glm::dvec4(debug_lod_color(0.0), 1.0), 0.0); // 12 hues
    CHECK_NEAR(glm::dvec4(debug_lod_color(NAN), 1.0), glm::dvec4(debug_lod_color(0.0), 1.0), 0.0);
}

// The reference's footprint on known gradients: a 4:1 footprint along u on a 256 texture.
TEST_CASE("footprint-known-gradients")
{
    const MipChain chain = make_procedural("checker", 256);
    const Lookup l{0.5, 0.5, 8.0 / 256, 0.0, 0.0, 2.0 / 256};
    CHECK_NEAR(footprint_anisotropy(chain, l), 4.0, 1e-12);
    const PixelFootprint trilinear = lookup_footprint(chain, filter_options(Filter::trilinear), l);
    CHECK_NEAR(trilinear.lod, 3.0, 1e-12); // log2(8)
    CHECK(trilinear.probes.empty());
    const PixelFootprint aniso = lookup_footprint(chain, filter_options(Filter::aniso), l);
    CHECK_NEAR(aniso.lod, 1.0, 1e-12); // log2(8 / 4 probes)
    CHECK_EQ(aniso.probes.size(), 4);
    CHECK_NEAR(aniso.probes[0].x, 0.5 - 3.0 / 256, 1e-15); // t = -3/8 of the 8-texel axis
    CHECK_NEAR(glm::length(aniso.major) * 256, 4.0, 1e-12); // half the probes' line
    CHECK_NEAR(glm::length(aniso.minor) * 256, 1.0, 1e-12); // half the level-1 texel
    const PixelFootprint ewa = lookup_footprint(chain, filter_options(Filter::ewa), l);
    CHECK_NEAR(ewa.lod, 0.5, 1e-12); // log2(minor semi-axis 2 / sqrt(2))
    CHECK_NEAR(std::abs(ewa.major.x) * 256, 4.0, 1e-12);
    CHECK_NEAR(std::abs(ewa.minor.y) * 256, 1.0, 1e-12);
    CHECK_NEAR(footprint_anisotropy(chain, {0.5, 0.5, 0, 0, 0, 0}), 1.0, 0.0);
    CHECK_NEAR(footprint_anisotropy(chain, {0.5, 0.5, NAN, 0, 0, 1}), 1.0, 0.0);
    CHECK(std::isinf(footprint_anisotropy(chain, {0.5, 0.5, 0.01, 0, 0.02, 0})));
}

// Views that make no sense are refused with a message naming them, before any work.
TEST_CASE("bad-combinations")
{
    CHECK_THROWS_WITH(check_view(Filter::ground_truth, DebugView::lod), "--filter ground-truth");
    CHECK_THROWS_WITH(check_view(Filter::none, DebugView::data), "--filter none");
    CHECK_THROWS_WITH(check_reference_view(DebugView::fetches), "counts no texel fetches");
    CHECK_THROWS_WITH(parse_view("heat"), "unknown view 'heat'");
    const MipChain chain = make_procedural("checker", 16);
    SceneParams scene = make_scene(SceneKind::plane, 8, 8, 16);
    CHECK_THROWS_WITH(reference_render(scene, chain, filter_options(Filter::ground_truth),
                                       view_options(SceneKind::plane, DebugView::anisotropy)),
                      "makes no lookup");
    CHECK_THROWS_WITH(reference_render(scene, chain, filter_options(Filter::trilinear),
                                       view_options(SceneKind::plane, DebugView::fetches)),
                      "--view fetches");
    CHECK_THROWS_WITH(pixel_footprint(scene, chain, filter_options(Filter::trilinear),
                                      view_options(SceneKind::plane, DebugView::color), {8, 0}),
                      "outside the 8x8 image");
    for (DebugView v : {DebugView::color, DebugView::lod, DebugView::anisotropy, DebugView::fetches, DebugView::data})
        CHECK(parse_view(to_string(v)) == v);
}
