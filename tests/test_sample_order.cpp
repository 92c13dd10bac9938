// `texfilter sample` answers a lookup the same whatever the lookups around it, for every hardware
// filter (hw-*) and every hardware-tap form (aniso, ewa --taps hardware), on the device under test.
//
// usage: test_sample_order PATH/TO/texfilter
//
// Why: a sampler may work per 2x2 quad or per SIMD batch. lavapipe's anisotropic filter takes its
// footprint from the quad's uv differences and its level from the batch's first quad, so when
// neighbouring lanes held unrelated lookups the same hw-aniso lookup gave 0.06 or 0.70 by file order.
// The sample pass now gives each hw-* lookup a subgroup of quads whose differences are its gradients
// (shaders/harness/sample.comp.glsl). Checked here: the same probe lookups in several orders in one
// file — as given, reversed, shuffled, and each probe between wildly different neighbours at every
// position modulo 2, 4, 8, 16 and 64 (quad, subgroup, workgroup) — give bit-identical answers (the CSV
// has 9 significant digits: a float round trip). Plus the degenerate inputs' documented answers:
// non-finite uv gives vec4(0); NaN/±Inf and huge (≥ 2^20) gradients give the coarsest level (hw-trilinear,
// hw-aniso; hw-nearest and hw-bilinear read level 0 only), within float rounding of the 1x1 level.
// These run the command (test::run_sample_command), not tf::sample_lookups in process: in a sanitizer build
// UBSan is made fatal for each run, which only a child's environment can set, and the empty file's case
// checks what the command writes.
#include "core/procedural.h"
#include "support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace tf;

