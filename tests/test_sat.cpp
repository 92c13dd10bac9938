// Summed-area tables: the host table (host/texture/sat.h) against brute force, and the sat / sat-assembly
// includes (shaders/texfilter/sat.glsl) through `texfilter sample` against the CPU reference
// (host/reference/sat.cpp) and against facts worked out here from the texels themselves.
//
// One test case a check (ctest: sat.CASE), each printing a line with the measured numbers.
//
// Tolerances, GPU vs exact. The table holds 16-bit texels quantised over each channel's own range,
// q = round((v − lo)/span·65535) (lo the channel's smallest value, span its largest − lo rounded up to
// float): each texel is off by at most 0.5/65535·span, so any weighted mean (weights ≥ 0, sum 1) is too.
// The reference averages the same quantised texels (in double), so GPU vs reference has no quantisation
// term. The shader forms every block sum exactly and then does ~12 float32 roundings (conversion,
// weights, sum, scale, + lo): relative 2^-24 each, < 2e-6·(|mean − lo| + |mean|) ≤ 2e-6·(|lo| + 2 span). Box edges are float32 texel coordinates x ± h: each rounding
// of an edge moves it by ≤ 2^-24·|x|; moving an edge by δ moves a mean by ≤ δ/width·(max − min texel), so
// per axis we allow 2^-21·(|x| + h + 1)/h·range (8x the few roundings there are). Footprints of at
// least 1/8 texel keep that term small; texel-aligned boxes in power-of-two textures have none.
#include "texture/error.h"
#include "io/image_io.h"
#include "core/procedural.h"
#include "reference/reference.h"
#include "texture/sat.h"
#include "support.h"

#include <glm/common.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <sys/wait.h>

using namespace tf;
using tf::test::as_float;
using tf::test::max_channel_diff;
using tf::test::SampleResult;

