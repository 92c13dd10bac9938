// bench --footprints (host/bench/footprint_bench.h): its per-lookup truths against the analytic value, every
// filter of its table on a constant texture, and whether its truths are fine enough for the errors it measures.
// The device filters run in this process on the suite's device (lavapipe by default).
#include "bench/footprint_bench.h"
#include "support.h"
#include "texture/image.h"
#include "texture/mip.h"
#include "vulkan/device.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/glm.hpp>

using namespace tf;

namespace {

struct Device {
    VulkanContext context;
    Device() : context(create_context(test::test_context_options())) {}
    ~Device() { destroy_context(context); }
};

constexpr double float_epsilon = 1.0 / 16777216.0; // 2^-24: float's rounding, relative

} // namespace

// A texture linear in x and y (texel centres on the plane a + b·x + c·y, so its bilinear reconstruction is the
// plane itself away from the edges): a lookup's box truth is the plane at the pixel's centre, up to what the
// jitter moves the samples' mean — each sample lies in its stratum, whose centres average to the pixel's centre
// exactly, so the mean is off by at most half a stratum along each pixel axis: (|∇f·J_x| + |∇f·J_y|) / (2·side).
// The Gaussian truth's mean position is a random mean of side² samples of sigma ½ px: five standard deviations
// of it, 5·½·(|∇f·J_x| + |∇f·J_y|)/side, bound it (a plain Monte-Carlo bound; strata only shrink it).
TEST_CASE("linear-texture-truth")
{
    const int size = 64;
    Image level0 = make_image(size, size);
    const glm::dvec3 a(0.1, 0.3, 0.5), bx(0.01, 0.0, -0.004), by(0.0, 0.012, 0.003); // per channel
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const glm::dvec3 value = a + bx * (i + 0.5) + by * (j + 0.5);
            level0.texels[size_t(j) * size + size_t(i)] = glm::vec4(glm::vec3(value), 1.0f);
        }
    int checked = 0;
    for (double du : {-3.1, 0.0, 2.7})
        for (int side : {4, 16, 64}) {
            // Centre near the middle; J with both columns oblique and unequal (texels a pixel).
            Lookup l;
            l.u = (31.3 + du) / size;
            l.v = 30.8 / size;
            l.dudx = 2.5 / size, l.dvdx = 0.7 / size, l.dudy = -0.9 / size, l.dvdy = 1.8 / size;
            const double cx = l.u * size, cy = l.v * size;
            const glm::dvec3 centre = a + bx * cx + by * cy;
            for (PixelFilter filter : {PixelFilter::box, PixelFilter::gaussian})
                for (uint32_t stream : {0u, 1u}) {
                    const glm::dvec4 truth = footprint_truth(level0, l, filter, side, 7, stream, Wrap::repeat);
                    for (int c = 0; c < 3; ++c) {
                        const double along_x = std::abs(bx[c] * l.dudx * size + by[c] * l.dvdx * size);
                        const double along_y = std::abs(bx[c] * l.dudy * size + by[c] * l.dvdy * size);
                        const double jitter = filter == PixelFilter::box ? (along_x + along_y) / (2.0 * side)
                                                                         : 5.0 * 0.5 * (along_x + along_y) / side;
                        // Texels are floats: each off by half an ulp of at most 1.
                        const double bound = jitter + float_epsilon;
                        CHECK_NEAR(truth[c], centre[c], bound);
                        ++checked;
                    }
                }
        }
    std::printf("linear-texture-truth: %d channel values within the strata's bound\n", checked);
}

// A constant texture: every filter of the table (device and host) answers the constant, to float precision.
// A filter's answer is a weighted mean, Σw·c / Σw in float: each sum of n terms is within n·2^-24 relative of its
// exact value, so the answer within 2·(n + 1)·2^-24·c, n the texels and taps it read (a hardware lookup blends at
// most 8 texels: 2 levels of 4). Host filters, which do not count, are held to the EWA's texel cap.
TEST_CASE("constant-texture")
{
    Device device;
    const glm::vec4 constant(0.25f, 0.5f, 0.75f, 1.0f);
    const MipChain chain = build_mip_chain(make_image(96, 80, constant));
    FootprintSampling sampling;
    sampling.lookups = 600;
    std::vector<Lookup> lookups;
    for (const FootprintLookup& l : footprint_lookups(96, 80, sampling))
        lookups.push_back(l.lookup);
    std::vector<FootprintFilter> filters = footprint_filters();
    const std::vector<FootprintAnswers> answers = run_footprint_filters(&device.context, "constant", chain, filters, lookups);
    test::limit_failure_lines(10);
    for (size_t f = 0; f < filters.size(); ++f) {
        double worst = 0;
        for (size_t i = 0; i < lookups.size(); ++i) {
            const double n = answers[f].stats.empty()
                                 ? 4096.0
                                 : double(answers[f].stats[i].texel_fetches) + 8.0 * answers[f].stats[i].hardware_lookups;
            for (int c = 0; c < 4; ++c) {
                const double error = std::abs(answers[f].colors[i][c] - double(constant[c]));
                worst = std::max(worst, error / double(constant[c]));
                CHECK(error <= 2.0 * (n + 1.0) * float_epsilon * double(constant[c]),
                      filters[f].label + " lookup " + std::to_string(i) + " channel " + std::to_string(c) + ": " +
                          test::show(answers[f].colors[i][c]) + " for " + test::show(double(constant[c])));
            }
        }
        std::printf("constant-texture: %-22s worst relative error %.3g\n", filters[f].label.c_str(), worst);
    }
}

// The truths are fine enough for what is measured: in every (truth, bucket) of the two full axes the noise floor (one truth against
// its independent twin) is at least 10 dB above the best filter's PSNR there. Each truth carries half the
// floor's squared error, so a filter's PSNR is then lowered by at most 10·log10(1 + ½·10^-1) = 0.21 dB by the
// truth's own noise. On the 512² checker (the hardest texture: every texel an edge), the run's default sampling.
TEST_CASE("noise-floor")
{
    Device device;
    FootprintConfig config;
    config.textures = {"checker"};
    config.texture_size = 512;
    config.sampling.lookups = 2000;
    config.filters = select_footprint_filters(default_footprint_labels());
    const FootprintRun run = run_footprint_bench(&device.context, config);
    int buckets = 0;
    for (const FootprintRow& floor_row : run.rows) {
        // The near-isotropic subset's buckets hold ~35 of these lookups each: too few for a PSNR to mean much
        // (a bucket of flat checker cells reads 79 dB); the full axes partition all 2000.
        if (floor_row.label != config.filters.front().label || floor_row.bucket.axis == "major-isotropic")
            continue;
        double best = -1;
        std::string best_label;
        for (const FootprintRow& r : run.rows)
            if (r.truth == floor_row.truth && r.bucket.name == floor_row.bucket.name && r.bucket.axis == floor_row.bucket.axis &&
                r.psnr > best) {
                best = r.psnr;
                best_label = r.label;
            }
        const std::string what = floor_row.truth + " " + floor_row.bucket.axis + " " + floor_row.bucket.name;
        std::printf("noise-floor: %-24s floor %5.1f dB, best %5.1f dB (%s)\n", what.c_str(), floor_row.floor_psnr,
                    best, best_label.c_str());
        CHECK(floor_row.floor_psnr >= best + 10.0, what + ": floor " + test::show(floor_row.floor_psnr) + ", best " +
                                                       best_label + " " + test::show(best));
        ++buckets;
    }
    CHECK(buckets == 2 * 14, std::to_string(buckets) + " (truth, bucket) pairs: 9 of major axis, 5 of anisotropy");
}