namespace {


// Probes: footprints from 1/16 texel to the whole texture, up to 16:1, rotated, uv inside and outside
// [0, 1]; then the degenerate ones.
std::vector<Lookup> probe_lookups(int count, unsigned seed)
{
    return test::as_float(test::random_footprint_lookups(count, seed, {.octave_max = 8.0, .max_stretch = 4.0}));
}

const double nan_ = std::numeric_limits<double>::quiet_NaN(), inf_ = INFINITY;

// What the degenerate probes must give.
enum class Expect { same_only, zero, coarsest };
struct Degenerate {
    Lookup l;
    Expect expect;
    const char* what;
};
const std::vector<Degenerate> degenerate = {
    {{0.3, 0.6, nan_, 0, 0, 0.01}, Expect::coarsest, "NaN gradient"},
    {{0.3, 0.6, inf_, 0, 0, 0.01}, Expect::coarsest, "+Inf gradient"},
    {{0.9, 0.1, -inf_, inf_, inf_, -inf_}, Expect::coarsest, "-Inf/+Inf gradients"},
    {{0.3, 0.6, 1e30, 0, 0, 1e30}, Expect::coarsest, "huge gradients"},
    {{0.3, 0.6, 3e38, -3e38, 3e38, 3e38}, Expect::coarsest, "largest float gradients"},
    {{0.3, 0.6, 1e30, 0, 0, 0}, Expect::coarsest, "huge x, zero y"},
    {{0.7, 0.2, 2e6, 0, 0, 1e-3}, Expect::coarsest, "2e6 x 1e-3"},
    {{0.3, 0.6, 0, 0, 0, 0}, Expect::same_only, "zero gradients"},
    {{0.3, 0.6, 1e-30, 0, 0, 1e-30}, Expect::same_only, "tiny gradients"},
    {{1e30, -1e30, 0.01, 0, 0, 0.01}, Expect::same_only, "huge uv"},
    {{nan_, 0.5, 0.01, 0, 0, 0.01}, Expect::zero, "NaN uv"},
    {{0.5, inf_, 0.01, 0, 0, 0.01}, Expect::zero, "Inf uv"},
    {{-inf_, nan_, nan_, inf_, 0, 0}, Expect::zero, "non-finite everything"},
};

// Neighbours as different from the probes and from each other as lookups get.
std::vector<Lookup> wild_lookups()
{
    return test::as_float(std::vector<Lookup>{
        {0.5, 0.5, 0.9, 0.0, 0.0, 0.9},          // the whole texture
        {37.3, -11.8, 1e-5, 0, 0, 1e-5},          // far away, magnified
        {0.2, 0.8, 0.3, 0.0, 0.0, 0.001},         // 300:1
        {0.1, 0.1, nan_, nan_, nan_, nan_},       // NaN footprint
        {0.7, 0.3, -0.02, 0.05, 0.04, 0.016},     // rotated, moderate
        {nan_, 0.4, 0.01, 0, 0, 0.01},            // NaN uv
        {0.45, 0.55, 1e30, -1e30, 1e30, 1e30},    // huge
        {-0.25, 1.75, 0, 0, 0, 0},                // zero footprint
    });
}

// One file holding every probe many times: blocks [as given][reversed][shuffled][interleaved x 5].
// where[p] lists the rows holding probe p.
std::vector<Lookup> arrange(const std::vector<Lookup>& probes, std::vector<std::vector<size_t>>& where)
{
    const std::vector<Lookup> wild = wild_lookups();
    std::vector<Lookup> rows;
    where.assign(probes.size(), {});
    auto put = [&](size_t p) {
        where[p].push_back(rows.size());
        rows.push_back(probes[p]);
    };
    for (size_t p = 0; p < probes.size(); ++p)
        put(p);
    for (size_t p = probes.size(); p-- > 0;)
        put(p);
    std::vector<size_t> order(probes.size());
    for (size_t p = 0; p < order.size(); ++p)
        order[p] = p;
    std::shuffle(order.begin(), order.end(), std::mt19937(11));
    for (size_t p : order)
        put(p);
    // Each probe after `gap` wild neighbours (a different one each time), so that it falls on every lane
    // of a quad, every quad of an 8- or 32-wide batch and both halves of a workgroup.
    int w = 0;
    for (int gap : {1, 3, 6, 13, 50}) {
        for (size_t p : order) {
            for (int k = 0; k < gap; ++k)
                rows.push_back(wild[size_t(w++) % wild.size()]);
            put(p);
        }
    }
    return rows;
}

bool same_bits(const glm::dvec4& a, const glm::dvec4& b)
{
    for (int c = 0; c < 4; ++c)
        if (!(a[c] == b[c] || (std::isnan(a[c]) && std::isnan(b[c]))))
            return false;
    return true;
}

struct Case {
    std::string filter; // flags after --filter
    bool level_zero_only; // hw-nearest, hw-bilinear: no MIP levels
    bool hardware_sampler; // an hw-* filter: degenerate gradients are the harness's to define
};

// One filter form on the random probes plus the degenerate ones, in every placement.
void check_orders(const Case& c)
{
    setenv("UBSAN_OPTIONS", "halt_on_error=1:print_stacktrace=1", 0); // sanitizer builds: UB fails the run
    test::limit_failure_lines(40);
    std::vector<Lookup> probes = probe_lookups(96, 2026);
    for (const Degenerate& d : degenerate)
        probes.push_back(test::as_float(d.l));
    const MipChain chain = make_procedural("noise", 256);

    std::vector<std::vector<size_t>> where;
    const std::vector<Lookup> rows = arrange(probes, where);
    const std::string csv = (test::work_dir() / "orders.csv").string();
    test::write_lookups_csv(csv, rows);
    const glm::dvec4 coarsest(chain.levels.back().texels.at(0));
    const size_t first_degenerate = probes.size() - degenerate.size();
    {
        test::SampleResult r =
            test::run_sample_command("--texture noise --wrap repeat --filter " + c.filter, csv, true);
        int differ = 0, wrong = 0;
        double spread = 0;
        for (size_t p = 0; p < probes.size(); ++p) {
            const glm::dvec4 first = r.colors[where[p][0]];
            bool same = true;
            for (size_t row : where[p]) {
                spread = std::max(spread, test::max_channel_diff(r.colors[row], first));
                same = same && same_bits(r.colors[row], first);
            }
            if (!same && ++differ <= 3)
                CHECK(same, c.filter + ": probe " + std::to_string(p) + " (" + test::show(probes[p].u) + ", " +
                                test::show(probes[p].v) + ") gives " + test::show(first) + " and others, up to " +
                                test::show(spread) + " apart");
            if (c.hardware_sampler && r.stats[where[p][0]].hardware_lookups != 1)
                CHECK(r.stats[where[p][0]].hardware_lookups == 1, c.filter + ": hardware lookups counted " +
                                                                      std::to_string(r.stats[where[p][0]].hardware_lookups));
            if (p < first_degenerate)
                continue;
            const Degenerate& d = degenerate[p - first_degenerate];
            // Non-finite uv: vec4(0) from the harness (hw-*) or the include (hardware taps).
            // Blur-fully gradients: the 1x1 level, where the filter has levels (float rounding of a mean).
            bool ok = true;
            if (d.expect == Expect::zero)
                ok = same_bits(first, glm::dvec4(0.0));
            else if (d.expect == Expect::coarsest && c.hardware_sampler && !c.level_zero_only)
                ok = test::max_channel_diff(first, coarsest) <= 1e-6;
            if (!ok) {
                ++wrong;
                CHECK(ok, c.filter + ": " + d.what + " gives " + test::show(first) + ", expected " +
                              (d.expect == Expect::zero ? "0" : "the coarsest level " + test::show(coarsest)));
            }
        }
        std::printf("%-44s %zu probes x %zu placements (%zu rows): %d differ (largest spread %.3g), degenerate "
                    "inputs %d wrong -> %s\n",
                    c.filter.c_str(), probes.size(), where[0].size(), rows.size(), differ, spread, wrong,
                    differ || wrong ? "FAIL" : "PASS");
    }
}

} // namespace