namespace {


std::string fmt(const char* format, double a, double b = 0, double c = 0)
{
    char buf[256];
    std::snprintf(buf, sizeof buf, format, a, b, c);
    return buf;
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// ---------------------------------------------------------------------------------------------------
// (1) Host table: exact integer box sums on a 4096x4096 texture.

// ---------------------------------------------------------------------------------------------------
// GPU runs through `texfilter sample`.

// One `texfilter sample --stats` run of these lookups (written out as float) on a procedural texture.
SampleResult sample(const std::string& texture, int size, const std::string& filter, Wrap wrap,
                    const std::vector<Lookup>& lookups, const std::string& extra = "")
{
    const std::string in = test::new_file_in(test::work_dir(), "lookups-", ".csv").string();
    test::write_lookups_csv(in, lookups);
    const std::string flags = "--texture " + texture + " --texture-size " + std::to_string(size) + " --filter " +
                              filter + " --wrap " + to_string(wrap) + " " + extra;
    return test::run_sample(flags, in, true);
}

SamplerOptions sat_options(Filter filter, Wrap wrap, int boxes = 4)
{
    SamplerOptions o;
    o.filter = filter;
    o.wrap = wrap;
    o.boxes = boxes;
    return o;
}

// Largest spread max − min of any channel over the texture (what an edge shift can move a mean by).
double channel_range(const Image& image)
{
    double range = 0;
    for (int c = 0; c < 4; ++c) {
        double lo = INFINITY, hi = -INFINITY;
        for (const glm::vec4& t : image.texels) {
            lo = std::min(lo, double(t[c]));
            hi = std::max(hi, double(t[c]));
        }
        range = std::max(range, hi - lo);
    }
    return range;
}

// The documented quantisation, written out here: per channel lo = the smallest value, span = largest − lo
// rounded up to float; a texel stands for lo + round((v − lo)/span·65535)·span/65535.
struct Levels {
    glm::dvec4 lo{INFINITY}, span{0.0};
    explicit Levels(const Image& image)
    {
        glm::dvec4 hi(-INFINITY);
        for (const glm::vec4& t : image.texels) {
            lo = glm::min(lo, glm::dvec4(t));
            hi = glm::max(hi, glm::dvec4(t));
        }
        for (int c = 0; c < 4; ++c) {
            float f = float(hi[c] - lo[c]);
            span[c] = double(f) < hi[c] - lo[c] ? std::nextafter(f, INFINITY) : f;
        }
    }
    glm::dvec4 operator()(const glm::vec4& t) const
    {
        glm::dvec4 v;
        for (int c = 0; c < 4; ++c)
            v[c] = span[c] == 0 ? lo[c] : lo[c] + std::round((double(t[c]) - lo[c]) / span[c] * 65535.0) * (span[c] / 65535.0);
        return v;
    }
    // What ~12 float32 roundings of a mean near these values can add up to: 2e-6·(|lo| + 2·span).
    double float_error() const
    {
        double m = 0;
        for (int c = 0; c < 4; ++c)
            m = std::max(m, std::abs(lo[c]) + 2 * span[c]);
        return 2e-6 * m;
    }
};

// GPU-vs-reference tolerance of one box lookup (see the top of the file): float rounding, float_error,
// and edge shifts. centre_extra: how far (texels) the shader's float centre may lie from uv·size beyond
// the wrap reduction (slice offsets). No quantisation term: both average the same quantised texels.
double box_tolerance(const Image& image, const Lookup& l, double float_error, double range, double centre_extra = 0,
                     double lod_bias = 0)
{
    const double w = image.width, h = image.height, m = std::exp2(lod_bias);
    const double hx = std::min(0.5 * (std::abs(l.dudx) + std::abs(l.dudy)) * w * m, 0.5 * w);
    const double hy = std::min(0.5 * (std::abs(l.dvdx) + std::abs(l.dvdy)) * h * m, 0.5 * h);
    // After the wrap reduction the centre lies in [-w, 2w] (clamp), [0, 2w] (mirror), [0, w] (repeat).
    auto edge = [&](double half, double size) { return std::exp2(-21.0) * (2 * size + centre_extra + half + 1) / half; };
    return float_error + range * (edge(hx, w) + edge(hy, h));
}

struct Tally {
    int checked = 0, over = 0;
    double worst_error = 0, worst_ratio = 0;
    void add(double error, double tolerance)
    {
        ++checked;
        worst_error = std::max(worst_error, error);
        worst_ratio = std::max(worst_ratio, error / tolerance);
        if (!(error <= tolerance))
            ++over;
    }
};

// ---------------------------------------------------------------------------------------------------
// (2) A texel-aligned box returns that rectangle's mean.

// ---------------------------------------------------------------------------------------------------
// (3) Wrap modes: random lookups, many across the border, GPU vs the reference.

// Random footprints from 1/8 texel to 512 texels (256 texture) around [0, 1]^2 (the shared generator),
// then a quarter moved right onto an edge (the box straddles it) and one in 16 many periods out.
std::vector<Lookup> random_lookups(int count, unsigned seed)
{
    std::vector<Lookup> lookups = test::random_footprint_lookups(
        count, seed, {.uv_min = -0.3, .uv_max = 1.3, .octave_min = -3.0, .octave_max = 9.0, .max_stretch = 3.0});
    std::mt19937 rng(seed + 1);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < count; ++i) {
        Lookup& l = lookups[size_t(i)];
        if (i % 4 == 0) // right at an edge: the box straddles it
            l.u = std::round(l.u) + (unit(rng) - 0.5) * 0.02;
        if (i % 4 == 1)
            l.v = std::round(l.v) + (unit(rng) - 0.5) * 0.02;
        if (i % 16 == 2) { // far away: many periods out
            l.u += 1000.0 * (unit(rng) - 0.5);
            l.v -= 100.0 * unit(rng);
        }
    }
    return as_float(lookups);
}

// Does the lookup's box leave [0, 1]^2 (in uv)?
bool crosses_border(const Lookup& l, double lod_bias)
{
    const double m = std::exp2(lod_bias);
    double hu = 0.5 * (std::abs(l.dudx) + std::abs(l.dudy)) * m, hv = 0.5 * (std::abs(l.dvdx) + std::abs(l.dvdy)) * m;
    return l.u - hu < 0 || l.u + hu > 1 || l.v - hv < 0 || l.v + hv > 1;
}

struct WrapCase { std::string texture; int size; Wrap wrap; float bias = 0; };

// (3)'s lookups and its GPU run of one case (what (5a) compares sat-assembly --boxes 1 with).
const std::vector<Lookup>& wrap_mode_lookups()
{
    static const std::vector<Lookup> lookups = random_lookups(2000, 2026);
    return lookups;
}

SampleResult wrap_mode_run(const WrapCase& c)
{
    return sample(c.texture, c.size, "sat", c.wrap, wrap_mode_lookups(), "--lod-bias " + std::to_string(c.bias));
}

// worst_gpu_error: raised to the largest GPU-vs-reference error seen (the case's summary line).
void check_wrap_mode(const WrapCase& c, double& worst_gpu_error)
{
    const std::vector<Lookup>& lookups = wrap_mode_lookups();
    {
        MipChain chain = make_procedural(c.texture, c.size);
        const Image& image = chain.levels[0];
        const double float_error = Levels(image).float_error(), range = channel_range(image);
        SampleResult gpu = wrap_mode_run(c);
        SamplerOptions options = sat_options(Filter::sat, c.wrap);
        options.lod_bias = c.bias;
        Tally inside, border;
        double worst_large = 0; // boxes of at least 4 x 4 texels: no edge term to speak of
        int border_count = 0;
        unsigned most_fetches = 0;
        for (size_t i = 0; i < lookups.size(); ++i) {
            glm::dvec4 ref = reference_sample(chain, options, lookups[i]);
            double e = max_channel_diff(gpu.colors[i], ref), tol = box_tolerance(image, lookups[i], float_error, range, 0, c.bias);
            bool b = crosses_border(lookups[i], c.bias);
            (b ? border : inside).add(e, tol);
            border_count += b;
            most_fetches = std::max(most_fetches, gpu.stats[i].texel_fetches);
            const Lookup& l = lookups[i];
            const double big = 4.0 / c.size / std::exp2(c.bias);
            if (std::abs(l.dudx) + std::abs(l.dudy) >= big && std::abs(l.dvdx) + std::abs(l.dvdy) >= big)
                worst_large = std::max(worst_large, e);
            if (!(e <= tol) && border.over + inside.over <= 3)
                CHECK(e <= tol, fmt("lookup %g: GPU vs reference %.3g > tolerance %.3g", double(i), e, tol));
        }
        worst_gpu_error = std::max({worst_gpu_error, inside.worst_error, border.worst_error});
        bool ok = inside.over == 0 && border.over == 0 && border_count > 500 && most_fetches <= 128;
        CHECK(border_count > 500 && most_fetches <= 128, fmt("%g border lookups, %g fetches", border_count, most_fetches));
        std::printf("(3) %s %d %s, lod bias %g: %zu lookups (%d across the border): max |GPU-ref| inside %.3g, border "
                    "%.3g, boxes >= 4x4 texels %.3g; worst error/tolerance %.3f; max fetches %u -> %s\n",
                    c.texture.c_str(), c.size, to_string(c.wrap).c_str(), c.bias, lookups.size(), border_count,
                    inside.worst_error, border.worst_error, worst_large, std::max(inside.worst_ratio, border.worst_ratio),
                    most_fetches, ok ? "PASS" : "FAIL");
    }
}

// ---------------------------------------------------------------------------------------------------
// (4) Constant time: the shader's texel fetches do not depend on the footprint's size.

// ---------------------------------------------------------------------------------------------------
// (5) sat-assembly: K = 1 is sat; more boxes follow a slanted footprint more closely.

// The pixel's parallelogram uv + J·(a, b), a, b in [−½, ½], integrated over the box-reconstructed
// texture by stratified supersampling (m x m midpoints).
glm::dvec4 parallelogram_mean(const Image& image, const Lookup& l, Wrap wrap, int m)
{
    glm::dvec4 sum(0.0);
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
            double a = (i + 0.5) / m - 0.5, b = (j + 0.5) / m - 0.5;
            double x = (l.u + a * l.dudx + b * l.dudy) * image.width, y = (l.v + a * l.dvdx + b * l.dvdy) * image.height;
            sum += glm::dvec4(image.at(wrap_texel((long long)std::floor(x), image.width, wrap),
                                       wrap_texel((long long)std::floor(y), image.height, wrap)));
        }
    return sum / double(m * m);
}

