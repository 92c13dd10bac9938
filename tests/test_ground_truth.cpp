// Tests of the ground truth (stratified pixel-filter samples, reference_ground_truth), the PFM reader and
// writer and the benchmark's measures, all on the CPU. Expected values come from the maths in the
// comments, never from the code under test; each tolerance says where it comes from.
#include "bench/metrics.h"
#include "texture/error.h"
#include "core/filter.h"
#include "reference/ground_truth.h"
#include "texture/image.h"
#include "texture/mip.h"
#include "io/pfm.h"
#include "reference/reference.h"
#include "scene/scene.h"
#include "support.h"

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

using glm::dvec2;
using glm::dvec4;
using tf::PixelFilter;
using tf::Wrap;
using tf::test::show;

namespace {

// ---------------------------------------------------------------------------------------------------
// Helpers.

// The largest of a set of errors; a NaN sticks, so that it fails the limit it is checked against.
struct Worst {
    double value = 0.0;
    void see(double v) { value = std::isnan(v) || std::isnan(value) ? NAN : std::max(value, v); }
};

const char* name(PixelFilter f) { return f == PixelFilter::box ? "box" : "gaussian"; }

tf::SamplerOptions truth_options(PixelFilter filter, int side, Wrap wrap)
{
    tf::SamplerOptions options;
    options.filter = tf::Filter::ground_truth;
    options.pixel_filter = filter;
    options.truth_side = side;
    options.wrap = wrap;
    return options;
}

// How far a Gaussian sample can land from the pixel centre. The radius is sigma * sqrt(-2 ln(1 - a)) with a
// in radial stratum k of `side`, jittered by 24 hash bits: a <= (side - 2^-24) / side, so
// 1 - a >= 2^-24 / side and r <= sigma * sqrt(2 ln(side * 2^24)): 3.11 px at side 16, 3.22 px at 64.
double gaussian_reach(int side) { return tf::ground_truth_sigma * std::sqrt(2.0 * std::log(side * 16777216.0)); }

// Where a pixel's samples can land, in pixel coordinates: the pixel itself (box), or the square of
// half side gaussian_reach about its centre.
struct Footprint {
    dvec2 lo, hi;
};
Footprint footprint(int x, int y, PixelFilter filter, int side)
{
    if (filter == PixelFilter::box)
        return {dvec2(x, y), dvec2(x + 1, y + 1)};
    const double r = gaussian_reach(side);
    return {dvec2(x + 0.5 - r, y + 0.5 - r), dvec2(x + 0.5 + r, y + 0.5 + r)};
}

// The zoom and minify quads face the camera, so uv is affine in the pixel position: a footprint's uv range
// is spanned by its corners (the map may run either way, so take the min and max).
struct UvRange {
    dvec2 lo{INFINITY}, hi{-INFINITY};
    int hits = 0;                 // corners on the quad
    int beyond[4] = {0, 0, 0, 0}; // corners past the quad's -s, +s, -t, +t edge
};
UvRange uv_range(const tf::SceneParams& scene, const Footprint& f)
{
    UvRange range;
    const dvec2 offset(scene.extent.z, scene.extent.w), half(scene.extent.x, scene.extent.y);
    for (double px : {f.lo.x, f.hi.x})
        for (double py : {f.lo.y, f.hi.y}) {
            const tf::PixelHit hit = tf::reference_hit(scene, px, py);
            range.lo = glm::min(range.lo, hit.uv);
            range.hi = glm::max(range.hi, hit.uv);
            range.hits += hit.hit;
            const dvec2 st = hit.uv - offset; // the quad is |s| <= half.x, |t| <= half.y
            range.beyond[0] += st.x < -half.x;
            range.beyond[1] += st.x > half.x;
            range.beyond[2] += st.y < -half.y;
            range.beyond[3] += st.y > half.y;
        }
    return range;
}

// Largest |colour - expected| over RGB.
double rgb_diff(const glm::vec4& colour, const dvec4& expected)
{
    double d = 0.0;
    for (int c = 0; c < 3; ++c)
        d = std::max(d, std::fabs(double(colour[c]) - expected[c]));
    return d;
}

// 1-texel checker of 0 and 1 in linear RGB (alpha 1): texel (i, j) is (i + j) mod 2.
tf::Image checker(int size)
{
    tf::Image image = tf::make_image(size, size);
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i)
            image.at(i, j) = glm::vec4(glm::vec3(float((i + j) % 2)), 1.0f);
    return image;
}

