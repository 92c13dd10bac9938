// `texfilter sample` on the device against the CPU reference (host/reference/resources.h: the lookup's layer
// or bindless texture chosen as the harness does; PCF compares the depth texels BEFORE filtering).
//
// Bounds, per lookup:
// - manual forms (texelFetch): float rounding. The shader works in float on float input: a result is a
//   normalised sum of n taps (n = the lookup's fetches + hardware lookups, from --stats) of values in
//   [0, 1], each adding one ulp, plus 16 ulp for the LOD, blend and normalisation (2n + 16 ulp; EWA's
//   weights add 2.5 (3 + 6 alpha R^2) ulp, as tests/test_ewa.cpp derives). Where the result jumps under a
//   tiny change of the footprint (a level edge, an aniso probe count, a texel at the EWA support's edge:
//   float lambda or ratio on the other side), the reference's own spread under the footprint scaled by
//   1 ± 1e-5 (both columns, and each column alone: lambda and the axis ratio move by ~1.4e-5, far more than
//   float's 1e-7) is allowed on top. aniso and ewa also place their taps in float (probe k at
//   uv + t_k axis; EWA's texel offsets from uv): 2 roundings of ulp(max(|u|, |v|) + 1) in uv, times the
//   level-0 side in texels, move a bilinear tap by that much, i.e. its value by that times
//   (across + down) <= 2 adjacent: 4 2^-24 (max(|u|, |v|) + 1) size adjacent. The cubics (bspline,
//   catmull-rom: 16 fetches, Catmull-Rom's weights negative at the edges, |weights| summing to <= 1.6) round
//   their texel coordinate x = u w - 1/2 twice in float (2 ulp of |x| + 1/2), which moves the weights by that
//   times sum |k'| <= 2 an axis (tests/test_bicubic.cpp derives it): 8 2^-24 (max(|u|, |v|) w + 1) for
//   texels in [0, 1]; their weighted sum's roundings are inside 2n + 16 ulp (n = 16: 48; test_bicubic allows 32).
// - hardware taps (--taps hardware): the sampler's rounding on top: bilinear weights to
//   subTexelPrecisionBits (a step 2^-s in each of alpha and beta: 2^-s (across + down) <= 2 2^-s adjacent,
//   plus one more step as tests/test_hw_vs_manual.cpp allows: 3 2^-s adjacent), a tap's float texel
//   position (2 2^-14 adjacent, as test_ewa), and for aniso's trilinear probes at an explicit LOD the level
//   blend quantised to mipmapPrecisionBits (2^-m times the largest difference between two levels' values,
//   <= 1 for [0, 1] data; for ewa-fast, whose lookups are such probes on one LOD, 2^-m times the lookup's own
//   difference between its layout on floor(λ) and floor(λ) + 1). adjacent = the largest difference of neighbouring texels on any level. The cubics'
//   hardware taps (bilinear taps at merged positions, tests/test_bicubic.cpp derives it): each tap's fraction
//   rounds to a step s = 2^-subTexelPrecisionBits an axis, 2 s times the 4x4 block's range (<= level 0's) times
//   each axis's sum of |tap weights| at the lookup's fraction (B-spline 1, Catmull-Rom up to 1.25).
#include "sample_checks.h"

#include "core/procedural.h"
#include "core/resource_textures.h"
#include "reference/render.h"
#include "reference/resources.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tf::test::sample {

