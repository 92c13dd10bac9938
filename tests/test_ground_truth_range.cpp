// The ground truth over a sample range (SamplerOptions::truth_first, truth_count): the viewer accumulates
// the truth a range a frame while the camera rests, so the ranges' means, weighted by their counts, must
// give the whole grid's mean; a range must be the same samples on the GPU and the CPU reference; and a
// range past the grid is refused by the host and clamped by the shader. 64x64 images, 16..64 spp.
#include "support.h"
#include "cli/golden.h"
#include "core/filter.h"
#include "core/procedural.h"
#include "reference/ground_truth.h"
#include "scene/scene.h"
#include "vulkan/backend.h"
#include "vulkan/render.h"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace tf;

namespace {

const double unit_roundoff = 0x1p-24; // float32: u = 2^-24

// gamma_n = n u / (1 - n u): a float sum of n terms (in any order) is within gamma_{n-1} sum |x| of the
// exact sum (Higham, Accuracy and Stability, 4.2); one more rounding for the division by n.
double gamma(int n) { return n * unit_roundoff / (1.0 - n * unit_roundoff); }

struct Chunk {
    int first, count;
};

SamplerOptions truth(PixelFilter pixel_filter, int side, Chunk chunk = {0, 0})
{
    SamplerOptions options;
    options.filter = Filter::ground_truth;
    options.pixel_filter = pixel_filter;
    options.truth_side = side;
    options.truth_first = chunk.first;
    options.truth_count = chunk.count;
    return options;
}

// The largest |value| a sample can take: every texel of level 0 and the background, every channel. A
// bilinear sample is a convex combination of texels, so it is no larger (up to its own rounding, which the
// gamma of the sum covers to first order).
double largest_sample(const MipChain& chain, const SceneParams& scene)
{
    double m = 0.0;
    for (const glm::vec4& t : chain.levels[0].texels)
        for (int c = 0; c < 4; ++c)
            m = std::max(m, double(std::fabs(t[c])));
    for (int c = 0; c < 4; ++c)
        m = std::max(m, double(std::fabs(scene.background[c])));
    return m;
}

// sum_k (count_k / total) chunk_k, per channel, in double.
std::vector<glm::dvec4> combine(const std::vector<Image>& chunks, const std::vector<Chunk>& ranges, int total)
{
    std::vector<glm::dvec4> out(chunks.at(0).texels.size(), glm::dvec4(0.0));
    for (size_t k = 0; k < chunks.size(); ++k) {
        const int count = ranges[k].count == 0 ? total - ranges[k].first : ranges[k].count;
        for (size_t i = 0; i < out.size(); ++i)
            out[i] += glm::dvec4(chunks[k].texels[i]) * (double(count) / total);
    }
    return out;
}

double largest_difference(const Image& full, const std::vector<glm::dvec4>& combined)
{
    double worst = 0.0;
    for (size_t i = 0; i < combined.size(); ++i)
        worst = std::max(worst, test::max_channel_diff(glm::dvec4(full.texels[i]), combined[i]));
    return worst;
}

double largest_difference(const Image& a, const Image& b)
{
    double worst = 0.0;
    for (size_t i = 0; i < a.texels.size(); ++i)
        worst = std::max(worst, test::max_channel_diff(glm::dvec4(a.texels[i]), glm::dvec4(b.texels[i])));
    return worst;
}

// The ranges every combination test splits the grid into: equal quarters, and an uneven split whose last
// range is count 0 (the rest), so that the weights matter.
const std::vector<std::vector<Chunk>> splits = {{{0, 16}, {16, 16}, {32, 16}, {48, 16}}, {{0, 5}, {5, 0}}};

// The test device with validation on and a 64-texel checker uploaded; at the end, no validation message.
struct Gpu {
    VulkanContext context = create_context(test::test_context_options());
    MipChain checker = make_procedural("checker", 64);
    GpuTexture texture = upload_texture(context, checker, false);
    ~Gpu()
    {
        destroy_texture(context, texture);
        destroy_context(context);
        CHECK_EQ(validation_message_count(), 0);
    }
    Image render(const SceneParams& scene, const SamplerOptions& options)
    {
        return gpu_render(context, texture, scene, options, RenderOptions{});
    }
};

// Golden case `name` of golden/manifest.txt: its scene, texture, options and thresholds.
GoldenCase golden_case(const std::string& name)
{
    for (const GoldenCase& c : read_manifest(TEXFILTER_SOURCE_DIR "/golden/manifest.txt"))
        if (c.name == name)
            return c;
    throw Error("golden/manifest.txt has no case " + name);
}

} // namespace