// ---------------------------------------------------------------------------------------------------
// 1. Box samples: inside the pixel, one per stratum of the side x side grid, the same on every call.

TEST_CASE("box-samples")
{
    const int pixels[][2] = {{0, 0}, {5, 3}, {63, 17}, {1000, 2000}};
    for (const auto& p : pixels)
        for (int side : {1, 4, 16}) {
            const int x = p[0], y = p[1];
            std::vector<int> per_stratum(size_t(side * side), 0);
            bool inside = true, repeatable = true;
            for (int i = 0; i < side * side; ++i) {
                const dvec2 s = tf::ground_truth_sample(x, y, i, side, PixelFilter::box);
                repeatable = repeatable && tf::ground_truth_sample(x, y, i, side, PixelFilter::box) == s;
                if (!(s.x >= x && s.x < x + 1 && s.y >= y && s.y < y + 1)) {
                    inside = false;
                    continue;
                }
                // Stratum (column, row) of width 1/side in each axis.
                const int col = int((s.x - x) * side), row = int((s.y - y) * side);
                ++per_stratum[size_t(row * side + col)];
            }
            const std::string where = "pixel " + std::to_string(x) + "," + std::to_string(y) + " side " +
                                      std::to_string(side);
            CHECK(inside, where);
            // side^2 samples over side^2 strata: one each exactly when none is empty and none is doubled.
            const auto [fewest, most] = std::minmax_element(per_stratum.begin(), per_stratum.end());
            CHECK(*fewest == 1 && *most == 1, where + ": " + std::to_string(*fewest) + ".." + std::to_string(*most));
            CHECK(repeatable, where);
        }
}

// ---------------------------------------------------------------------------------------------------
// 2. Gaussian samples: the moments and the median radius of a 2D Gaussian of sigma 0.5 px.

