// Manual filters (GLSL includes) vs the hardware sampler, through `texfilter sample` on random lookups.
// The hardware is allowed exactly what Vulkan lets it round, with the precision bits of the device the
// test runs on (test::test_device_info(); 8 sub-texel and 4 mipmap bits on lavapipe): texel weights to
// subTexelPrecisionBits, and the LOD and level blend to mipmapPrecisionBits (see lod_error). Anything
// beyond that is a bug in one of the two. One test case a filter, texture and wrap.
//
// Formats (--format, every level rounded on the host as the upload stores it): both sides read the same
// stored texels, so the weight bounds are taken from the rounded chain's texel contrast. On top, for 8-bit
// formats, one quantum of the format at the result (1/255 for unorm8, the sRGB code's linear step): a
// device may filter 8-bit texels in 8-bit fixed point and round the result to the format (lavapipe's
// unorm8 path, DESIGN.md section 4). sRGB adds each side's decode allowance (test_formats.cpp: half the
// step between the top two codes; the sampler and texelFetch may decode differently). binary16 is read
// exactly: no extra term.
#include "core/procedural.h"
#include "core/texture_format.h"
#include "texture/image.h"
#include "reference/reference.h"
#include "device_lod.h"
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

const double float_error = 2e-6;

// 2^-subTexelPrecisionBits: "frac(u - shift) ... where the number of fraction bits retained is specified
// by subTexelPrecisionBits" (Vulkan spec, Image Operations, "(u,v,w,a) to (i,j,k,l,n) Transformation");
// the truncation worst case, one whole step.
double sub_texel_step() { return std::ldexp(1.0, -int(test::test_device_info().sub_texel_precision_bits)); }

// How far the hardware's lambda may sit from the one measured for it (device_lod.h), in levels: the spec's
// "Scale Factor Operation, LOD Operation and Image Level(s) Selection" says "The LOD must be computed with
// mipmapPrecisionBits of accuracy" (one step, 2^-mipmapPrecisionBits) and that the blend fraction delta is
// "quantized to the number of mipmap precision bits" (one more step, truncation worst case). The scale factor
// is the device's own: Vulkan lets it approximate rho (max(|m_ux|, |m_vx|) <= f_x <= sqrt(2)(|m_ux| + |m_vx|)),
// so its lambda is measured on mipcolors at the same lookups and checked against those bounds
// (test::device_lods), and the manual filter, which takes the exact rho, may differ by what trilinear changes
// between the two.
double lod_error() { return 2.0 * std::ldexp(1.0, -int(test::test_device_info().mipmap_precision_bits)); }


std::vector<glm::dvec4> sample_colors(const std::string& texture, const std::string& filter, const std::string& wrap,
                                      const std::string& lookups, TextureFormat format = TextureFormat::rgba32f)
{
    const std::string flags =
        "--texture " + texture + " --filter " + filter + " --wrap " + wrap + " --format " + to_string(format);
    return test::run_sample(flags, lookups, false).colors;
}

// What the format adds to |manual - hardware| at a result of `value` (see the top of the file).
double format_allowance(TextureFormat format, const glm::dvec4& value)
{
    const FormatInfo& info = format_info(format);
    if (info.bits != 8)
        return 0.0;
    double quantum = 0;
    for (int c = 0; c < info.channels; ++c)
        quantum = std::max(quantum, format_quantum(format, std::clamp(value[c], 0.0, 1.0)));
    const double decode = info.srgb ? 2 * 0.5 * (1.0 - double(srgb8_decode_table()[254])) : 0.0;
    return quantum + decode;
}

// The procedural chain as the upload stores it in `format`.
MipChain stored_chain(const std::string& texture, TextureFormat format)
{
    MipChain chain = make_procedural(texture, 256);
    quantise_chain(chain, format);
    return chain;
}