TEST_SUITE_BEGIN("gpu");
// Case: the --filter flags, reads level 0 only, is an hw-* filter (see Case).
TEST_CASE("hw-nearest") { check_orders({"hw-nearest", true, true}); }
TEST_CASE("hw-bilinear") { check_orders({"hw-bilinear", true, true}); }
TEST_CASE("hw-trilinear") { check_orders({"hw-trilinear", false, true}); }
TEST_CASE("hw-aniso-16") { check_orders({"hw-aniso --aniso 16", false, true}); }
TEST_CASE("hw-aniso-4") { check_orders({"hw-aniso --aniso 4", false, true}); }
TEST_CASE("aniso-gpu-hardware-taps") { check_orders({"aniso --taps hardware --aniso-shape gpu", false, false}); }
TEST_CASE("aniso-feline-hardware-taps") { check_orders({"aniso --taps hardware --aniso-shape feline", false, false}); }
TEST_CASE("ewa-hardware-taps") { check_orders({"ewa --taps hardware", false, false}); }

// A lookups file with a header and no rows: a header-only CSV from both backends, --stats too (the
// Vulkan pass used to memcpy from a null pointer there: UBSan, which this test makes fatal for its runs).
TEST_CASE("no-lookups")
{
    setenv("UBSAN_OPTIONS", "halt_on_error=1:print_stacktrace=1", 0);
    const std::string csv = (test::work_dir() / "empty.csv").string();
    test::write_lookups_csv(csv, {});
    int ok = 0, total = 0;
    for (const char* filter : {"trilinear", "hw-aniso", "sat", "ewa --taps hardware"})
        for (bool reference : {false, true}) {
            ++total;
            try {
                test::SampleResult r = test::run_sample_command(std::string("--texture checker --filter ") + filter +
                                                            (reference ? " --backend reference" : ""),
                                                        csv, !reference);
                ok += CHECK(r.colors.empty() && r.stats.empty(), std::string(filter) + ": " +
                                                                     std::to_string(r.colors.size()) + " rows");
            } catch (const std::exception& e) {
                CHECK(false, e.what());
            }
        }
    std::printf("no lookups: %d of %d runs (vulkan with --stats, reference) write a header-only CSV -> %s\n", ok, total,
                ok == total ? "PASS" : "FAIL");
}
TEST_SUITE_END();