TEST_CASE("gaussian-samples")
{
    const int side = 64, n = side * side, x = 12, y = 34;
    const dvec2 centre(x + 0.5, y + 0.5);
    const double sigma = tf::ground_truth_sigma;
    // Half the mass of a 2D Gaussian lies within r = sigma sqrt(2 ln 2): P(r < R) = 1 - exp(-R^2 / 2 sigma^2).
    const double median_radius = sigma * std::sqrt(2.0 * std::log(2.0));
    dvec2 sum(0.0), sum_sq(0.0);
    int below_median = 0;
    bool repeatable = true;
    for (int i = 0; i < n; ++i) {
        const dvec2 s = tf::ground_truth_sample(x, y, i, side, PixelFilter::gaussian);
        repeatable = repeatable && tf::ground_truth_sample(x, y, i, side, PixelFilter::gaussian) == s;
        const dvec2 d = s - centre;
        sum += d;
        sum_sq += d * d;
        below_median += glm::length(d) < median_radius;
    }
    CHECK(repeatable);
    const dvec2 mean = sum / double(n), var = sum_sq / double(n); // second moment about the true centre
    // Plain Monte Carlo with N = 4096 would give the mean to sigma / sqrt(N) = 0.0078 px and the variance
    // to sigma^2 sqrt(2 / N) = 0.0055: 0.01 would be under 2 sd. Stratified (64 radial quantiles x 64
    // angles), what is left is mostly the spread inside the outermost ring, where -ln(1 - a) is ln 64 plus
    // an Exp(1) variate: x^2 there has sd ~0.35 px^2 over 64 samples -> ~7e-4 on the variance, and x an
    // sd ~0.12 px -> ~2e-4 px on the mean. 0.01 is over 10 of those, and still fails a sigma 3% off
    // (variance off by 0.015) or a centre 0.01 px off.
    CHECK_LE("gaussian: |mean - centre| (px)", std::max(std::fabs(mean.x), std::fabs(mean.y)), 0.01);
    CHECK_LE("gaussian: |per-axis variance - sigma^2| (px^2)",
             std::max(std::fabs(var.x - sigma * sigma), std::fabs(var.y - sigma * sigma)), 0.01);
    // r < median_radius exactly when the radial quantile a < 1/2: 32 of the 64 radial strata, so the
    // fraction is 1/2 up to ties at the boundary; 0.01 is 41 samples.
    CHECK_LE("gaussian: |fraction within median radius - 1/2|", std::fabs(below_median / double(n) - 0.5), 0.01);

    // Every sample within gaussian_reach (what tests 3 and 4 take as the Gaussian's footprint).
    Worst reach_excess{-INFINITY}; // negative: the margin left
    for (const auto& p : {dvec2(0, 0), dvec2(12, 34), dvec2(63, 63), dvec2(777, 5)})
        for (int s : {16, 64}) {
            const double reach = gaussian_reach(s);
            for (int i = 0; i < s * s; ++i) {
                const dvec2 d = tf::ground_truth_sample(int(p.x), int(p.y), i, s, PixelFilter::gaussian) -
                                (p + 0.5);
                reach_excess.see(std::max(std::fabs(d.x), std::fabs(d.y)) - reach);
            }
        }
    CHECK_LE("gaussian: max(|dx|, |dy|) - reach (px)", reach_excess.value, 0.0);
}

// ---------------------------------------------------------------------------------------------------
// 3. A constant texture: the constant wherever the footprint lies on the quad, the background wherever it
// lies off it, a blend of the two in between; every wrap mode, both pixel filters. The quad's edges run
// through pixel middles, so a box pixel on an edge is covered exactly by the share of its corners that hit
// (1/2 along an edge, 1/4 at a corner): side 16 is even, and the edge falls between two strata columns.

TEST_CASE("constant-texture")
{
    const int w = 64, size = 64, side = 16;
    const glm::vec4 colour(0.25f, 0.5f, 0.75f, 1.0f);
    const tf::MipChain chain = tf::build_mip_chain(tf::make_image(w, w, colour));
    tf::SceneParams scene = tf::make_scene(tf::SceneKind::zoom, size, size, w);
    // The zoom quad is unbounded; bound it to 20.5 px either side of the image centre (a pixel corner;
    // 1/(8w) uv a pixel) so that some pixels miss it and its edges halve pixels 11 and 52.
    scene.extent.x = scene.extent.y = float(20.5 / (8.0 * w));
    const dvec4 c(colour), background(scene.background);
    for (PixelFilter filter : {PixelFilter::box, PixelFilter::gaussian})
        for (Wrap wrap : {Wrap::repeat, Wrap::clamp, Wrap::mirror}) {
            const tf::Image truth = tf::reference_ground_truth(scene, chain, truth_options(filter, side, wrap));
            CHECK(truth.width == size && truth.height == size);
            if (truth.width != size || truth.height != size)
                continue;
            Worst on, off, blend, coverage;
            int n_on = 0, n_off = 0, n_blend = 0;
            for (int y = 0; y < size; ++y)
                for (int x = 0; x < size; ++x) {
                    const glm::vec4& t = truth.at(x, y);
                    const UvRange r = uv_range(scene, footprint(x, y, filter, side));
                    if (r.hits == 4) { // a convex quad holds the square its corners span
                        on.see(rgb_diff(t, c));
                        ++n_on;
                    } else if (*std::max_element(r.beyond, r.beyond + 4) == 4) { // all past one edge
                        off.see(rgb_diff(t, background));
                        ++n_off;
                    } else { // a mean of the two colours: each channel between them
                        for (int k = 0; k < 3; ++k)
                            blend.see(std::max(std::min(c[k], background[k]) - double(t[k]),
                                               double(t[k]) - std::max(c[k], background[k])));
                        if (filter == PixelFilter::box)
                            coverage.see(rgb_diff(t, background + (c - background) * (r.hits / 4.0)));
                        ++n_blend;
                    }
                }
            const std::string what = std::string("constant ") + name(filter) + " " + tf::to_string(wrap);
            CHECK(n_on > 0 && n_off > 0 && n_blend > 0,
                  what + ": " + std::to_string(n_on) + " on, " + std::to_string(n_off) + " off, " +
                      std::to_string(n_blend) + " between");
            // Bilinear weights sum to 1 in double, and 256 equal floats add and divide by 256 exactly: the
            // only error is double rounding (~1e-16) before the float store. 1e-6 is a few float ulps.
            CHECK_LE(what + ": on the quad, |truth - constant|", on.value, 1e-6);
            CHECK_LE(what + ": off the quad, |truth - background|", off.value, 1e-6);
            CHECK_LE(what + ": edges, distance outside [bg, constant]", blend.value, 1e-6);
            // The scene's float constants put the edge within ~1e-6 px of the strata boundary (20.5 px
            // times a float rounding): a sample that close could land on the other side, 1/256 of the
            // contrast (0.72) -> 0.0028. A stratum's shift (16 samples) is 0.045.
            if (filter == PixelFilter::box)
                CHECK_LE(what + ": edges, |truth - share of corners|", coverage.value,
                         rgb_diff(colour, background) / 256 + 1e-6);
        }
}

