// Every resource kind through `texfilter sample --resource` (array, separate-array, separate, bindless,
// shadow) on the GPU against the CPU reference (host/reference/resources.h: the lookup's layer or bindless
// texture chosen as the harness does; PCF compares the depth texels BEFORE filtering), and percentage-closer
// filtering by hand (bilinear, trilinear on the shadow resource) against the hardware comparison sampler
// (hw-bilinear, hw-trilinear through sampler2DShadow) on the same lookups.
//
// Bounds, per lookup: tests/sample_checks.cpp derives them (float rounding of the manual forms, the sampler's
// sub-texel and mipmap precision for hardware taps, the reference's own spread at level edges).
// Each layered check also asserts that it can fail: on most lookups the right texture's result is further
// from the one a wrong layer / index would give than the bound (distinct layer content).
#include "core/procedural.h"
#include "core/resource.h"
#include "core/resource_textures.h"
#include "reference/reference.h"
#include "reference/render.h"
#include "reference/resources.h"
#include "reference/stochastic.h"
#include "device_lod.h"
#include "sample_checks.h"
#include "support.h"
#include "vulkan/textures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/glm.hpp>

using namespace tf;
using tf::test::max_channel_diff;
using namespace tf::test::sample;

namespace {

// What the test device offers for the kinds lavapipe 22.3 lacks: non-uniform indexing of sampled-image
// arrays (bindless), linear filtering of D32_SFLOAT (the hardware's bilinear/trilinear comparison). A
// case that needs one prints SKIP where it is missing (and runs on a device that has it).
bool has_bindless() { return test::test_device_info().sampled_image_array_non_uniform_indexing; }
bool has_linear_depth()
{
    static const bool linear = [] {
        VulkanContext context = create_context(test::test_context_options());
        bool ok = true;
        try {
            check_shadow_format(context, true);
        } catch (const Error&) {
            ok = false;
        }
        destroy_context(context);
        return ok;
    }();
    return linear;
}
bool skip(bool missing, const std::string& what)
{
    if (missing)
        std::printf("SKIP: %s lacks %s\n", test::test_device_info().name.c_str(), what.c_str());
    return missing;
}

// The reference as if every lookup read texture `index` of the case's chains.
std::vector<glm::dvec4> reference_on(const Case& c, int index)
{
    ResourceOptions one = c.resource;
    one.resource = Resource::array; // every lookup on one clamped layer
    one.layer = index;
    return reference_sample_resource(chains_of(c), lookups(), c.options, one);
}

// An array case: checked against the reference, and a wrong layer (layer 0, the texture itself, and the
// neighbour) must be caught.
void check_array(Resource resource, Filter filter, Taps taps, int layer, Wrap wrap = Wrap::repeat)
{
    const Case c = make_case(resource, filter, taps, 4, layer, wrap);
    const int read = std::clamp(layer, 0, 3);
    check_case(c, {reference_on(c, read == 0 ? 1 : 0), reference_on(c, read == 3 ? 2 : read + 1)});
}

// The bindless case: lookup i reads (first + i) % count. A shader that read `first` for every lookup (the
// index made uniform) or texture 0 gets caught on the lookups where those differ (3 in 4 of them).
void check_bindless(Filter filter, Taps taps)
{
    if (skip(!has_bindless(), "shaderSampledImageArrayNonUniformIndexing (bindless)"))
        return;
    const Case c = make_case(Resource::bindless, filter, taps, 4, 1);
    check_case(c, {reference_on(c, 1), reference_on(c, 0)}, 0.65);
}

// The depth chain filtered without any comparison (the depth itself, in .r).
std::vector<glm::dvec4> reference_sample_all_depth(const MipChain& depth, const Case& c)
{
    return reference_sample_all(depth, lookups(), c.options);
}

// A shadow case: against the PCF reference; comparing the filtered depth instead (compare AFTER
// filtering: a 0/1 answer) must be caught where the lookup sees an edge (not for the nearest families,
// where one texel is read and the two orders agree).
void check_shadow(Filter filter, Taps taps, CompareOp op = CompareOp::less_or_equal, float dref = 0.5f)
{
    if (taps == Taps::hardware && skip(!has_linear_depth(), "linear filtering of VK_FORMAT_D32_SFLOAT"))
        return;
    Case c = make_case(Resource::shadow, filter, taps);
    c.resource.compare = op;
    c.resource.dref = dref;
    const std::vector<MipChain> depth = chains_of(c);
    const std::vector<glm::dvec4> filtered = reference_sample_all_depth(depth[0], c);
    std::vector<glm::dvec4> after(filtered.size());
    for (size_t i = 0; i < filtered.size(); ++i)
        after[i] = glm::dvec4(compare_depth(op, double(dref), filtered[i].r));
    const bool one_texel = filter == Filter::nearest || filter == Filter::nearest_mip;
    check_case(c, one_texel ? std::vector<std::vector<glm::dvec4>>{} : std::vector<std::vector<glm::dvec4>>{after}, 0.3);
}

// PCF by hand vs the hardware comparison sampler, the same lookups on the shadow resource.
//
// The bound. A hardware comparison lookup compares each texel it reads with dref first (Vulkan, "Depth
// Compare Operation": t = 1 when dref OP D, else 0; exact here: D32 float texels against a float dref,
// the same comparison the shader makes) and then filters the 0/1 values t. Bilinear on one level is
// f(a, b) = (1-a)(1-b) t00 + a(1-b) t10 + (1-a) b t01 + a b t11 with the fractions a, b of the texel
// coordinate; the sampler keeps subTexelPrecisionBits s of them (Vulkan, "(u,v,w,a) to (i,j,k,l,n)
// Transformation"), so a', b' are within one step 2^-s of a, b (truncation's worst case). f is linear in
// each fraction with slope df/da = (1-b)(t10 - t00) + b(t11 - t01), a convex combination of the two rows'
// differences, so |df/da| <= across = max(|t10 - t00|, |t11 - t01|) (0 or 1: these are 0/1 terms), and
// likewise |df/db| <= down; hence |f(a', b') - f(a, b)| <= 2^-s (across + down) <= 2 2^-s. Plus float
// rounding of the weights and the sum (2e-6). A quantised fraction that crosses a texel edge (a' = 1 on
// texel i0 is a = 0 on i0 + 1) gives the same f: bilinear is continuous there.
// Trilinear: the hardware's lambda is within 2 2^-m of the exact one (mipmapPrecisionBits m: the LOD's
// accuracy and the blend fraction's quantisation, one step each, as tests/test_hw_vs_manual.cpp allows);
// trilinear of the 0/1 chain is piecewise linear in lambda, so the manual result may differ by its spread
// over [lambda - e, lambda + e] (the ends and whole levels between), plus the bilinear bound above on
// every level in that range.
double pcf_bilinear_bound(const Image& level, double u, double v, Wrap wrap)
{
    double across = 0, down = 0;
    test::texel_contrast(level, u, v, wrap, across, down);
    return sub_texel_step() * (across + down) + 2e-6;
}

void check_pcf_hardware(Filter hw, Filter manual)
{
    if (hw != Filter::hw_nearest && skip(!has_linear_depth(), "linear filtering of VK_FORMAT_D32_SFLOAT"))
        return;
    const Case m = make_case(Resource::shadow, manual, Taps::manual), h = make_case(Resource::shadow, hw, Taps::manual);
    const test::SampleResult by_hand = gpu_run(m), hardware = gpu_run(h);
    const std::vector<Lookup>& ls = lookups();
    CHECK(by_hand.colors.size() == ls.size() && hardware.colors.size() == ls.size(), "row counts");
    if (by_hand.colors.size() != ls.size() || hardware.colors.size() != ls.size())
        return;
    const MipChain lit = compare_chain(chains_of(m)[0], m.resource.compare, double(m.resource.dref));
    const int top = int(lit.levels.size()) - 1;
    const double e = 2 * mipmap_step();
    const std::vector<double> device_lods =
        manual == Filter::trilinear ? test::device_lods(lookups_path(), ls, kSize) : std::vector<double>();
    test::limit_failure_lines(8);
    double worst = 0;
    int partial = 0;
    for (size_t i = 0; i < ls.size(); ++i) {
        const Lookup& l = ls[i];
        double bound = 0;
        if (manual == Filter::nearest) {
            // The same texel but where the texel coordinate lies within one sub-texel step of an edge
            // (the hardware's rounded coordinate may pick the neighbour): such lookups are skipped.
            const double fx = l.u * kSize, fy = l.v * kSize;
            if (std::min(std::abs(fx - std::round(fx)), std::abs(fy - std::round(fy))) <= sub_texel_step())
                continue;
            bound = 2e-6;
        } else if (manual == Filter::bilinear) {
            bound = pcf_bilinear_bound(lit.levels[0], l.u, l.v, m.options.wrap);
        } else {
            // The manual filter at the exact lambda, the hardware at its own (measured on mipcolors, Vulkan's
            // scale-factor bounds checked there: device_lod.h), +- e.
            const double lambda = std::clamp(reference_lod(lit, l, m.options), 0.0, double(top));
            const glm::dvec4 centre = reference_trilinear_at(lit, lambda, l.u, l.v, m.options.wrap);
            double spread = 0, weights = 0;
            const std::vector<double> probes = test::lod_probes(lambda, device_lods[i], e);
            for (double d : probes)
                spread = std::max(spread, max_channel_diff(reference_trilinear_at(lit, d, l.u, l.v, m.options.wrap), centre));
            for (int level = std::max(0, int(probes[0])); level <= std::min(top, int(probes[1]) + 1); ++level)
                weights = std::max(weights, pcf_bilinear_bound(lit.levels[size_t(level)], l.u, l.v, m.options.wrap));
            bound = spread + weights;
        }
        const double error = max_channel_diff(by_hand.colors[i], hardware.colors[i]);
        worst = std::max(worst, error / bound);
        // nearest: one texel, 0 or 1; the others: a fraction (an edge inside the footprint)
        partial += manual == Filter::nearest ? by_hand.colors[i].r > 0.5 : by_hand.colors[i].r > 0.01 && by_hand.colors[i].r < 0.99;
        CHECK(error <= bound, to_string(manual) + " vs " + to_string(hw) + ": lookup " + std::to_string(i) + " manual " +
                                  test::show(by_hand.colors[i]) + " hardware " + test::show(hardware.colors[i]) +
                                  " bound " + test::show(bound));
    }
    std::printf("PCF %s vs %s: worst error/bound %.3f, %d of %zu lookups partly lit\n", to_string(manual).c_str(),
                to_string(hw).c_str(), worst, partial, ls.size());
    // The lookups must see shadow edges (nearest: lit and unlit texels), or the comparison says little.
    CHECK(partial >= int(ls.size()) / 5 && (manual != Filter::nearest || partial <= int(ls.size()) * 4 / 5),
          std::to_string(partial) + " lookups partly lit (nearest: lit)");
}

// sample --stochastic on a resource kind (sample_checks.h).
void check_stochastic(Resource resource, Filter filter, int layers = 4, int layer = 2)
{
    if (resource == Resource::bindless && skip(!has_bindless(), "shaderSampledImageArrayNonUniformIndexing (bindless)"))
        return;
    tf::test::sample::check_stochastic(make_case(resource, filter, Taps::manual, layers, layer));
}

} // namespace