TEST_SUITE_BEGIN("gpu");

// 1. GPU chunk means, weighted by their counts, give the full GPU ground truth. Each sample is the same
//    float computation in either run (same pixel, index and grid), so the two differ only by summation:
//    the full mean is within (gamma_{N-1} + u) M <= gamma_N M of the exact mean, chunk k within
//    gamma_{n_k} M of its own, and the weights n_k / N carry those into the combination (in double):
//    |full - combined| <= M (gamma_N + sum_k (n_k / N) gamma_{n_k}), M the largest |sample|. For N = 64
//    in four chunks of 16 that is 80 u M = 4.8e-6 M.
TEST_CASE("chunks-combine-to-full")
{
    Gpu gpu;
    const int side = 8, total = side * side; // 64 spp
    const SceneParams scene = make_scene(SceneKind::plane, 64, 64, 64);
    const double m = largest_sample(gpu.checker, scene);
    for (PixelFilter pixel_filter : {PixelFilter::box, PixelFilter::gaussian}) {
        // One pipeline, the range set in its push constants as make_push_constants sets it (a pipeline
        // compile is most of a render's time on lavapipe).
        std::unique_ptr<GpuRenderer> renderer =
            create_renderer(gpu.context, gpu.texture, scene, truth(pixel_filter, side), RenderOptions{});
        const Image full = render_frame(*renderer, scene);
        for (const std::vector<Chunk>& split : splits) {
            std::vector<Image> chunks;
            double bound = gamma(total), chunk_off = 0.0;
            for (const Chunk& chunk : split) {
                const PushConstants range = make_push_constants(truth(pixel_filter, side, chunk), 0, glm::vec4(0.0f),
                                                                glm::vec4(0.0f));
                renderer->push.truth_first = range.truth_first;
                renderer->push.truth_count = range.truth_count;
                chunks.push_back(render_frame(*renderer, scene));
                const int count = chunk.count == 0 ? total - chunk.first : chunk.count;
                bound += double(count) / total * gamma(count);
                chunk_off = std::max(chunk_off, largest_difference(chunks.back(), full));
            }
            bound *= m;
            const double worst = largest_difference(full, combine(chunks, split, total));
            std::printf("  %s, %zu chunks: |full - combined| %.3g (bound %.3g); a chunk off the full by up to %.3g\n",
                        to_string(pixel_filter).c_str(), split.size(), worst, bound, chunk_off);
            CHECK(worst <= bound, test::show(worst) + " > " + test::show(bound));
            // The chunks are means of different samples: if the range were ignored, each would be the full
            // mean and the check above would pass for nothing.
            CHECK(chunk_off > 1000 * bound, test::show(chunk_off));
        }
    }
}

// 2. One chunk on the GPU equals the CPU reference's same chunk within the thresholds the golden case of
//    that scene uses (golden/manifest.txt; sRGB-encoded units, as `texfilter golden` compares). The cases
//    whose thresholds are per pixel (no failing percentage, which would depend on the image size): the
//    slanted quad under the Gaussian and the tunnel under the box.
TEST_CASE("chunk-vs-reference")
{
    Gpu gpu;
    for (const char* name : {"slanted-checker-ground-truth-gaussian", "tunnel-grid-ground-truth-box"}) {
        const GoldenCase c = golden_case(name);
        CHECK(c.thresholds.fail_percent == 0.0, std::string(name) + ": the thresholds are per pixel");
        const MipChain chain = make_procedural(c.texture.name_or_path, c.texture.procedural_size);
        GpuTexture texture = upload_texture(gpu.context, chain, false);
        const SceneParams scene = make_scene(c.scene, 64, 64, chain.levels[0].width);
        const int total = c.sampler.truth_side * c.sampler.truth_side;
        SamplerOptions options = c.sampler;
        options.truth_first = total / 4; // the second quarter and the third: not where the full grid starts
        options.truth_count = total / 2;
        const Image gpu_chunk = gpu_render(gpu.context, texture, scene, options, c.render);
        const Image cpu_chunk = reference_ground_truth(scene, chain, options);
        const Image cpu_full = reference_ground_truth(scene, chain, c.sampler);
        destroy_texture(gpu.context, texture);

        const DiffResult result = diff_images(encode_srgb(gpu_chunk), encode_srgb(cpu_chunk), c.thresholds);
        const DiffResult against_full = diff_images(encode_srgb(gpu_chunk), encode_srgb(cpu_full), c.thresholds);
        std::printf("  %s, samples [%d, %d): GPU vs CPU chunk max %.4g (hardfail %.4g); vs the full CPU truth %.4g\n",
                    name, options.truth_first, options.truth_first + options.truth_count, result.max_error,
                    c.thresholds.hard_fail, against_full.max_error);
        CHECK(result.pass, std::string(name) + "\n" + describe(result, c.thresholds));
        // The chunk is not the full grid: a GPU that ignored the range would match this instead.
        CHECK(!against_full.pass, std::string(name) + ": the chunk matches the full truth");
    }
}