// How far 8-bit weights can move a bilinear lookup: one weight step times the texel differences.
double bilinear_tolerance(const Image& level, double u, double v, Wrap wrap)
{
    double across = 0, down = 0;
    test::texel_contrast(level, u, v, wrap, across, down);
    // A step in alpha moves both rows, a step in beta moves between rows (themselves moved by alpha).
    return sub_texel_step() * (across + down + across) + float_error;
}

struct Tally {
    std::string name;
    int checked = 0, over = 0;
    double worst_ratio = 0;
    std::string worst; // the worst lookup: index, both colours, the tolerance
    void add(double error, double tolerance, size_t index, const glm::dvec4& manual, const glm::dvec4& hw)
    {
        ++checked;
        if (error / tolerance > worst_ratio)
            worst = "lookup " + std::to_string(index) + ": manual " + test::show(manual) + " hardware " + test::show(hw) +
                    " tolerance " + test::show(tolerance);
        worst_ratio = std::max(worst_ratio, error / tolerance);
        if (error > tolerance)
            ++over;
    }
    void report()
    {
        std::printf("%-44s %5d lookups, worst error/tolerance %.3f, %d over -> %s\n", name.c_str(), checked,
                    worst_ratio, over, over ? "FAIL" : "PASS");
        CHECK(over == 0 && checked > 0, name + "; worst " + worst);
    }
};

// The lookups every case samples (written once a process): footprints from 1/16 texel to 512 texels, up
// to 4:1. The reference sees the float-rounded values the GPU sees.
const std::vector<Lookup>& all_lookups()
{
    static const std::vector<Lookup> all =
        test::as_float(test::random_footprint_lookups(4096, 2026, {.octave_max = 9.0, .max_stretch = 2.0}));
    return all;
}

const std::string& lookups_path()
{
    static const std::string path = [] {
        const std::string p = (test::work_dir() / "lookups.csv").string();
        test::write_lookups_csv(p, all_lookups());
        return p;
    }();
    return path;
}

// nearest: identical except where the texel coordinate sits within one sub-texel step of an edge.
void compare_nearest(const std::string& texture, Wrap wrap)
{
    const std::string w = to_string(wrap), path = lookups_path();
    const std::vector<Lookup>& lookups = all_lookups();
    {
        auto manual = sample_colors(texture, "nearest", w, path), hw = sample_colors(texture, "hw-nearest", w, path);
        Tally tally{"nearest vs hw-nearest (" + texture + ", " + w + ")"};
        for (size_t i = 0; i < lookups.size(); ++i) {
            double fx = lookups[i].u * 256.0, fy = lookups[i].v * 256.0;
            double edge = std::min(std::abs(fx - std::round(fx)), std::abs(fy - std::round(fy)));
            if (edge > sub_texel_step())
                tally.add(max_channel_diff(manual[i], hw[i]), float_error, i, manual[i], hw[i]);
        }
        tally.report();
    }
}

// bilinear: level 0 only on both sides.
void compare_bilinear(const std::string& texture, Wrap wrap, TextureFormat format = TextureFormat::rgba32f)
{
    const std::string w = to_string(wrap), path = lookups_path();
    const std::vector<Lookup>& lookups = all_lookups();
    const MipChain chain = stored_chain(texture, format);
    {
        auto manual = sample_colors(texture, "bilinear", w, path, format),
             hw = sample_colors(texture, "hw-bilinear", w, path, format);
        Tally tally{"bilinear vs hw-bilinear (" + texture + ", " + w + ", " + to_string(format) + ")"};
        for (size_t i = 0; i < lookups.size(); ++i)
            tally.add(max_channel_diff(manual[i], hw[i]),
                      bilinear_tolerance(chain.levels[0], lookups[i].u, lookups[i].v, wrap) +
                          format_allowance(format, manual[i]),
                      i, manual[i], hw[i]);
        tally.report();
    }
}

// The device's lambda at every lookup (measured once a process; test::device_lods checks it against Vulkan's
// bounds).
const std::vector<double>& hardware_lods()
{
    static const std::vector<double> lods = [] {
        return test::device_lods(lookups_path(), all_lookups(), 256);
    }();
    return lods;
}