TEST_SUITE_BEGIN("gpu");
TEST_CASE("array-trilinear") { check_array(Resource::array, Filter::trilinear, Taps::manual, 2); }
TEST_CASE("array-ewa") { check_array(Resource::array, Filter::ewa, Taps::manual, 1, Wrap::clamp); }
TEST_CASE("array-aniso-hardware-taps") { check_array(Resource::array, Filter::aniso, Taps::hardware, 3); }
TEST_CASE("array-layer-clamped") { check_array(Resource::array, Filter::bilinear, Taps::manual, 9); }
TEST_CASE("separate-array-trilinear") { check_array(Resource::separate_array, Filter::trilinear, Taps::manual, 1); }
TEST_CASE("separate-array-ewa-hardware-taps") { check_array(Resource::separate_array, Filter::ewa, Taps::hardware, 2); }
TEST_CASE("separate-trilinear") { check_case(make_case(Resource::separate, Filter::trilinear)); }
TEST_CASE("separate-aniso-hardware-taps") { check_case(make_case(Resource::separate, Filter::aniso, Taps::hardware)); }
TEST_CASE("separate-ewa-hardware-taps") { check_case(make_case(Resource::separate, Filter::ewa, Taps::hardware)); }
TEST_CASE("bindless-trilinear") { check_bindless(Filter::trilinear, Taps::manual); }
TEST_CASE("bindless-aniso-hardware-taps") { check_bindless(Filter::aniso, Taps::hardware); }
TEST_CASE("shadow-nearest") { check_shadow(Filter::nearest, Taps::manual); }
TEST_CASE("shadow-bilinear") { check_shadow(Filter::bilinear, Taps::manual); }
TEST_CASE("shadow-nearest-mip") { check_shadow(Filter::nearest_mip, Taps::manual, CompareOp::greater); }
TEST_CASE("shadow-bilinear-mip") { check_shadow(Filter::bilinear_mip, Taps::manual); }
TEST_CASE("shadow-trilinear") { check_shadow(Filter::trilinear, Taps::manual, CompareOp::greater_or_equal, 0.45f); }
TEST_CASE("shadow-brilinear") { check_shadow(Filter::brilinear, Taps::manual); }
TEST_CASE("shadow-aniso") { check_shadow(Filter::aniso, Taps::manual, CompareOp::less); }
TEST_CASE("shadow-aniso-hardware-taps") { check_shadow(Filter::aniso, Taps::hardware); }
TEST_CASE("shadow-ewa") { check_shadow(Filter::ewa, Taps::manual); }
TEST_CASE("shadow-ewa-hardware-taps") { check_shadow(Filter::ewa, Taps::hardware, CompareOp::greater, 0.55f); }
TEST_CASE("pcf-nearest-vs-hw-nearest") { check_pcf_hardware(Filter::hw_nearest, Filter::nearest); }
TEST_CASE("pcf-bilinear-vs-hw-bilinear") { check_pcf_hardware(Filter::hw_bilinear, Filter::bilinear); }
TEST_CASE("pcf-trilinear-vs-hw-trilinear") { check_pcf_hardware(Filter::hw_trilinear, Filter::trilinear); }
TEST_CASE("stochastic-separate-trilinear") { check_stochastic(Resource::separate, Filter::trilinear); }
TEST_CASE("stochastic-array-aniso") { check_stochastic(Resource::array, Filter::aniso); }
TEST_CASE("stochastic-separate-array-bilinear") { check_stochastic(Resource::separate_array, Filter::bilinear, 4, 3); }
TEST_CASE("stochastic-bindless-trilinear") { check_stochastic(Resource::bindless, Filter::trilinear, 4, 1); }
TEST_CASE("stochastic-shadow-trilinear") { check_stochastic(Resource::shadow, Filter::trilinear); }
TEST_CASE("stochastic-shadow-ewa") { check_stochastic(Resource::shadow, Filter::ewa); }