// ---------------------------------------------------------------------------------------------------
// 4. A linear ramp: any filter symmetric about the pixel centre reproduces a linear function exactly,
// so both truths equal the ramp at the centre's uv, up to the sampling error of the mean sample position.

TEST_CASE("linear-ramp")
{
    const int w = 64, size = 64, side = 64;
    // Texel x holds its centre's u, (x + 0.5) / w (exact in float: a multiple of 1/128).
    tf::Image ramp = tf::make_image(w, w);
    for (int y = 0; y < w; ++y)
        for (int x = 0; x < w; ++x)
            ramp.at(x, y) = glm::vec4(glm::vec3(float((x + 0.5) / w)), 1.0f);
    const tf::MipChain chain = tf::build_mip_chain(ramp);
    const tf::SceneParams scene = tf::make_scene(tf::SceneKind::zoom, size, size, w);

    // The premise, checked on its own: between the first and last texel centres, bilinear reconstruction
    // of the ramp is u itself ((1 - a) (i + 0.5) / w + a (i + 1.5) / w = (i + 0.5 + a) / w = u).
    Worst premise;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const dvec2 uv = tf::reference_hit(scene, x + 0.5, y + 0.5).uv;
            premise.see(std::fabs(tf::reference_bilinear(chain.levels[0], uv.x, uv.y, Wrap::clamp).x - uv.x));
        }
    CHECK_LE("ramp: |bilinear(uv) - u| at pixel centres", premise.value, 1e-9);

    // Mean sample position off the centre by e px moves the result by e / (8 w) = e / 512 in u.
    // Box: the mean of 4096 jitters, each uniform over 1/64 px, is off by sd (1/64) / sqrt(12 * 4096)
    // = 7e-5 px -> 1.4e-7 in u (max over 4096 pixels ~ 6e-7), plus a float store (3e-8 at u ~ 0.5).
    // 1e-5 u is 0.005 px: a systematic shift of one stratum (1/64 px -> 3e-5) fails it.
    // Gaussian: test 2's mean error, < 0.01 px -> 2e-5 in u; 1e-4 (0.05 px) leaves room for the pixels
    // test 2 does not look at, and still fails a half-stratum radial bias or a wrong centre (0.5 px).
    for (PixelFilter filter : {PixelFilter::box, PixelFilter::gaussian}) {
        const double limit = filter == PixelFilter::box ? 1e-5 : 1e-4;
        const tf::Image truth = tf::reference_ground_truth(scene, chain, truth_options(filter, side, Wrap::clamp));
        Worst error;
        int used = 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                // Only footprints a texel or more inside the texture: there the reconstruction is the ramp
                // and the clamp never acts.
                const UvRange r = uv_range(scene, footprint(x, y, filter, side));
                if (!(r.hits == 4 && r.lo.x * w >= 1 && r.hi.x * w <= w - 1 && r.lo.y * w >= 1 && r.hi.y * w <= w - 1))
                    continue;
                ++used;
                const double u = tf::reference_hit(scene, x + 0.5, y + 0.5).uv.x;
                error.see(rgb_diff(truth.at(x, y), dvec4(u)));
            }
        CHECK(used == size * size, std::to_string(used) + " pixels inside"); // zoom shows 8x8 central texels
        CHECK_LE(std::string("ramp ") + name(filter) + ": |truth - u(centre)|", error.value, limit);
    }
}