// ---------------------------------------------------------------------------------------------------
// (6) NaN, Inf, zero and huge gradients (and uv) give finite, defined results.

// ---------------------------------------------------------------------------------------------------
// (7) HDR texels keep 16 bits of their own range: one 65504 texel among 0.3s (a regression guard: the GPU once gave 0
// where the reference gave 0.3, silently). Each channel is quantised over [lo, lo + span], so the 0.3s
// are exactly level 0 and any box mean is within 0.5/65535·span (~0.5 here) of the exact float mean,
// plus float rounding; the GPU is within float rounding of the reference, which averages the same levels.

// ---------------------------------------------------------------------------------------------------
// (8) NaN and ±Inf texels are refused with a message naming the texel, on both backends and in build_sat.

// Runs a command, returns its exit status and what it printed on stderr: (8) is a CLI test in part (the
// command's exit status, its one message, no output file).
int run_capturing(const std::string& command, std::string& err)
{
    const std::string err_path = (test::work_dir() / "stderr.txt").string();
    const int status = std::system((command + " 2> '" + err_path + "' > /dev/null").c_str());
    err.clear();
    if (FILE* f = std::fopen(err_path.c_str(), "r")) {
        char buf[4096];
        size_t got = 0;
        while ((got = std::fread(buf, 1, sizeof buf, f)) > 0)
            err.append(buf, got);
        std::fclose(f);
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

} // namespace

// A case's summary line: the worst GPU-vs-reference error it saw, and its time.
struct SatCase {
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    double worst_gpu_error = 0;
    ~SatCase()
    {
        std::printf("max GPU-vs-reference error: %.3g; total %.1f s\n", worst_gpu_error, seconds_since(start));
    }
};

TEST_SUITE_BEGIN("reference");
TEST_CASE("exact-box-sums")
{
    SatCase c;
    auto start = std::chrono::steady_clock::now();
    const int n = sat_max_dimension;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> uniform(0.0f, 3.0f), wide(-0.5f, 3.0f), top(2.99f, 3.0f);
    Image image = make_image(n, n);
    // R uniform, G with negatives, B in a narrow band near 3, A at its largest value but for one texel
    // at its smallest: the whole texture's A sum is (4096^2 − 1)·65535 ≈ 2^40 − 2^24, so bit 39 of the
    // table and of the sums is used.
    for (glm::vec4& t : image.texels)
        t = glm::vec4(uniform(rng), wide(rng), top(rng), 3.0f);
    image.texels[12345].a = -1.5f;

    auto build_start = std::chrono::steady_clock::now();
    SatTable table = build_sat(image);
    double build_s = seconds_since(build_start);
    // Each channel's own range, from the texels (the span rounded up to float).
    glm::dvec4 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec4& t : image.texels) {
        lo = glm::min(lo, glm::dvec4(t));
        hi = glm::max(hi, glm::dvec4(t));
    }
    glm::dvec4 span;
    for (int c = 0; c < 4; ++c) {
        float f = float(hi[c] - lo[c]);
        span[c] = double(f) < hi[c] - lo[c] ? std::nextafter(f, INFINITY) : f;
    }
    CHECK(table.width == n && table.height == n && glm::dvec4(table.offset) == lo && glm::dvec4(table.scale) == span,
          fmt("offset R %.9g, scale R %.9g, scale A %.9g", table.offset.r, table.scale.r, table.scale.a));
    CHECK(table.low.size() == size_t(n + 1) * size_t(n + 1) * 4 && table.high.size() == size_t(n + 1) * size_t(n + 1),
          fmt("%g words", double(table.low.size())));

    // The quantised texels, written out from the formula (not from sat.cpp), 4 planes.
    std::vector<std::vector<uint16_t>> q(4, std::vector<uint16_t>(size_t(n) * size_t(n)));
    for (size_t i = 0; i < image.texels.size(); ++i)
        for (int c = 0; c < 4; ++c)
            q[size_t(c)][i] = uint16_t(std::lround((double(image.texels[i][c]) - lo[c]) / span[c] * 65535.0));
    auto brute = [&](int x0, int y0, int x1, int y1) {
        std::array<uint64_t, 4> sum{};
        for (int c = 0; c < 4; ++c)
            for (int y = y0; y < y1; ++y) {
                const uint16_t* row = q[size_t(c)].data() + size_t(y) * size_t(n);
                uint64_t s = 0;
                for (int x = x0; x < x1; ++x)
                    s += row[x];
                sum[size_t(c)] += s;
            }
        return sum;
    };

    struct Box { int x0, y0, x1, y1; };
    std::vector<Box> boxes = {{0, 0, n, n}, {0, 0, 1, 1}, {n - 1, n - 1, n, n}, {1234, 567, 1235, 568},
                              {0, 0, n, 1}, {0, n - 1, n, n}, {0, 0, 1, n}, {n - 1, 0, n, n},
                              {17, 0, 18, n}, {0, 2048, n, 2049}, {1, 1, n, n}, {0, 0, n - 1, n - 1},
                              {5, 5, 5, 9}, {0, 0, 0, 0}};
    std::uniform_int_distribution<int> coord(0, n);
    std::uniform_real_distribution<double> octave(0.0, 12.0);
    for (int i = 0; i < 300; ++i) {
        if (i % 3 == 0) { // any corners
            int x0 = coord(rng), x1 = coord(rng), y0 = coord(rng), y1 = coord(rng);
            boxes.push_back({std::min(x0, x1), std::min(y0, y1), std::max(x0, x1), std::max(y0, y1)});
        } else { // log-uniform sides from 1 to 4096 (thin strips and big boxes alike)
            int w = std::min(n, int(std::exp2(octave(rng)))), h = std::min(n, int(std::exp2(octave(rng))));
            int x0 = std::uniform_int_distribution<int>(0, n - w)(rng), y0 = std::uniform_int_distribution<int>(0, n - h)(rng);
            boxes.push_back({x0, y0, x0 + w, y0 + h});
        }
    }
    int mismatches = 0;
    uint64_t largest = 0;
    for (const Box& b : boxes) {
        std::array<uint64_t, 4> table_sum = sat_box_sum(table, b.x0, b.y0, b.x1, b.y1), exact = brute(b.x0, b.y0, b.x1, b.y1);
        for (int c = 0; c < 4; ++c) {
            largest = std::max(largest, exact[size_t(c)]);
            if (table_sum[size_t(c)] != exact[size_t(c)] && ++mismatches <= 5)
                CHECK(table_sum[size_t(c)] == exact[size_t(c)],
                      "box [" + std::to_string(b.x0) + "," + std::to_string(b.x1) + ")x[" + std::to_string(b.y0) + "," +
                          std::to_string(b.y1) + ") channel " + std::to_string(c) + ": table " +
                          std::to_string(table_sum[size_t(c)]) + " vs brute force " + std::to_string(exact[size_t(c)]));
        }
    }
    const uint64_t full_alpha = (uint64_t(n) * uint64_t(n) - 1) * 65535u;
    CHECK(sat_box_sum(table, 0, 0, n, n)[3] == full_alpha, std::to_string(sat_box_sum(table, 0, 0, n, n)[3]));
    CHECK(largest >= (uint64_t(1) << 39), std::to_string(largest));

    // The limits: sides above 4096 are refused, boxes outside the texture too.
    bool threw_wide = false, threw_tall = false, threw_box = false;
    try { build_sat(make_image(n + 1, 1)); } catch (const Error&) { threw_wide = true; }
    try { build_sat(make_image(1, n + 1)); } catch (const Error&) { threw_tall = true; }
    try { sat_box_sum(table, 0, 0, n + 1, 1); } catch (const Error&) { threw_box = true; }
    CHECK(threw_wide && threw_tall && threw_box, "build_sat/sat_box_sum must throw tf::Error outside the limits");

    std::printf("(1) exact box sums, 4096x4096: %zu boxes x 4 channels, %d mismatches, largest sum %.6g "
                "(2^40 = %.6g); build_sat %.2f s, whole check %.2f s -> %s\n",
                boxes.size(), mismatches, double(largest), std::exp2(40.0), build_s, seconds_since(start),
                mismatches ? "FAIL" : "PASS");
}
TEST_SUITE_END();

