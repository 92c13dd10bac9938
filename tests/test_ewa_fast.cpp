// ewa-fast (shaders/texfilter/ewa_fast.glsl, host/reference/ewa_fast.cpp): the device through `texfilter sample`
// against the CPU reference (tests/sample_checks.h: bounds from float rounding and the device's reported
// subTexelPrecisionBits / mipmapPrecisionBits, as aniso's hardware probes), a constant texture, and the number of
// hardware lookups the header promises.
#include "core/filter.h"
#include "core/lookup_stats.h"
#include "io/texture_source.h"
#include "reference/reference.h"
#include "scene/scene.h"
#include "sample_checks.h"
#include "support.h"
#include "vulkan/backend.h"
#include "vulkan/device.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

using namespace tf;
namespace sample = tf::test::sample;

namespace {

// The header's cap: a row of at most 2·4 + 1 probes.
constexpr int kMaxLookups = 9;

// The reference's probe count of a lookup: 3 for the triangle, 2·half + 1 for the row.
int reference_count(const MipChain& chain, const SamplerOptions& options, const Lookup& l)
{
    const EwaFastProbes p = reference_ewa_fast_probes(chain, options, l);
    return p.triangle ? 3 : 2 * p.half + 1;
}

// Footprints the count rules name: zero, non-finite, huge, isotropic, 2:1 and 64:1 (a row of 9), at the size of
// the sample checks' texture.
std::vector<Lookup> named_footprints()
{
    const double texel = 1.0 / sample::kSize, nan = std::numeric_limits<double>::quiet_NaN();
    return test::as_float(std::vector<Lookup>{
        {0.3, 0.4, 0, 0, 0, 0},                               // zero: 1
        {0.3, 0.4, nan, 0, 0, texel},                         // NaN: 1
        {0.3, 0.4, 1e30, 0, 0, 1e30},                         // 4k²σ1² + 1 past float range: 1
        {0.3, 0.4, 1e6, 0, 0, 1e3},                           // huge, 1000:1: the row of 9
        {0.3, 0.4, 4 * texel, 0, 0, 4 * texel},               // isotropic, 4 texels: the triangle, 3
        {0.3, 0.4, 0.25 * texel, 0, 0, 0.25 * texel},         // magnified: the triangle, 3
        {0.3, 0.4, 2 * texel, 2 * texel, -2 * texel, 2 * texel}, // rotated, isotropic: 3
        {0.3, 0.4, 64 * texel, 0, 0, texel},                  // 64:1: the row of 9
        {0.3, 0.4, 20 * texel, 20 * texel, -0.3 * texel, 0.3 * texel}, // 47:1 diagonal: 9
    });
}
const int kNamedCounts[] = {1, 1, 1, 9, 3, 3, 3, 9, 9};

} // namespace

// GPU vs reference lookup by lookup (256 footprints, 1/4 to 64 texels, up to 4:1), three wrap modes and the
// separate texture + sampler kind: within float rounding plus the sampler's sub-texel and mipmap steps.
TEST_CASE("sample-repeat") { sample::check_case(sample::make_case(Resource::combined, Filter::ewa_fast)); }
TEST_CASE("sample-clamp")
{
    sample::check_case(sample::make_case(Resource::combined, Filter::ewa_fast, Taps::manual, 4, 2, Wrap::clamp));
}
TEST_CASE("sample-mirror")
{
    sample::check_case(sample::make_case(Resource::combined, Filter::ewa_fast, Taps::manual, 4, 2, Wrap::mirror));
}
TEST_CASE("sample-separate") { sample::check_case(sample::make_case(Resource::separate, Filter::ewa_fast)); }

// A constant texture gives the constant: the weights are normalised and every lookup of a constant is it, on
// the device within 2n + 16 ulp (n lookups) of the value, the reference within a few double ulp.
TEST_CASE("constant-texture")
{
    const glm::vec4 value(0.25f, 0.5f, 0.75f, 1.0f);
    const MipChain chain = build_mip_chain(make_image(sample::kSize, sample::kSize, value));
    std::vector<Lookup> ls = sample::lookups();
    for (const Lookup& l : named_footprints())
        ls.push_back(l);
    SamplerOptions options;
    options.filter = Filter::ewa_fast;
    VulkanContext context = create_context(test::test_context_options());
    GpuTexture texture = upload_texture(context, chain, false);
    std::vector<LookupStats> stats;
    const std::vector<glm::vec4> gpu = gpu_sample(context, texture, ls, options, &stats);
    destroy_texture(context, texture);
    destroy_context(context);
    CHECK(validation_message_count() == 0, "Vulkan validation messages");
    double worst = 0;
    for (size_t i = 0; i < ls.size(); ++i) {
        const double n = stats[i].hardware_lookups, bound = (16 + 2 * n) * std::ldexp(1.0, -24);
        const double error = test::max_channel_diff(glm::dvec4(gpu[i]), glm::dvec4(value));
        worst = std::max(worst, error / bound);
        CHECK(error <= bound, "lookup " + std::to_string(i) + " GPU " + test::show(glm::dvec4(gpu[i])));
        const glm::dvec4 reference = reference_ewa_fast(chain, options, ls[i]); // double: a few ulp of it
        CHECK(test::max_channel_diff(reference, glm::dvec4(value)) <= 1e-15,
              "reference, lookup " + std::to_string(i) + ": " + test::show(reference));
    }
    std::printf("constant texture: %zu lookups, worst error/bound %.3f\n", ls.size(), worst);
}