// ---------------------------------------------------------------------------------------------------
// 5. A 1-texel checker under minification. Its bilinear reconstruction is separable:
//    f(x, y) = 1/2 - 1/2 g(x) g(y), g the triangle wave of period 2 texels with g(i + 1/2) = (-1)^i,
// so a box over whole periods (4 texels a pixel) integrates to exactly 1/2, whatever the alignment. The
// Gaussian (sigma 0.5 px) damps the wave's fundamental, 1/2 cycle a texel, by exp(-2 pi^2 sigma^2 f^2):
// 2.7e-9 at 4 texels a pixel (sigma = 2 texels), 1.5e-5 at 3 (sigma = 1.5): it gives 1/2 too.
// At 4 texels a pixel both are exact, so what is left is sampling error and neither beats the other by
// the maths: no comparison there. At 3 texels a pixel with pixel edges on texel edges the box takes
// three whole texels a side: each texel [i, i + 1] of g averages (-1)^i / 2, three of them (-1)^i / 6,
// so the box gives 1/2 + (c - 1/2) / 36 (c the checker value of the pixel's middle texel): off by 1/72
// = 0.0139 everywhere, while the Gaussian stays at 1/2. There the Gaussian must be the closer one.
//
// Sampling error (N = 4096 stratified samples): the integrand lies in [0, 1], so plain Monte Carlo's sd is
// at most 0.5 / sqrt(N) = 0.0078 a pixel; stratification only lowers it. 0.04 is 5 of those, per pixel;
// the image mean averages 4096 independently jittered pixels (sd <= 1.2e-4), so 0.002 there. The box's
// strata are 1/16 texel square at 4 texels a pixel; |grad f| <= 1/2 * 2 = 1 a texel per axis, so f moves
// by at most 1/8 within one, a sample strays from its stratum's mean with sd <= 1/16, and the pixel's sd
// is <= (1/16) / sqrt(N) = 0.001: 0.01 (10 sd) per pixel for the box.