TEST_SUITE_BEGIN("gpu");
TEST_CASE("aligned-boxes")
{
    SatCase c;
    const int n = 256;
    MipChain chain = make_procedural("noise", n);
    const Image& image = chain.levels[0];
    struct Box { int x0, y0, x1, y1; };
    const std::vector<Box> boxes = {{16, 32, 80, 40}, {0, 0, 256, 256}, {100, 7, 101, 8},  {3, 0, 253, 1},
                                    {0, 0, 1, 256},   {200, 10, 256, 250}, {64, 64, 192, 192}, {1, 2, 3, 5}};
    const Levels levels(image);
    std::vector<Lookup> lookups;
    std::vector<glm::dvec4> exact, exact_q;
    for (const Box& b : boxes) {
        // Centre and side / n are exact in float for n = 256: the box is exactly [x0, x1) x [y0, y1).
        lookups.push_back({(b.x0 + b.x1) / 2.0 / n, (b.y0 + b.y1) / 2.0 / n, double(b.x1 - b.x0) / n, 0.0, 0.0,
                           double(b.y1 - b.y0) / n});
        glm::dvec4 sum(0.0), sum_q(0.0);
        for (int y = b.y0; y < b.y1; ++y)
            for (int x = b.x0; x < b.x1; ++x) {
                sum += glm::dvec4(image.at(x, y));
                sum_q += levels(image.at(x, y));
            }
        exact.push_back(sum / double((b.x1 - b.x0) * (b.y1 - b.y0)));
        exact_q.push_back(sum_q / double((b.x1 - b.x0) * (b.y1 - b.y0)));
    }
    SampleResult gpu = sample("noise", n, "sat", Wrap::repeat, lookups);
    // No edge term here: vs the float texels quantisation (0.5 step) plus float rounding, vs the quantised
    // texels float rounding only.
    const double range = channel_range(image), tolerance = 0.5 / 65535.0 * range + levels.float_error();
    Tally tally, tally_q, reference;
    for (size_t i = 0; i < boxes.size(); ++i) {
        double e = max_channel_diff(gpu.colors[i], exact[i]), eq = max_channel_diff(gpu.colors[i], exact_q[i]);
        tally.add(e, tolerance);
        tally_q.add(eq, levels.float_error());
        CHECK(e <= tolerance, fmt("box %g: GPU off the exact mean by %.3g > %.3g", double(i), e, tolerance));
        CHECK(eq <= levels.float_error(), fmt("box %g: GPU off the quantised mean by %.3g > %.3g", double(i), eq,
                                              levels.float_error()));
        glm::dvec4 ref = reference_sample(chain, sat_options(Filter::sat, Wrap::repeat), lookups[i]);
        double r = max_channel_diff(ref, exact_q[i]);
        reference.add(r, 1e-12);
        CHECK(r <= 1e-12, fmt("box %g: reference off the quantised mean by %.3g", double(i), r));
    }
    std::printf("(2) texel-aligned boxes (noise 256): %d boxes, GPU max error vs the float texels %.3g (tolerance "
                "%.3g = 0.5/65535 span + float), vs the quantised texels %.3g (%.3g); reference vs quantised %.3g "
                "-> %s\n",
                tally.checked, tally.worst_error, tolerance, tally_q.worst_error, levels.float_error(),
                reference.worst_error, tally.over || tally_q.over || reference.over ? "FAIL" : "PASS");
}