// 3. A range past the grid: the host refuses it, naming the field; the shader clamps what reaches it
//    (first into [0, N-1], count into [1, N - first], count <= 0 the rest), so a renderer whose push
//    constants were written by hand still runs a bounded loop and gives a finite mean.
TEST_CASE("range-past-grid")
{
    Gpu gpu;
    const int side = 4, total = 16;
    const SceneParams scene = make_scene(SceneKind::zoom, 64, 64, 64);
    CHECK_THROWS_WITH(gpu.render(scene, truth(PixelFilter::box, side, {total, 1})), "truth_first 16");
    CHECK_THROWS_WITH(gpu.render(scene, truth(PixelFilter::box, side, {-1, 0})), "truth_first -1");
    CHECK_THROWS_WITH(gpu.render(scene, truth(PixelFilter::box, side, {10, 7})), "truth_count 7");
    CHECK_THROWS_WITH(gpu.render(scene, truth(PixelFilter::box, side, {0, -2})), "truth_count -2");

    const Image last = gpu.render(scene, truth(PixelFilter::box, side, {total - 1, 1}));
    const Image full = gpu.render(scene, truth(PixelFilter::box, side));
    auto render_with = [&](int first, int count) {
        std::unique_ptr<GpuRenderer> renderer =
            create_renderer(gpu.context, gpu.texture, scene, truth(PixelFilter::box, side), RenderOptions{});
        renderer->push.truth_first = first;
        renderer->push.truth_count = count;
        return render_frame(*renderer, scene);
    };
    // Past the end: the last sample alone. Before the start with count <= 0: the whole grid. Both exact:
    // the same samples summed in the same order.
    CHECK_EQ(largest_difference(render_with(1 << 30, 1 << 30), last), 0.0);
    CHECK_EQ(largest_difference(render_with(-5, -3), full), 0.0);
    CHECK(largest_difference(last, full) > 0.01, "the last sample alone differs from the grid's mean");
}

TEST_SUITE_END();

TEST_SUITE_BEGIN("reference");

// 4. The same on the CPU reference: it sums in double (error ~N 2^-53 M, negligible) and stores float,
//    so the full mean and each chunk mean are within u of their exact values: |full - combined| <= 2 u M
//    (plus the double sums, 1e-12 M).
TEST_CASE("reference-chunks-combine-to-full")
{
    const int side = 8, total = side * side;
    const MipChain chain = make_procedural("checker", 64);
    const SceneParams scene = make_scene(SceneKind::slanted, 64, 64, 64);
    const double bound = (2 * unit_roundoff + 1e-12) * largest_sample(chain, scene);
    for (PixelFilter pixel_filter : {PixelFilter::box, PixelFilter::gaussian}) {
        const Image full = reference_ground_truth(scene, chain, truth(pixel_filter, side));
        for (const std::vector<Chunk>& split : splits) {
            std::vector<Image> chunks;
            for (const Chunk& chunk : split)
                chunks.push_back(reference_ground_truth(scene, chain, truth(pixel_filter, side, chunk)));
            const double worst = largest_difference(full, combine(chunks, split, total));
            std::printf("  %s, %zu chunks: |full - combined| %.3g (bound %.3g)\n", to_string(pixel_filter).c_str(),
                        split.size(), worst, bound);
            CHECK(worst <= bound, test::show(worst) + " > " + test::show(bound));
            CHECK(largest_difference(chunks[0], full) > 1000 * bound, "chunk 0 is not the full mean");
        }
    }
    CHECK_THROWS_WITH(reference_ground_truth(scene, chain, truth(PixelFilter::box, side, {total, 0})), "truth_first 64");
    CHECK_THROWS_WITH(reference_ground_truth(scene, chain, truth(PixelFilter::box, side, {60, 5})), "truth_count 5");
}

TEST_SUITE_END();