// trilinear: the manual filter at the exact lambda, the hardware at its own (measured, +- e); trilinear is
// piecewise linear in lambda, so its extremes between the two are at the ends or at whole levels in between.
void compare_trilinear(const std::string& texture, Wrap wrap, TextureFormat format = TextureFormat::rgba32f)
{
    const std::string w = to_string(wrap), path = lookups_path();
    const std::vector<Lookup>& lookups = all_lookups();
    const MipChain chain = stored_chain(texture, format);
    SamplerOptions options;
    options.wrap = wrap;
    const double lod_error = ::lod_error();
    {
        auto manual = sample_colors(texture, "trilinear", w, path, format),
             hw = sample_colors(texture, "hw-trilinear", w, path, format);
        Tally tally{"trilinear vs hw-trilinear (" + texture + ", " + w + ", " + to_string(format) + ")"};
        int top = int(chain.levels.size()) - 1;
        const std::vector<double>& device = hardware_lods();
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
            const std::vector<double> probes = test::lod_probes(lambda, device[i], lod_error);
            for (double d : probes)
                spread = std::max(spread, max_channel_diff(at(d), centre));
            for (int level = std::max(0, int(probes[0])); level <= std::min(top, int(probes[1]) + 1); ++level)
                weights = std::max(weights, bilinear_tolerance(chain.levels[size_t(level)], l.u, l.v, wrap));
            tally.add(max_channel_diff(manual[i], hw[i]), spread + weights + format_allowance(format, manual[i]), i,
                      manual[i], hw[i]);
        }
        tally.report();
    }
}

} // namespace

TEST_SUITE_BEGIN("gpu");
TEST_CASE("nearest-noise-repeat") { compare_nearest("noise", Wrap::repeat); }
TEST_CASE("nearest-checker-clamp") { compare_nearest("checker", Wrap::clamp); }
TEST_CASE("nearest-zoneplate-mirror") { compare_nearest("zoneplate", Wrap::mirror); }
TEST_CASE("bilinear-noise-repeat") { compare_bilinear("noise", Wrap::repeat); }
TEST_CASE("bilinear-checker-clamp") { compare_bilinear("checker", Wrap::clamp); }
TEST_CASE("bilinear-zoneplate-mirror") { compare_bilinear("zoneplate", Wrap::mirror); }
TEST_CASE("trilinear-noise-repeat") { compare_trilinear("noise", Wrap::repeat); }
TEST_CASE("trilinear-checker-clamp") { compare_trilinear("checker", Wrap::clamp); }
TEST_CASE("trilinear-zoneplate-mirror") { compare_trilinear("zoneplate", Wrap::mirror); }
// The stored formats (--format): 8-bit and binary16.
TEST_CASE("bilinear-noise-repeat-rgba8") { compare_bilinear("noise", Wrap::repeat, TextureFormat::rgba8); }
TEST_CASE("bilinear-noise-repeat-rgba8-srgb") { compare_bilinear("noise", Wrap::repeat, TextureFormat::rgba8_srgb); }
TEST_CASE("bilinear-checker-clamp-r8") { compare_bilinear("checker", Wrap::clamp, TextureFormat::r8); }
TEST_CASE("bilinear-zoneplate-mirror-rgba16f") { compare_bilinear("zoneplate", Wrap::mirror, TextureFormat::rgba16f); }
TEST_CASE("bilinear-noise-repeat-r16f") { compare_bilinear("noise", Wrap::repeat, TextureFormat::r16f); }
TEST_CASE("trilinear-zoneplate-mirror-rgba8-srgb") { compare_trilinear("zoneplate", Wrap::mirror, TextureFormat::rgba8_srgb); }
TEST_CASE("trilinear-noise-repeat-rgba8") { compare_trilinear("noise", Wrap::repeat, TextureFormat::rgba8); }
TEST_CASE("trilinear-noise-repeat-rgba16f") { compare_trilinear("noise", Wrap::repeat, TextureFormat::rgba16f); }
TEST_SUITE_END();