TEST_CASE("wrap-noise-256-repeat") { SatCase c; check_wrap_mode({"noise", 256, Wrap::repeat}, c.worst_gpu_error); }
TEST_CASE("wrap-noise-256-clamp") { SatCase c; check_wrap_mode({"noise", 256, Wrap::clamp}, c.worst_gpu_error); }
TEST_CASE("wrap-noise-256-mirror") { SatCase c; check_wrap_mode({"noise", 256, Wrap::mirror}, c.worst_gpu_error); }
TEST_CASE("wrap-zoneplate-100-repeat") { SatCase c; check_wrap_mode({"zoneplate", 100, Wrap::repeat}, c.worst_gpu_error); }
TEST_CASE("wrap-zoneplate-100-clamp") { SatCase c; check_wrap_mode({"zoneplate", 100, Wrap::clamp}, c.worst_gpu_error); }
TEST_CASE("wrap-zoneplate-100-mirror") { SatCase c; check_wrap_mode({"zoneplate", 100, Wrap::mirror}, c.worst_gpu_error); }
TEST_CASE("wrap-grid-64-repeat-bias-1.5") { SatCase c; check_wrap_mode({"grid", 64, Wrap::repeat, 1.5f}, c.worst_gpu_error); }
TEST_CASE("wrap-checker-96-clamp-bias-minus-1") { SatCase c; check_wrap_mode({"checker", 96, Wrap::clamp, -1.0f}, c.worst_gpu_error); }
TEST_CASE("constant-time")
{
    SatCase c;
    const double tiny = 1e-4 / 256, small = 1.0 / 256, huge = 0.999;
    std::vector<Lookup> centre = as_float({{0.5, 0.5, tiny, 0, 0, tiny},
                                           {0.5, 0.5, small, 0, 0, small},
                                           {0.5, 0.5, 0.2, 0.1, -0.05, 0.3},
                                           {0.5, 0.5, huge, 0, 0, huge},
                                           {0.5, 0.5, 1e6, 1e6, -1e6, 1e6},
                                           {0.5, 0.5, 0, 0, 0, 0}});
    std::vector<Lookup> border = as_float({{0.0, 0.0, tiny, 0, 0, tiny}, {0.0, 0.0, 0.3, 0, 0, 0.3},
                                           {1.0, 1.0, huge, 0, 0, huge},  {-3.2, 7.9, 0.4, 0.1, 0.2, 0.5},
                                           {0.999, 0.5, 0.01, 0, 0, 0.5}, {0.5, 1e4, 0.2, 0, 0, 0.2}});
    for (Wrap wrap : {Wrap::repeat, Wrap::clamp, Wrap::mirror}) {
        SampleResult inside = sample("noise", 256, "sat", wrap, centre);
        SampleResult edge = sample("noise", 256, "sat", wrap, border);
        auto by_fetches = [](const LookupStats& a, const LookupStats& b) { return a.texel_fetches < b.texel_fetches; };
        unsigned lo = std::min_element(inside.stats.begin(), inside.stats.end(), by_fetches)->texel_fetches;
        unsigned hi = std::max_element(inside.stats.begin(), inside.stats.end(), by_fetches)->texel_fetches;
        unsigned edge_hi = std::max_element(edge.stats.begin(), edge.stats.end(), by_fetches)->texel_fetches;
        bool ok = lo == 32 && hi == 32 && edge_hi <= 128;
        CHECK(ok, fmt("inside %g..%g, border max %g", lo, hi, edge_hi));
        std::printf("(4) constant time, %s: texelFetch per lookup inside the texture %u (footprint 1e-4 texel) .. %u "
                    "(whole texture, 1e6 texels, zero) = 16 table entries; across the border at most %u (<= 128) -> %s\n",
                    to_string(wrap).c_str(), lo, hi, edge_hi, ok ? "PASS" : "FAIL");
    }
}
TEST_SUITE_END();