namespace {

constexpr double kUlp = 1.0 / 16777216.0; // 2^-24
constexpr double kSupport = 2.0;         // TF_EWA_SUPPORT (R^2)


std::vector<Lookup> scaled(std::vector<Lookup> ls, double x, double y)
{
    for (Lookup& l : ls) {
        l.dudx *= x, l.dvdx *= x;
        l.dudy *= y, l.dvdy *= y;
    }
    return ls;
}

// Largest neighbouring-texel difference on any level of any chain (wrapped).
double adjacent_difference(const std::vector<MipChain>& chains, Wrap wrap)
{
    double d = 0;
    for (const MipChain& chain : chains)
        for (const Image& img : chain.levels)
            for (int y = 0; y < img.height; ++y)
                for (int x = 0; x < img.width; ++x) {
                    const glm::dvec4 t(img.at(x, y));
                    d = std::max({d, max_channel_diff(t, glm::dvec4(img.at(wrap_texel(x + 1, img.width, wrap), y))),
                                  max_channel_diff(t, glm::dvec4(img.at(x, wrap_texel(y + 1, img.height, wrap))))});
                }
    return d;
}

// Largest difference between two texels of level 0 of any chain, any channel.
double level0_range(const std::vector<MipChain>& chains)
{
    double range = 0;
    for (const MipChain& chain : chains) {
        glm::dvec4 lo(1e300), hi(-1e300);
        const Image& img = chain.levels.at(0);
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x)
                lo = glm::min(lo, glm::dvec4(img.at(x, y))), hi = glm::max(hi, glm::dvec4(img.at(x, y)));
        range = std::max(range, max_channel_diff(hi, lo));
    }
    return range;
}

struct Outcome {
    std::vector<glm::dvec4> reference;
    std::vector<double> bound;
};

// The reference for c's lookups and the bound of each (see the top).
Outcome reference_and_bounds(const Case& c, const std::vector<MipChain>& chains, const test::SampleResult& gpu)
{
    const std::vector<Lookup>& ls = lookups();
    Outcome o;
    o.reference = reference_sample_resource(chains, ls, c.options, c.resource);
    std::vector<double> spread(ls.size(), 0.0);
    for (auto [x, y] : {std::pair{1 + 1e-5, 1 + 1e-5}, {1 - 1e-5, 1 - 1e-5}, {1 + 1e-5, 1.0}, {1 - 1e-5, 1.0},
                        {1.0, 1 + 1e-5}, {1.0, 1 - 1e-5}}) {
        const auto moved = reference_sample_resource(chains, scaled(ls, x, y), c.options, c.resource);
        for (size_t i = 0; i < ls.size(); ++i)
            spread[i] = std::max(spread[i], max_channel_diff(moved[i], o.reference[i]));
    }
    const bool ewa = c.options.filter == Filter::ewa, hardware_taps = c.options.taps == Taps::hardware;
    const double weights = ewa ? 2.5 * (3 + 6 * double(c.options.alpha) * kSupport) : 0.0;
    double sampler = 0;
    const bool fast = c.options.filter == Filter::ewa_fast; // hardware trilinear lookups only, as aniso's taps
    if ((hardware_taps && (ewa || c.options.filter == Filter::aniso)) || fast) {
        sampler = (3 * sub_texel_step() + 2 * std::exp2(-14)) * adjacent_difference(chains, c.options.wrap);
        if (!ewa && !fast)
            sampler += mipmap_step(); // the probes' level blend; values in [0, 1]
    }
    const bool float_taps = ewa || c.options.filter == Filter::aniso || fast;
    const bool cubic = c.options.filter == Filter::bspline || c.options.filter == Filter::catmull_rom;
    const Reconstruction kernel =
        c.options.filter == Filter::bspline ? Reconstruction::bspline : Reconstruction::catmull_rom;
    auto tap_weight_sum = [&](double x) { // one axis's sum of |tap weights| at texel coordinate x
        const double t = x - std::floor(x);
        double sum = 0;
        for (int i = -1; i <= 2; ++i)
            sum += std::abs(cubic_kernel(t - i, kernel));
        return sum;
    };
    const double cubic_range = cubic && hardware_taps ? level0_range(chains) : 0.0;
    const double adjacent = float_taps ? adjacent_difference(chains, c.options.wrap) : 0.0;
    for (size_t i = 0; i < ls.size(); ++i) {
        const double n = gpu.stats[i].texel_fetches + gpu.stats[i].hardware_lookups;
        const double uv = std::max(std::abs(ls[i].u), std::abs(ls[i].v));
        double position = float_taps ? 4 * kUlp * (uv + 1) * kSize * adjacent : 0.0;
        if (cubic) // texel coordinate x = u w - 1/2: 2 roundings, times sum |k'| <= 4, texels in [0, 1]
            position = 8 * kUlp * (uv * kSize + 1);
        double taps = sampler;
        if (cubic && hardware_taps)
            taps = 2 * sub_texel_step() * cubic_range * tap_weight_sum(double(ls[i].u) * kSize - 0.5) *
                   tap_weight_sum(double(ls[i].v) * kSize - 0.5);
        if (fast) { // the probes' level blend, 2^-m times this lookup's own difference between its two levels
            EwaFastProbes lo = reference_ewa_fast_probes(chains.at(0), c.options, ls[i]), hi = lo;
            lo.lod = std::floor(lo.lod), hi.lod = lo.lod + 1;
            taps += mipmap_step() * max_channel_diff(reference_ewa_fast_layout(chains[0], c.options, ls[i], lo),
                                                     reference_ewa_fast_layout(chains[0], c.options, ls[i], hi));
        }
        o.bound.push_back(spread[i] + (16 + 2 * n + weights) * kUlp + position + taps);
    }
    return o;
}

