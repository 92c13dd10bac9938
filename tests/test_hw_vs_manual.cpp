// Manual filters (GLSL includes) vs the hardware sampler, through `texfilter sample` on random lookups.
// The hardware is allowed exactly what Vulkan lets it round: texel weights to subTexelPrecisionBits
// (8 on lavapipe) and the level blend to mipmapPrecisionBits (4), plus lavapipe's approximate log2
// in the LOD (measured ~0.04, DESIGN.md section 4). Anything beyond that is a bug in one of the two.
#include "core/procedural.h"
#include "reference/reference.h"
#include "support.h"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>
#include <glm/glm.hpp>

using namespace tf;
using tf::test::max_channel_diff;

namespace {

const double sub_texel_step = 1.0 / 256.0;      // 2^-subTexelPrecisionBits, truncation worst case
const double lod_error = 1.0 / 16.0 + 0.04;     // 2^-mipmapPrecisionBits + approximate log2
const double float_error = 2e-6;

std::string texfilter;
std::filesystem::path work;

std::vector<glm::dvec4> sample_colors(const std::string& texture, const std::string& filter, const std::string& wrap,
                                      const std::string& lookups)
{
    const std::string flags = "--texture " + texture + " --filter " + filter + " --wrap " + wrap;
    return test::run_sample(texfilter, work, flags, lookups, false).colors;
}

// How far 8-bit weights can move a bilinear lookup: one weight step times the texel differences.
double bilinear_tolerance(const Image& level, double u, double v, Wrap wrap)
{
    double across = 0, down = 0;
    test::texel_contrast(level, u, v, wrap, across, down);
    // A step in alpha moves both rows, a step in beta moves between rows (themselves moved by alpha).
    return sub_texel_step * (across + down + across) + float_error;
}

struct Tally {
    std::string name;
    int checked = 0, over = 0;
    double worst_ratio = 0;
    void add(double error, double tolerance)
    {
        ++checked;
        worst_ratio = std::max(worst_ratio, error / tolerance);
        if (error > tolerance)
            ++over;
    }
    void report()
    {
        std::printf("%-44s %5d lookups, worst error/tolerance %.3f, %d over -> %s\n", name.c_str(), checked,
                    worst_ratio, over, over ? "FAIL" : "PASS");
        CHECK(over == 0 && checked > 0, name);
    }
};

void compare(const std::string& texture, Wrap wrap, const std::vector<Lookup>& lookups, const std::string& path)
{
    std::string w = to_string(wrap);
    MipChain chain = make_procedural(texture, 256);
    SamplerOptions options;
    options.wrap = wrap;

    // nearest: identical except where the texel coordinate sits within one sub-texel step of an edge.
    {
        auto manual = sample_colors(texture, "nearest", w, path), hw = sample_colors(texture, "hw-nearest", w, path);
        Tally tally{"nearest vs hw-nearest (" + texture + ", " + w + ")"};
        for (size_t i = 0; i < lookups.size(); ++i) {
            double fx = lookups[i].u * 256.0, fy = lookups[i].v * 256.0;
            double edge = std::min(std::abs(fx - std::round(fx)), std::abs(fy - std::round(fy)));
            if (edge > sub_texel_step)
                tally.add(max_channel_diff(manual[i], hw[i]), float_error);
        }
        tally.report();
    }
    // bilinear: level 0 only on both sides.
    {
        auto manual = sample_colors(texture, "bilinear", w, path), hw = sample_colors(texture, "hw-bilinear", w, path);
        Tally tally{"bilinear vs hw-bilinear (" + texture + ", " + w + ")"};
        for (size_t i = 0; i < lookups.size(); ++i)
            tally.add(max_channel_diff(manual[i], hw[i]),
                      bilinear_tolerance(chain.levels[0], lookups[i].u, lookups[i].v, wrap));
        tally.report();
    }
    // trilinear: the hardware may sit anywhere in [lambda - e, lambda + e]; trilinear is piecewise
    // linear in lambda, so its extremes there are at the ends or at whole levels in between.
    {
        auto manual = sample_colors(texture, "trilinear", w, path), hw = sample_colors(texture, "hw-trilinear", w, path);
        Tally tally{"trilinear vs hw-trilinear (" + texture + ", " + w + ")"};
        int top = int(chain.levels.size()) - 1;
        for (size_t i = 0; i < lookups.size(); ++i) {
            const Lookup& l = lookups[i];
            double lambda = std::clamp(reference_lod(chain, l, options), 0.0, double(top));
            auto at = [&](double d) {
                d = std::clamp(d, 0.0, double(top));
                int lo = int(std::floor(d));
                int hi = std::min(lo + 1, top);
                double f = d - lo;
                return (1 - f) * reference_bilinear(chain.levels[size_t(lo)], l.u, l.v, wrap) +
                       f * reference_bilinear(chain.levels[size_t(hi)], l.u, l.v, wrap);
            };
            glm::dvec4 centre = at(lambda);
            double spread = 0, weights = 0;
            std::vector<double> probes = {lambda - lod_error, lambda + lod_error};
            for (int k = int(std::ceil(lambda - lod_error)); k <= int(std::floor(lambda + lod_error)); ++k)
                probes.push_back(k);
            for (double d : probes)
                spread = std::max(spread, max_channel_diff(at(d), centre));
            for (int level = std::max(0, int(lambda - lod_error)); level <= std::min(top, int(lambda + lod_error) + 1); ++level)
                weights = std::max(weights, bilinear_tolerance(chain.levels[size_t(level)], l.u, l.v, wrap));
            tally.add(max_channel_diff(manual[i], hw[i]), spread + weights);
        }
        tally.report();
    }
}

} // namespace

int main(int argc, char** argv)
{
    texfilter = test::texfilter_path_from_args(argc, argv, "test_hw_vs_manual PATH/TO/texfilter");
    work = test::make_work_dir("hw-vs-manual");
    // The reference sees the float-rounded values the GPU sees.
    // Footprints from 1/16 texel to 512 texels, up to 4:1.
    const std::vector<Lookup> lookups = test::as_float(test::random_footprint_lookups(4096, 2026, 9.0, 2.0));
    const std::string path = (work / "lookups.csv").string();
    test::write_lookups_csv(path, lookups);
    try {
        compare("noise", Wrap::repeat, lookups, path);
        compare("checker", Wrap::clamp, lookups, path);
        compare("zoneplate", Wrap::mirror, lookups, path);
    } catch (const std::exception& e) {
        test::fail(e.what());
    }
    return test::finish();
}