TEST_SUITE_BEGIN("gpu slow");
TEST_CASE("assembly")
{
    SatCase c;
    double& worst_gpu_error = c.worst_gpu_error;
    // K = 1 against the sat runs of (3) (noise 256 repeat, clamp): bit for bit (CSV has 9 digits: a float).
    const std::vector<Lookup>& lookups = wrap_mode_lookups();
    int differ = 0;
    for (Wrap wrap : {Wrap::repeat, Wrap::clamp}) {
        const SampleResult sat = wrap_mode_run({"noise", 256, wrap});
        SampleResult k1 = sample("noise", 256, "sat-assembly", wrap, lookups, "--boxes 1");
        for (size_t i = 0; i < lookups.size(); ++i)
            differ += k1.colors[i] != sat.colors[i];
    }
    CHECK(differ == 0, fmt("%g lookups differ", differ));
    std::printf("(5a) sat-assembly --boxes 1 vs sat: %zu lookups x 2 wrap modes, %d differ -> %s\n", lookups.size(),
                differ, differ ? "FAIL" : "PASS");

    // K = 4 against the reference on the random lookups. The slice centres uv + J e·a/size are float: that
    // adds rounding of the centre's magnitude (the offset, and in clamp mode uv itself, not reduced).
    MipChain chain = make_procedural("noise", 256);
    const Image& image = chain.levels[0];
    const double float_error = Levels(image).float_error(), range = channel_range(image);
    for (Wrap wrap : {Wrap::repeat, Wrap::clamp, Wrap::mirror}) {
        SampleResult gpu = sample("noise", 256, "sat-assembly", wrap, lookups, "--boxes 4");
        Tally tally;
        int skipped = 0;
        for (size_t i = 0; i < lookups.size(); ++i) {
            const Lookup& l = lookups[i];
            double lx = std::hypot(l.dudx, l.dvdx) * 256, ly = std::hypot(l.dudy, l.dvdy) * 256;
            if (std::abs(lx - ly) <= 1e-4 * std::max(lx, ly)) { // float and double may pick different major axes
                ++skipped;
                continue;
            }
            glm::dvec4 ref = reference_sample(chain, sat_options(Filter::sat_assembly, wrap, 4), l);
            double e = max_channel_diff(gpu.colors[i], ref);
            double centre = 0.5 * std::max(lx, ly) + (wrap == Wrap::clamp ? 256 * std::max(std::abs(l.u), std::abs(l.v)) : 0);
            double tol = box_tolerance(image, l, float_error, range, centre);
            tally.add(e, tol);
            if (!(e <= tol) && tally.over <= 3)
                CHECK(e <= tol, fmt("lookup %g: sat-assembly GPU vs reference %.3g > %.3g", double(i), e, tol));
        }
        worst_gpu_error = std::max(worst_gpu_error, tally.worst_error);
        std::printf("(5b) sat-assembly K=4 vs reference (noise 256 %s): %d lookups (%d near-isotropic skipped), "
                    "max error %.3g, worst error/tolerance %.3f -> %s\n",
                    to_string(wrap).c_str(), tally.checked, skipped, tally.worst_error, tally.worst_ratio,
                    tally.over ? "FAIL" : "PASS");
    }

    // Slanted footprints (8:1, 20..70 degrees, 8..64 texels long) vs the supersampled parallelogram.
    std::mt19937 rng(99);
    std::uniform_real_distribution<double> uv(0.0, 1.0), angle(0.35, 1.22), length(8.0, 64.0);
    for (const std::string texture : {"zoneplate", "checker"}) {
        const int n = 256;
        MipChain chain = make_procedural(texture, n);
        std::vector<Lookup> slanted;
        for (int i = 0; i < 200; ++i) {
            double a = angle(rng), len = length(rng) / n, minor = len / 8;
            slanted.push_back({uv(rng), uv(rng), len * std::cos(a), len * std::sin(a), -minor * std::sin(a), minor * std::cos(a)});
        }
        slanted = as_float(slanted);
        std::vector<glm::dvec4> truth;
        for (const Lookup& l : slanted)
            truth.push_back(parallelogram_mean(chain.levels[0], l, Wrap::repeat, 256));
        std::string line;
        std::vector<double> errors;
        for (int k : {1, 2, 4, 8, 16}) {
            SampleResult gpu = sample(texture, n, "sat-assembly", Wrap::repeat, slanted, "--boxes " + std::to_string(k));
            double sum = 0;
            for (size_t i = 0; i < slanted.size(); ++i)
                sum += max_channel_diff(gpu.colors[i], truth[i]);
            errors.push_back(sum / double(slanted.size()));
            line += fmt(" K=%g %.4f", k, errors.back());
        }
        // More slices, closer to the parallelogram: K=4 beats K=1 and K=16 beats K=4.
        bool ok = errors[2] < errors[0] && errors[4] < errors[2];
        CHECK(ok, "mean error by K:" + line);
        std::printf("(5c) sat-assembly on 200 slanted 8:1 footprints (%s 256), mean |result - parallelogram "
                    "integral|:%s -> %s\n",
                    texture.c_str(), line.c_str(), ok ? "PASS" : "FAIL");
    }
}
TEST_SUITE_END();