std::string filter_flags(const SamplerOptions& o)
{
    std::string f = "--filter " + to_string(o.filter);
    if (takes_taps(o.filter))
        f += " --taps " + to_string(o.taps);
    return f;
}

} // namespace

const std::vector<Lookup>& lookups()
{
    static const std::vector<Lookup> all = as_float(random_footprint_lookups(
        256, 1313, {.octave_min = -2.0, .octave_max = 6.0, .max_stretch = 2.0, .texture_size = double(kSize)}));
    return all;
}

const std::string& lookups_path()
{
    static const std::string path = [] {
        const std::string p = (test::work_dir() / "lookups.csv").string();
        write_lookups_csv(p, lookups());
        return p;
    }();
    return path;
}

double sub_texel_step() { return std::ldexp(1.0, -int(test_device_info().sub_texel_precision_bits)); }
double mipmap_step() { return std::ldexp(1.0, -int(test_device_info().mipmap_precision_bits)); }

std::string resource_flags(const ResourceOptions& r)
{
    std::string f = " --resource " + to_string(r.resource);
    if (is_layered(r.resource))
        f += " --layers " + std::to_string(r.layers) + " --layer " + std::to_string(r.layer);
    if (r.resource == Resource::shadow)
        f += " --compare " + to_string(r.compare) + " --dref " + test::show(double(r.dref));
    return f;
}

test::SampleResult gpu_run(const Case& c)
{
    const std::string path = lookups_path();
    return test::run_sample("--texture " + c.texture + " --texture-size " + std::to_string(kSize) + " --wrap " +
                                to_string(c.options.wrap) + " " + c.flags + resource_flags(c.resource),
                            path, true);
}

std::vector<MipChain> chains_of(const Case& c) { return make_resource_chains(make_procedural(c.texture, kSize), c.resource); }

// GPU vs reference within the bound on every lookup; `wrong` (when given): what a wrong layer / index / an
// unfiltered comparison would give, which must be further than the bound on at least `min_caught` of them.
void check_case(const Case& c, const std::vector<std::vector<glm::dvec4>>& wrongs, double min_caught)
{
    const test::SampleResult gpu = gpu_run(c);
    const std::vector<MipChain> chains = chains_of(c);
    const Outcome o = reference_and_bounds(c, chains, gpu);
    const std::string name = c.flags + resource_flags(c.resource);
    CHECK(gpu.colors.size() == lookups().size(), name);
    if (gpu.colors.size() != lookups().size())
        return;
    test::limit_failure_lines(8);
    double worst = 0;
    for (size_t i = 0; i < gpu.colors.size(); ++i) {
        const double error = max_channel_diff(gpu.colors[i], o.reference[i]);
        worst = std::max(worst, error / o.bound[i]);
        CHECK(error <= o.bound[i], name + ": lookup " + std::to_string(i) + " GPU " + test::show(gpu.colors[i]) +
                                       " reference " + test::show(o.reference[i]) + " bound " + test::show(o.bound[i]));
    }
    std::printf("%-90s worst error/bound %.3f\n", name.c_str(), worst);
    for (const auto& wrong : wrongs) {
        size_t caught = 0;
        for (size_t i = 0; i < wrong.size(); ++i)
            caught += max_channel_diff(wrong[i], o.reference[i]) > 2 * o.bound[i];
        const double fraction = double(caught) / double(wrong.size());
        std::printf("%-90s a wrong texture is caught on %.0f %% of the lookups\n", "", 100 * fraction);
        CHECK(fraction >= min_caught, name + ": a wrong texture differs from the right one beyond the bound on " +
                                          test::show(fraction) + " of the lookups");
    }
}