TEST_CASE("checker")
{
    const int w = 64, size = 64, side = 64;
    const tf::MipChain chain = tf::build_mip_chain(checker(w));

    const tf::SceneParams scene4 = tf::make_minified_scene(size, size, w, 4.0);
    for (PixelFilter filter : {PixelFilter::box, PixelFilter::gaussian}) {
        const tf::Image truth = tf::reference_ground_truth(scene4, chain, truth_options(filter, side, Wrap::repeat));
        Worst error;
        double sum = 0.0, off = 0.0;
        for (const glm::vec4& t : truth.texels) {
            error.see(rgb_diff(t, dvec4(0.5)));
            sum += t.r;
            off += std::fabs(t.r - 0.5);
        }
        const std::string what = std::string("checker 4 texels/px ") + name(filter);
        std::printf("  %s: mean |truth - 1/2| %.4g (sampling noise only)\n", what.c_str(), off / double(size * size));
        CHECK_LE(what + ": |truth - 1/2|", error.value, filter == PixelFilter::box ? 0.01 : 0.04);
        CHECK_LE(what + ": |image mean - 1/2|", std::fabs(sum / double(size * size) - 0.5), 0.002);
    }

    // 3 texels a pixel; the image centre (a pixel corner) at uv (1/2, 1/2), texel edge 32 of 64: every
    // pixel edge is then on a texel edge.
    tf::SceneParams scene3 = tf::make_minified_scene(size, size, w, 3.0);
    scene3.extent.z = scene3.extent.w = 0.5f;
    const tf::Image box = tf::reference_ground_truth(scene3, chain, truth_options(PixelFilter::box, side, Wrap::repeat));
    const tf::Image gauss =
        tf::reference_ground_truth(scene3, chain, truth_options(PixelFilter::gaussian, side, Wrap::repeat));
    Worst box_error, gauss_error;
    double box_off = 0.0, gauss_off = 0.0; // mean |truth - 1/2|
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const dvec2 uv = tf::reference_hit(scene3, x + 0.5, y + 0.5).uv; // the middle texel's inside
            const long long i = (long long)std::floor(uv.x * w), j = (long long)std::floor(uv.y * w);
            const double c = double(((i + j) % 2 + 2) % 2);
            box_error.see(rgb_diff(box.at(x, y), dvec4(0.5 + (c - 0.5) / 36.0)));
            gauss_error.see(rgb_diff(gauss.at(x, y), dvec4(0.5)));
            box_off += std::fabs(box.at(x, y).r - 0.5);
            gauss_off += std::fabs(gauss.at(x, y).r - 0.5);
        }
    box_off /= size * size;
    gauss_off /= size * size;
    // Box strata at 3 texels a pixel are 3/64 texel: f moves by at most 3/32 -> sd <= 7e-4; 0.01 as above.
    CHECK_LE("checker 3 texels/px box: |truth - (1/2 + (c - 1/2)/36)|", box_error.value, 0.01);
    CHECK_LE("checker 3 texels/px gaussian: |truth - 1/2|", gauss_error.value, 0.04);
    // The box's mean offset is 1/72 = 0.0139 by the maths; the Gaussian's is sampling noise, at most
    // 0.8 * 0.0078 = 0.006 even for unstratified samples.
    std::printf("  checker 3 texels/px: mean |truth - 1/2|: box %.4g, gaussian %.4g\n", box_off, gauss_off);
    CHECK(gauss_off < box_off, show(gauss_off) + " vs " + show(box_off));
    CHECK_NEAR(box_off, 1.0 / 72.0, 0.002);
}

// ---------------------------------------------------------------------------------------------------
// 6. PFM: bit-exact RGB round trip, the layout the format prescribes, and errors that name the path.

uint32_t bits(float f) { return std::bit_cast<uint32_t>(f); }