TEST_SUITE_BEGIN("gpu");
TEST_CASE("degenerate")
{
    SatCase c;
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = INFINITY;
    const int n = 256;
    MipChain chain = make_procedural("noise", n);
    const Image& image = chain.levels[0];
    glm::dvec4 mean(0.0), lo(INFINITY), hi(-INFINITY);
    for (const glm::vec4& t : image.texels) {
        mean += glm::dvec4(t);
        lo = glm::min(lo, glm::dvec4(t));
        hi = glm::max(hi, glm::dvec4(t));
    }
    mean /= double(image.texels.size());
    // kCornerMean: sat as the reference (the texels at the corner, equally); sat-assembly only bounded: its
    // slices' offsets (1e-31 of uv) are lost to float where their centres wrap, here and in the reference.
    enum Expect { kMean, kNearest, kBounded, kZero, kCornerMean };
    struct Case { Lookup l; Expect expect; const char* what; };
    const std::vector<Case> cases = {
        {{0.3, 0.6, nan, 0, 0, 0.01}, kMean, "NaN gradient"},
        {{0.3, 0.6, 0.01, 0, 0, nan}, kMean, "NaN gradient"},
        {{0.3, 0.6, inf, 0, 0, 0.01}, kMean, "+Inf gradient"},
        {{0.9, 0.1, -inf, inf, inf, -inf}, kMean, "-Inf/+Inf gradients"},
        {{0.3, 0.6, 0, 0, 0, 0}, kNearest, "zero gradients"},
        {{0.123, 0.987, 0, 0, 0, 0}, kNearest, "zero gradients"},
        {{-2.7, 5.3, 0, 0, 0, 0}, kNearest, "zero gradients, outside"},
        {{0.3, 0.6, 1e-30, 0, 0, 1e-30}, kNearest, "denormal-small gradients"},
        // A box far narrower than a texel across texel edges on both axes (a period's edge, and texel 0's
        // edge under clamp): the mean of the texels at the corner, not NaN (the empty middle block's weight
        // was 1/width, whose square overflowed).
        {{1.0, 1.0, 1e-30, 0, 0, 1e-30}, kCornerMean, "tiny box on a corner of texels"},
        {{0.0, 0.0, 1e-30, 0, 0, 1e-30}, kCornerMean, "tiny box on a corner of texels"},
        {{0.5, 0.5, 1e-30, 0, 0, 1e-30}, kCornerMean, "tiny box on a corner of texels"},
        // Finite gradients whose footprint entry (gradient x 256) is past float range: as non-finite.
        {{-1.0, 0.5, 1e37, 0, 0, 0}, kMean, "footprint entry past float range"},
        {{0.25, 0.5, 0, 2e36, -1e37, 0}, kMean, "footprint entry past float range"},
        {{0.3, 0.6, 1e30, 0, 0, 1e30}, kBounded, "huge gradients"},
        {{0.3, 0.6, 3e38, -3e38, 3e38, 3e38}, kBounded, "largest float gradients"},
        {{0.3, 0.6, 1e30, 0, 0, 0}, kBounded, "huge x, zero y"},
        {{1e30, -1e30, 0.01, 0, 0, 0.01}, kBounded, "huge uv"},
        {{nan, 0.5, 0.01, 0, 0, 0.01}, kZero, "NaN uv"},
        {{0.5, inf, 0.01, 0, 0, 0.01}, kZero, "Inf uv"},
    };
    std::vector<Lookup> lookups;
    for (const Case& c : cases)
        lookups.push_back(c.l);
    lookups = as_float(lookups);
    const double tolerance = 0.5 / 65535.0 + 2e-6;
    for (Wrap wrap : {Wrap::repeat, Wrap::clamp, Wrap::mirror})
        for (const char* filter : {"sat", "sat-assembly"}) {
            SampleResult gpu = sample("noise", n, filter, wrap, lookups);
            double worst = 0;
            int bad = 0;
            for (size_t i = 0; i < cases.size(); ++i) {
                const glm::dvec4 c = gpu.colors[i];
                const Lookup& l = lookups[i];
                bool finite = std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b) && std::isfinite(c.a);
                double e = 0;
                switch (cases[i].expect) {
                case kMean: e = max_channel_diff(c, mean); break;
                case kNearest: e = max_channel_diff(c, reference_nearest(image, l.u, l.v, wrap)); break;
                case kZero: e = max_channel_diff(c, glm::dvec4(0.0)); break;
                case kCornerMean: // sat: the reference, below
                case kBounded:
                    e = std::max(max_channel_diff(glm::max(c, hi), hi), max_channel_diff(glm::min(c, lo), lo));
                    break;
                }
                // Where the reference defines the answer, they agree (huge uv: float centres differ).
                const bool assembly = std::string(filter) == "sat-assembly";
                if (cases[i].expect != kBounded && !(cases[i].expect == kCornerMean && assembly))
                    e = std::max(e, max_channel_diff(c, reference_sample(chain, sat_options(std::string(filter) == "sat"
                                                                                             ? Filter::sat
                                                                                             : Filter::sat_assembly,
                                                                                         wrap),
                                                                         l)));
                worst = std::max(worst, e);
                if (!finite || !(e <= tolerance)) {
                    ++bad;
                    CHECK(finite && e <= tolerance,
                          std::string(cases[i].what) + " (" + filter + ", " + to_string(wrap) + "): " +
                              fmt("%.9g %.9g %.9g", c.r, c.g, c.b) + fmt(", error %.3g", e));
                }
            }
            std::printf("(6) degenerate footprints, %s %s: %zu cases (NaN/Inf/zero/huge gradients, NaN/Inf/huge uv), "
                        "all finite, max error vs defined answer %.3g (tolerance %.3g) -> %s\n",
                        filter, to_string(wrap).c_str(), cases.size(), worst, tolerance, bad ? "FAIL" : "PASS");
        }
}