Case make_case(Resource resource, Filter filter, Taps taps, int layers, int layer, Wrap wrap)
{
    Case c;
    c.options.filter = filter;
    c.options.taps = taps;
    c.options.wrap = wrap;
    c.flags = filter_flags(c.options);
    c.resource.resource = resource;
    c.resource.layers = layers;
    c.resource.layer = layer;
    return c;
}

// sample --stochastic: row i draws the numbers of pixel (0, 0), lookup i, on the device and the reference of
// the case's kind, so they pick the same texels except where xi lies within float rounding of a weight
// boundary: at most 1 % of the rows may differ by more than 1e-5 (the cap test_stochastic.cpp sample-backends
// uses). It can fail: at least a quarter of the rows must be off the deterministic filter (the estimate is
// noisy: it really is the stochastic form), and on a layered kind a reference that read another texture must
// differ on most rows, as must one that drew another row's numbers (the row order of a bindless batch, which
// reads its lookups' textures in groups, kept).
void check_stochastic(Case c)
{
    const Resource resource = c.resource.resource;
    c.options.stochastic = true;
    c.options.noise = Noise::white;
    c.options.accumulate = 8;
    c.flags += " --stochastic white --accumulate 8";
    const test::SampleResult gpu = gpu_run(c);
    const std::vector<MipChain> chains = chains_of(c);
    const std::vector<Lookup>& ls = lookups();
    const std::vector<glm::dvec4> cpu = reference_sample_resource(chains, ls, c.options, c.resource);
    SamplerOptions deterministic = c.options;
    deterministic.stochastic = false;
    const std::vector<glm::dvec4> exact = reference_sample_resource(chains, ls, deterministic, c.resource);
    const std::string name = c.flags + resource_flags(c.resource);
    CHECK(gpu.colors.size() == ls.size(), name);
    if (gpu.colors.size() != ls.size())
        return;
    auto share = [&](const std::vector<glm::dvec4>& a, const std::vector<glm::dvec4>& b, double tolerance) {
        size_t n = 0;
        for (size_t i = 0; i < ls.size(); ++i)
            n += max_channel_diff(a[i], b[i]) > tolerance ? 1 : 0;
        return double(n) / double(ls.size());
    };
    const double differ = share(gpu.colors, cpu, 1e-5), noisy = share(cpu, exact, 1e-3);
    std::printf("%-90s rows differing %.4f, off the deterministic filter %.3f\n", name.c_str(), differ, noisy);
    CHECK(differ <= 0.01, name + ": share of rows where device and reference differ: " + test::show(differ));
    CHECK(noisy >= 0.25, name + ": share of rows off the deterministic filter (noise is there): " + test::show(noisy));
    if (is_layered(resource)) {
        ResourceOptions other = c.resource;
        if (resource == Resource::bindless)
            other.layer = (c.resource.layer + 1) % c.resource.layers;
        else
            other.layer = c.resource.layer == 0 ? 1 : 0;
        const double caught = share(gpu.colors, reference_sample_resource(chains, ls, c.options, other), 1e-5);
        CHECK(caught >= 0.5, name + ": a reference on other textures differs on only " + test::show(caught));
    }
    SamplerOptions shifted = c.options; // the same lookups drawing the next frames' numbers
    shifted.stochastic_first = 8;
    const double reseeded = share(gpu.colors, reference_sample_resource(chains, ls, shifted, c.resource), 1e-5);
    CHECK(reseeded >= 0.25, name + ": other random numbers change only " + test::show(reseeded) + " of the rows");
}

} // namespace tf::test::sample