std::string read_bytes(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write_bytes(const std::filesystem::path& path, const std::string& bytes)
{
    std::ofstream(path, std::ios::binary) << bytes;
}

TEST_CASE("pfm")
{
    const std::filesystem::path work = tf::test::make_work_dir("ground-truth");
    // 3x2 (not square: a transposition shows), values of every kind of float.
    const float values[18] = {0.0f,      -0.0f,   1.0f,     -1.5f,     3.0e38f,   -3.0e38f,
                              1.0e-40f,  -1.0e-45f, FLT_MIN, FLT_MAX,  0.1f,      -123456.789f,
                              INFINITY,  -INFINITY, std::numeric_limits<float>::quiet_NaN(), 7.0f, 1e-7f, 65504.0f};
    tf::Image image = tf::make_image(3, 2);
    for (int k = 0; k < 6; ++k)
        image.texels[size_t(k)] = glm::vec4(values[3 * k], values[3 * k + 1], values[3 * k + 2], 0.25f);
    const std::string path = (work / "image.pfm").string();
    tf::write_pfm(path, image);

    const tf::Image back = tf::read_pfm(path);
    CHECK(back.width == 3 && back.height == 2 && back.texels.size() == 6);
    if (back.texels.size() == 6)
        for (size_t k = 0; k < 6; ++k) {
            for (int c = 0; c < 3; ++c)
                CHECK(bits(back.texels[k][c]) == bits(image.texels[k][c]),
                      "texel " + std::to_string(k) + " channel " + std::to_string(c));
            CHECK(back.texels[k].a == 1.0f); // PFM has no alpha
        }

    // The file itself: "PF", size, a negative scale (little-endian), then rows bottom first, 3 floats a pixel.
    const std::string bytes = read_bytes(path);
    const std::string header = "PF\n3 2\n-1.0\n";
    CHECK(bytes.size() == header.size() + 6 * 12, std::to_string(bytes.size()) + " bytes");
    CHECK(bytes.compare(0, header.size(), header) == 0);
    if (bytes.size() == header.size() + 6 * 12) {
        auto at = [&](size_t k) { // float k of the data, little-endian
            uint32_t b = 0;
            for (int byte = 3; byte >= 0; --byte)
                b = (b << 8) | uint8_t(bytes[header.size() + 4 * k + size_t(byte)]);
            return b;
        };
        CHECK(at(0) == bits(image.at(0, 1).r)); // first: the bottom row's first pixel
        CHECK(at(5) == bits(image.at(1, 1).b));
        CHECK(at(9) == bits(image.at(0, 0).r)); // then the top row
    }

    // Missing, not a colour PFM ("Pf" is greyscale, "P6" a PPM), truncated: each message names the path.
    const std::string missing = (work / "missing.pfm").string();
    CHECK_THROWS_WITH(tf::read_pfm(missing), missing);
    const std::string grey = (work / "grey.pfm").string();
    write_bytes(grey, "Pf\n1 1\n-1.0\n" + std::string(4, '\0'));
    CHECK_THROWS_WITH(tf::read_pfm(grey), grey);
    const std::string ppm = (work / "ppm.pfm").string();
    write_bytes(ppm, "P6\n1 1\n255\n" + std::string(3, '\0'));
    CHECK_THROWS_WITH(tf::read_pfm(ppm), ppm);
    const std::string truncated = (work / "truncated.pfm").string();
    write_bytes(truncated, bytes.substr(0, bytes.size() - 1));
    CHECK_THROWS_WITH(tf::read_pfm(truncated), truncated);
    const std::string header_only = (work / "header-only.pfm").string();
    write_bytes(header_only, header);
    CHECK_THROWS_WITH(tf::read_pfm(header_only), header_only);
}

// ---------------------------------------------------------------------------------------------------
// 7. Benchmark measures: time summaries, display RMSE and PSNR, flicker.

tf::Image constant(int w, int h, glm::vec3 rgb) { return tf::make_image(w, h, glm::vec4(rgb, 1.0f)); }

TEST_CASE("bench-metrics")
{
    const tf::TimeSummary odd = tf::summarize_times({3, 1, 2});
    CHECK_EQ(odd.min, 1);
    CHECK_EQ(odd.median, 2);
    CHECK_EQ(odd.max, 3);
    CHECK_EQ(odd.frames, 3);
    const tf::TimeSummary even = tf::summarize_times({4, 1, 3, 2});
    CHECK_EQ(even.median, 2.5); // (2 + 3) / 2
    CHECK_EQ(even.min, 1);
    CHECK_EQ(even.max, 4);
    CHECK_EQ(even.frames, 4);
    CHECK_THROWS(tf::summarize_times({}));

    // RMSE in sRGB-encoded units. Encoded values are stored as float (error <= 6e-8 each): 1e-6.
    const tf::Image a = constant(4, 3, {0.2f, 0.5f, 0.01f}), b = constant(4, 3, {0.1f, 0.5f, 0.002f});
    CHECK_EQ(tf::display_rmse(a, a), 0.0);
    double sum = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double d = tf::linear_to_srgb(double(a.texels[0][c])) - tf::linear_to_srgb(double(b.texels[0][c]));
        sum += d * d;
    }
    const double expected_rmse = std::sqrt(sum / 3.0); // every pixel alike: the mean over channels
    CHECK_NEAR(tf::display_rmse(a, b), expected_rmse, 1e-6);
    CHECK_NEAR(tf::display_rmse(b, a), expected_rmse, 1e-6);
    // Clamped to [0, 1] before encoding: 1.5 shows as 1, -0.3 as 0.
    CHECK_NEAR(tf::display_rmse(constant(2, 2, {1.5f, -0.3f, 0.5f}), constant(2, 2, {1.0f, 0.0f, 0.5f})), 0.0, 1e-12);
    CHECK_THROWS(tf::display_rmse(a, constant(3, 4, {0.2f, 0.5f, 0.01f})));

    CHECK_NEAR(tf::psnr_from_rmse(0.1), 20.0, 1e-12);  // 20 log10(1 / 0.1)
    CHECK_NEAR(tf::psnr_from_rmse(1.0), 0.0, 1e-12);
    CHECK_NEAR(tf::psnr_from_rmse(0.01), 40.0, 1e-12);
    CHECK_EQ(tf::psnr_from_rmse(0.0), 99.0);           // the cap

    // Flicker. A truth that moves: two pixels, three frames.
    const std::vector<glm::vec3> pixel0 = {{0.2f, 0.3f, 0.4f}, {0.25f, 0.3f, 0.1f}, {0.6f, 0.05f, 0.1f}};
    const std::vector<glm::vec3> pixel1 = {{0.7f, 0.7f, 0.7f}, {0.7f, 0.8f, 0.5f}, {0.35f, 0.8f, 0.55f}};
    std::vector<tf::Image> truth;
    for (size_t t = 0; t < 3; ++t) {
        tf::Image frame = tf::make_image(2, 1);
        frame.at(0, 0) = glm::vec4(pixel0[t], 1.0f);
        frame.at(1, 0) = glm::vec4(pixel1[t], 1.0f);
        truth.push_back(frame);
    }
    CHECK_NEAR(tf::display_flicker(truth, truth), 0.0, 0.0); // the truth's own motion costs nothing

    // Frames that never change while the truth does: the flicker is the RMS of the truth's encoded change
    // (2 frame pairs x 2 pixels x 3 channels). Float-stored encodings: 1e-6.
    const std::vector<tf::Image> frozen(3, truth[0]);
    double change_sq = 0.0;
    for (const auto* p : {&pixel0, &pixel1})
        for (size_t t = 0; t + 1 < 3; ++t)
            for (int c = 0; c < 3; ++c) {
                const double d = tf::linear_to_srgb((*p)[t + 1][c]) - tf::linear_to_srgb((*p)[t][c]);
                change_sq += d * d;
            }
    CHECK_NEAR(tf::display_flicker(frozen, truth), std::sqrt(change_sq / 12.0), 1e-6);

    // Frames that follow the truth at a constant offset in encoded space (+0.05; the truth encodes to
    // 0.24..0.91, so nothing reaches 1 and clamps)
    // change exactly as it does: 0, up to float round trips through linear (~1e-7).
    std::vector<tf::Image> offset = truth;
    for (tf::Image& frame : offset)
        for (glm::vec4& t : frame.texels)
            for (int c = 0; c < 3; ++c)
                t[c] = float(tf::srgb_to_linear(tf::linear_to_srgb(t[c]) + 0.05));
    CHECK_NEAR(tf::display_flicker(offset, truth), 0.0, 1e-6);

    CHECK_THROWS(tf::display_flicker({truth[0]}, {truth[0]}));           // one frame: no change to measure
    CHECK_THROWS(tf::display_flicker({}, {}));
    CHECK_THROWS(tf::display_flicker(frozen, {truth[0], truth[1]}));    // counts differ
}

} // namespace