// The cost the header states: never more than 9 hardware lookups, no texel fetch, the named footprints'
// counts, and on the sample checks' footprints the reference's count (the same rule in double) except where
// the footprint sits on a count boundary (the reference's count moves under a 1e-5 change of the footprint).
TEST_CASE("lookup-count")
{
    const sample::Case c = sample::make_case(Resource::combined, Filter::ewa_fast);
    const std::vector<MipChain> chains = sample::chains_of(c);
    const test::SampleResult gpu = sample::gpu_run(c);
    const std::vector<Lookup>& ls = sample::lookups();
    CHECK(gpu.stats.size() == ls.size(), "rows");
    if (gpu.stats.size() != ls.size())
        return;
    int largest = 0, differ = 0;
    for (size_t i = 0; i < ls.size(); ++i) {
        const int n = int(gpu.stats[i].hardware_lookups);
        largest = std::max(largest, n);
        CHECK(n >= 1 && n <= kMaxLookups && gpu.stats[i].texel_fetches == 0,
              "lookup " + std::to_string(i) + ": " + std::to_string(n) + " lookups, " +
                  std::to_string(gpu.stats[i].texel_fetches) + " fetches");
        if (n != reference_count(chains[0], c.options, ls[i])) {
            bool boundary = false;
            for (double x : {1 - 1e-5, 1 + 1e-5}) {
                Lookup moved = ls[i];
                moved.dudx *= x, moved.dvdx *= x, moved.dudy *= x, moved.dvdy *= x;
                boundary = boundary || reference_count(chains[0], c.options, moved) == n;
            }
            differ += boundary ? 0 : 1;
            CHECK(boundary, "lookup " + std::to_string(i) + ": GPU " + std::to_string(n) + " lookups, reference " +
                                std::to_string(reference_count(chains[0], c.options, ls[i])));
        }
    }
    std::printf("sample footprints: at most %d lookups, %d counts off the reference's\n", largest, differ);
    VulkanContext context = create_context(test::test_context_options());
    GpuTexture texture = upload_texture(context, chains[0], false);
    std::vector<LookupStats> stats;
    const std::vector<Lookup> named = named_footprints();
    gpu_sample(context, texture, named, c.options, &stats);
    destroy_texture(context, texture);
    destroy_context(context);
    for (size_t i = 0; i < named.size(); ++i) {
        CHECK(int(stats[i].hardware_lookups) == kNamedCounts[i],
              "named footprint " + std::to_string(i) + ": " + std::to_string(stats[i].hardware_lookups) +
                  " lookups, expected " + std::to_string(kNamedCounts[i]));
        CHECK(reference_count(chains[0], c.options, named[i]) == kNamedCounts[i],
              "named footprint " + std::to_string(i) + " on the reference");
    }
}

// The bench's plane (256², checker 512) in one render: the data view (render --view data) counts each pixel's
// lookups (B: fetches + hardware lookups of its one lookup); none above 9 (lavapipe, 2026-12-05: mean 4.93;
// the bench's counted reads, 6.8, come from its own frames).
TEST_CASE("plane-lookups")
{
    const int texture_size = 512;
    const MipChain chain = load_texture(TextureSource{"checker", texture_size});
    const SceneParams scene = make_scene(SceneKind::plane, 256, 256, texture_size);
    RenderOptions render = make_render_options(SceneKind::plane, Stage::fragment, Gradients::fine);
    render.view = DebugView::data;
    SamplerOptions options;
    options.filter = Filter::ewa_fast;
    VulkanContext context = create_context(test::test_context_options());
    GpuTexture texture = upload_texture(context, chain, false);
    const Image data = gpu_render(context, texture, scene, options, render);
    destroy_texture(context, texture);
    destroy_context(context);
    CHECK_EQ(validation_message_count(), 0);
    double sum = 0, largest = 0;
    for (int y = 0; y < data.height; ++y)
        for (int x = 0; x < data.width; ++x) {
            sum += data.at(x, y).b;
            largest = std::max(largest, double(data.at(x, y).b));
        }
    const double mean = sum / (double(data.width) * data.height);
    std::printf("plane: %d x %d pixels, %.2f lookups a pixel, at most %.0f\n", data.width, data.height, mean, largest);
    CHECK(largest <= kMaxLookups, "most lookups a pixel on the plane: " + test::show(largest));
    CHECK(mean >= 1 && mean <= kMaxLookups, "mean lookups a pixel on the plane: " + test::show(mean));
}