// The bindless reference (CPU only, so it runs where the device has no bindless): its lookups are filtered in
// groups by the texture they read, and lookup i must still draw row i's numbers, as the device's does. Row k
// of a group (the numbering before the fix) would draw other numbers on most rows.
TEST_CASE("stochastic-bindless-reference-rows")
{
    Case c = make_case(Resource::bindless, Filter::trilinear, Taps::manual, 4, 1);
    c.options.stochastic = true;
    c.options.accumulate = 4;
    const std::vector<MipChain> chains = chains_of(c);
    const std::vector<Lookup>& ls = lookups();
    const std::vector<glm::dvec4> grouped = reference_sample_resource(chains, ls, c.options, c.resource);
    size_t wrong = 0, group_numbering = 0;
    std::vector<uint32_t> position(chains.size(), 0); // a lookup's row within its texture's group
    for (size_t i = 0; i < ls.size(); ++i) {
        const size_t t = size_t(texture_index(c.resource, i));
        const glm::dvec4 own = reference_stochastic_mean(chains[t], c.options, ls[i], 0, 0, uint32_t(i));
        const glm::dvec4 in_group = reference_stochastic_mean(chains[t], c.options, ls[i], 0, 0, position[t]++);
        wrong += max_channel_diff(grouped[i], own) > 0.0 ? 1 : 0;
        group_numbering += max_channel_diff(in_group, own) > 1e-5 ? 1 : 0;
    }
    CHECK(wrong == 0, std::to_string(wrong) + " rows do not draw their own row's numbers");
    CHECK(double(group_numbering) / double(ls.size()) >= 0.5,
          "numbering rows within their group changes only " + std::to_string(group_numbering) + " rows");
}
TEST_SUITE_END();