TEST_CASE("hdr")
{
    SatCase c;
    const int n = 64;
    Image image = make_image(n, n, glm::vec4(0.3f, 0.3f, 0.3f, 1.0f));
    image.at(37, 21) = glm::vec4(65504.0f, 65504.0f, 65504.0f, 1.0f);
    const std::string path = (test::work_dir() / "hdr.pfm").string();
    write_image(path, image);
    MipChain chain;
    chain.levels.push_back(image); // level 0 is all sat reads
    const SatTable table = build_sat(image);
    CHECK(table.offset.r == 0.3f && table.scale.r >= 65504.0f - 0.3f && table.scale.a == 0.0f,
          fmt("offset %.9g, scale %.9g, alpha scale %.9g", table.offset.r, table.scale.r, table.scale.a));

    // Texel-aligned boxes (centre and side exact in float for n = 64): away from the spike, on it, the
    // whole texture (NaN gradient), and a box of 0.3s right beside it.
    struct Box { int x0, y0, x1, y1; };
    const std::vector<Box> boxes = {{0, 0, 16, 16}, {32, 16, 48, 32}, {37, 21, 38, 22}, {0, 0, 64, 64},
                                    {38, 16, 54, 32}, {0, 40, 64, 41}, {30, 20, 40, 24}};
    std::vector<Lookup> lookups;
    std::vector<glm::dvec4> exact;
    for (const Box& b : boxes) {
        lookups.push_back({(b.x0 + b.x1) / 2.0 / n, (b.y0 + b.y1) / 2.0 / n, double(b.x1 - b.x0) / n, 0.0, 0.0,
                           double(b.y1 - b.y0) / n});
        glm::dvec4 sum(0.0);
        for (int y = b.y0; y < b.y1; ++y)
            for (int x = b.x0; x < b.x1; ++x)
                sum += glm::dvec4(image.at(x, y));
        exact.push_back(sum / double((b.x1 - b.x0) * (b.y1 - b.y0)));
    }
    lookups.push_back({0.3, 0.7, std::numeric_limits<double>::quiet_NaN(), 0, 0, 0.1}); // the whole texture
    exact.push_back(exact[3]);
    const std::string in = (test::work_dir() / "hdr-lookups.csv").string();
    test::write_lookups_csv(in, lookups);
    const SampleResult gpu = test::run_sample("--texture " + path + " --filter sat", in, false);
    const SampleResult cli_reference =
        test::run_sample("--texture " + path + " --filter sat --backend reference", in, false);

    const double step = double(table.scale.r) / 65535.0;
    Tally vs_exact, vs_reference;
    for (size_t i = 0; i < lookups.size(); ++i) {
        const glm::dvec4 ref = reference_sample(chain, sat_options(Filter::sat, Wrap::repeat), lookups[i]);
        const double m = exact[i].r;
        // Documented: 0.5 step from quantisation; float rounding ~2e-6 relative to (mean − lo) and the mean.
        const double rounding = 2e-6 * (std::abs(m - 0.3) + std::abs(m));
        const double bound = 0.5 * step + rounding;
        for (const glm::dvec4& r : {gpu.colors[i], ref, cli_reference.colors[i]}) {
            const double e = max_channel_diff(r, exact[i]);
            vs_exact.add(e, bound);
            if (!(e <= bound))
                CHECK(e <= bound, fmt("HDR box %g: %.9g vs exact mean %.9g", double(i), r.r, m));
        }
        const double g = max_channel_diff(gpu.colors[i], ref);
        vs_reference.add(g, rounding);
        if (!(g <= rounding))
            CHECK(g <= rounding, fmt("HDR box %g: GPU %.9g vs reference %.9g", double(i), gpu.colors[i].r, ref.r));
    }
    // The boxes of 0.3s alone are exact (level 0 is 0.3f itself).
    for (size_t i : {size_t(0), size_t(4), size_t(5)})
        CHECK(std::abs(gpu.colors[i].r - 0.3) <= 2e-6 * 0.3, fmt("box of 0.3s: GPU %.9g", gpu.colors[i].r));
    std::printf("(7) HDR (64x64 of 0.3, one texel 65504): %zu boxes, step %.4g; GPU, reference, CLI reference vs exact "
                "mean: max error %.3g (bound 0.5 step + float); GPU vs reference max %.3g (float rounding); "
                "box of 0.3s: GPU %.9g -> %s\n",
                lookups.size(), step, vs_exact.worst_error, vs_reference.worst_error, gpu.colors[0].r,
                vs_exact.over || vs_reference.over ? "FAIL" : "PASS");
}

TEST_CASE("non-finite-texels")
{
    SatCase c;
    struct Bad { float value; const char* word; };
    const Bad bad[] = {{std::numeric_limits<float>::quiet_NaN(), "NaN"}, {INFINITY, "+Inf"}, {-INFINITY, "-Inf"}};
    const std::string in = (test::work_dir() / "one-lookup.csv").string();
    test::write_lookups_csv(in, {{0.5, 0.5, 0.1, 0, 0, 0.1}});
    int passed = 0, total = 0;
    for (const Bad& b : bad) {
        Image image = make_image(16, 8, glm::vec4(0.25f));
        image.at(5, 3).g = b.value;
        const std::string expect = std::string("texel (5, 3) is ") + b.word;
        CHECK_THROWS_WITH(build_sat(image), expect);
        CHECK_THROWS_WITH(check_sat_texels(image, "bad.pfm"), "texture bad.pfm: " + expect);
        MipChain chain;
        chain.levels.push_back(image);
        CHECK_THROWS_WITH(reference_sample(chain, sat_options(Filter::sat, Wrap::repeat), {0.5, 0.5, 0.1, 0, 0, 0.1}),
                          expect);
        const std::string path = (test::work_dir() / (std::string("bad-") + b.word + ".pfm")).string();
        write_image(path, image);
        for (const char* backend : {"vulkan", "reference"})
            for (const char* filter : {"sat", "sat-assembly"}) {
                const std::string out = (test::work_dir() / "bad-out.csv").string();
                std::filesystem::remove(out);
                std::string err;
                const int status = run_capturing("'" + test::texfilter_path() + "' sample --texture '" + path + "' --filter " +
                                                     filter + " --backend " + backend + " --lookups '" + in +
                                                     "' -o '" + out + "'",
                                                 err);
                const bool ok = status == 2 && err.find(expect) != std::string::npos &&
                                err.find("every filter needs finite texels") != std::string::npos &&
                                !std::filesystem::exists(out);
                ++total;
                passed += ok;
                CHECK(ok, std::string(backend) + " " + filter + " on a texel " + b.word + ": exit " +
                              std::to_string(status) + ", stderr: " + err);
            }
    }
    std::printf("(8) NaN/+Inf/-Inf texel: build_sat, check_sat_texels, reference throw; %d of %d sample runs exit 2 "
                "with \"texel (5, 3) is ...: every filter needs finite texels\" and no output -> %s\n",
                passed, total, passed == total ? "PASS" : "FAIL");
}
TEST_SUITE_END();
