// OpenImageIO's TextureSystem as the project's peer (host/io/oiio_texture.h): that a lookup means the same point
// to OIIO as to texfilter, what OIIO's trilinear does with a footprint, that its answers on a constant are that
// constant, and that the temporary texture file never outlives the call.
//
// One test case a check (ctest: oiio_texture.CASE), each printing its measured numbers.
//
// Tolerances. OIIO takes u, v and the gradients as float and computes the texel coordinate x = s·w − ½ in
// float: s is off by ≤ 2^-24·|u|, the product and the difference are each rounded (≤ 2^-24·(|x| + ½) each), so
// x is off by ≤ 3·2^-24·(|u|·w + 1) texels (and y likewise). A bilinear result moves by at most the texel contrast
// across (down) per texel of x (y) — support.h's texel_contrast. Its weights (1 − f, f) are rounded once each
// and its sum of 4 products of values ≤ 1 rounds ≤ 4 times: ≤ 6·2^-24 more. A constant c comes back through every
// MIP level (each a normalised box sum, ≤ 9 terms a texel on NPOT sides: ≤ 9 roundings) and every tap of the
// lookup (≤ probes × taps × 2 levels products and sums): relative ≤ (9·levels + 2·probes·taps + 8)·2^-24.
#include "core/filter.h"
#include "io/oiio_texture.h"
#include "reference/reference.h"
#include "support.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <random>
#include <string>
#include <vector>

using namespace tf;
using namespace tf::test;
namespace fs = std::filesystem;

namespace {

constexpr double kFloatStep = 1.0 / 16777216.0; // 2^-24: float's relative rounding

// TMPDIR pointed at a fresh directory for the test's lookups (where io/oiio_texture.h makes its private
// directory), the old value back afterwards; leftovers() lists what is still in it.
class ScopedTmpdir {
public:
    explicit ScopedTmpdir(const std::string& name) : dir_(make_work_dir("oiio-" + name) / "tmp")
    {
        fs::create_directories(dir_);
        if (const char* old = std::getenv("TMPDIR"))
            old_ = old;
        setenv("TMPDIR", dir_.c_str(), 1);
    }
    ScopedTmpdir(const ScopedTmpdir&) = delete;
    ScopedTmpdir& operator=(const ScopedTmpdir&) = delete;
    ~ScopedTmpdir()
    {
        if (old_)
            setenv("TMPDIR", old_->c_str(), 1);
        else
            unsetenv("TMPDIR");
    }
    const fs::path& dir() const { return dir_; }
    std::string leftovers() const
    {
        std::string names;
        for (const fs::directory_entry& entry : fs::directory_iterator(dir_))
            names += " " + entry.path().filename().string();
        return names;
    }

private:
    fs::path dir_;
    std::optional<std::string> old_;
};

// The lookups through OIIO with TMPDIR at a fresh directory, checked empty afterwards.
std::vector<glm::vec4> oiio_lookups(const std::string& name, const Image& image, const std::vector<Lookup>& lookups,
                                    Wrap wrap, OiioTextureMode mode)
{
    const ScopedTmpdir tmp(name);
    std::vector<glm::vec4> colors = oiio_texture_lookups(image, lookups, wrap, mode);
    const std::string left = tmp.leftovers();
    CHECK(left.empty(), "left in TMPDIR:" + left);
    return colors;
}

// R = x / w and G = y / h at texel (x, y): linear in the texel coordinate, so bilinear (and the cubic B-spline,
// which reproduces lines) at uv gives ((u·w − ½) / w, (v·h − ½) / h) away from the edges.
Image ramp(int width, int height)
{
    Image image = make_image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.at(x, y) = glm::vec4(float(x) / float(width), float(y) / float(height), 0.25f, 1.0f);
    return image;
}

Image random_texels(int width, int height, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> value(0.0f, 1.0f);
    Image image = make_image(width, height);
    for (glm::vec4& t : image.texels)
        t = glm::vec4(value(rng), value(rng), value(rng), value(rng));
    return image;
}

// Lookups at uniform random uv in [lo, hi)², every gradient `gradient` (0: a point; 1e-7: a tiny footprint).
std::vector<Lookup> point_lookups(int count, unsigned seed, double lo, double hi, double gradient)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uv(lo, hi);
    std::vector<Lookup> lookups(static_cast<size_t>(count));
    for (Lookup& l : lookups) {
        l.u = uv(rng);
        l.v = uv(rng);
        l.dudx = l.dvdy = gradient;
    }
    return as_float(lookups); // what OIIO is given: the expectations use the same numbers
}

int taps_of(OiioInterp interp)
{
    switch (interp) {
    case OiioInterp::closest: return 1;
    case OiioInterp::bilinear: return 4;
    case OiioInterp::bicubic:
    case OiioInterp::smartbicubic: return 16;
    }
    return 16;
}

} // namespace

TEST_CASE("modes")
{
    const std::vector<OiioTextureMode>& modes = all_oiio_texture_modes();
    CHECK_EQ(modes.size(), 8);
    for (const OiioTextureMode& mode : modes)
        CHECK(parse_oiio_texture_mode(to_string(mode)) == mode, to_string(mode));
    CHECK(to_string(OiioTextureMode{OiioMip::trilinear, OiioInterp::bilinear}) == "trilinear");
    CHECK(to_string(OiioTextureMode{OiioMip::aniso, OiioInterp::smartbicubic}) == "aniso-smartbicubic");
    CHECK(parse_oiio_interp("bicubic") == OiioInterp::bicubic);
    CHECK_THROWS_WITH(parse_oiio_texture_mode("ewa"), "unknown OpenImageIO texture mode 'ewa'");
    CHECK_THROWS_WITH(parse_oiio_texture_mode("aniso-bilinear"), "expected one of: trilinear, trilinear-closest");
    CHECK_THROWS_WITH(parse_oiio_interp("cubic"), "closest, bilinear, bicubic, smartbicubic");
}

// Every mode, every wrap, footprints from a sixteenth of a texel to past the whole texture, stretched and
// sheared: a constant texture gives its constant.
TEST_CASE("constant")
{
    const glm::dvec4 c(0.25, 0.5, 0.75, 1.0);
    const int width = 37, height = 23;
    const Image image = make_image(width, height, glm::vec4(c));
    FootprintRanges ranges;
    ranges.texture_size = width;
    ranges.max_stretch = 4.0;
    ranges.max_shear = 0.5;
    const std::vector<Lookup> lookups = as_float(random_footprint_lookups(300, 7, ranges));
    const int levels = 6; // 37x23 down to 1x1
    for (Wrap wrap : {Wrap::repeat, Wrap::clamp, Wrap::mirror})
        for (const OiioTextureMode& mode : all_oiio_texture_modes()) {
            const int probes = mode.mip == OiioMip::aniso ? 64 : 1; // aniso: at most 2 × TextureOpt::anisotropic
            const double bound = (9.0 * levels + 2.0 * probes * taps_of(mode.interp) + 8.0) * kFloatStep;
            const std::vector<glm::vec4> colors = oiio_lookups("constant", image, lookups, wrap, mode);
            double worst = 0;
            for (size_t i = 0; i < colors.size(); ++i) {
                const double error = max_channel_diff(glm::dvec4(colors[i]), c);
                worst = std::max(worst, std::isnan(error) ? INFINITY : error);
            }
            CHECK(worst <= bound, to_string(wrap) + " " + to_string(mode) + ": worst " + show(worst) + ", bound " +
                                      show(bound));
            std::printf("constant %s %s: worst %.3g (bound %.3g)\n", to_string(wrap).c_str(), to_string(mode).c_str(),
                        worst, bound);
        }
}

// OIIO's u, v and texel centres are texfilter's: on a ramp, at interior points, bilinear and the cubic B-spline
// (bicubic, smartbicubic) give the ramp's value at uv in either mip mode, with zero and with tiny gradients;
// closest gives the texel that contains uv. A flipped t axis would give 1 − v in G; a texel-corner convention
// would be half a texel (0.5/w, 0.5/h) off.
TEST_CASE("ramp")
{
    const int width = 45, height = 29;
    const Image image = ramp(width, height);
    for (double gradient : {0.0, 1e-7}) {
        // Two texels in from every edge: no tap (the B-spline's reach 2) leaves the texture.
        std::vector<Lookup> lookups = point_lookups(400, 11, 0.0, 1.0, gradient);
        std::erase_if(lookups, [&](const Lookup& l) {
            return l.u * width < 2.5 || l.u * width > width - 2.5 || l.v * height < 2.5 || l.v * height > height - 2.5;
        });
        for (const OiioTextureMode& mode : all_oiio_texture_modes()) {
            const std::vector<glm::vec4> colors = oiio_lookups("ramp", image, lookups, Wrap::clamp, mode);
            double worst = 0;
            int checked = 0;
            for (size_t i = 0; i < lookups.size(); ++i) {
                const Lookup& l = lookups[i];
                const double x = l.u * width, y = l.v * height;
                glm::dvec2 expected((x - 0.5) / width, (y - 0.5) / height);
                if (mode.interp == OiioInterp::closest) {
                    // Within float's reach of a texel edge the texel is either one: not a convention.
                    if (std::abs(x - std::round(x)) < 1e-4 || std::abs(y - std::round(y)) < 1e-4)
                        continue;
                    expected = glm::dvec2(std::floor(x) / width, std::floor(y) / height);
                }
                // The coordinate's float error, in ramp units (slope 1/w a texel across, 1/h down), plus the
                // sum's roundings.
                const double sum = (2.0 + taps_of(mode.interp)) * kFloatStep;
                const glm::dvec2 bound(3.0 * kFloatStep * (x + 1.0) / width + sum,
                                       3.0 * kFloatStep * (y + 1.0) / height + sum);
                const glm::dvec2 error(std::abs(colors[i].r - expected.x), std::abs(colors[i].g - expected.y));
                worst = std::max({worst, error.x / bound.x, error.y / bound.y});
                ++checked;
                CHECK(error.x <= bound.x && error.y <= bound.y,
                      to_string(mode) + " at uv (" + show(l.u) + ", " + show(l.v) + "): " + show(glm::dvec4(colors[i])) +
                          ", expected rg " + show(expected.x) + ", " + show(expected.y));
            }
            std::printf("ramp %s gradient %g: %d lookups, worst error %.3g of its bound\n", to_string(mode).c_str(),
                        gradient, checked, worst);
        }
    }
}

// Point lookups anywhere in [-2, 3)² on random texels, each wrap: OIIO's bilinear is tf::reference_bilinear's,
// so repeat, clamp and mirror mean what they mean in texfilter (OIIO's periodic, clamp and mirror).
TEST_CASE("wrap")
{
    const int width = 45, height = 29;
    const Image image = random_texels(width, height, 5);
    const std::vector<Lookup> lookups = point_lookups(600, 13, -2.0, 3.0, 0.0);
    for (Wrap wrap : {Wrap::repeat, Wrap::clamp, Wrap::mirror})
        for (OiioMip mip : {OiioMip::trilinear, OiioMip::aniso}) {
            const OiioTextureMode mode{mip, OiioInterp::bilinear};
            const std::vector<glm::vec4> colors = oiio_lookups("wrap", image, lookups, wrap, mode);
            double worst = 0;
            for (size_t i = 0; i < lookups.size(); ++i) {
                const Lookup& l = lookups[i];
                const glm::dvec4 expected = reference_bilinear(image, l.u, l.v, wrap);
                double across = 0, down = 0;
                texel_contrast(image, l.u, l.v, wrap, across, down);
                const double bound = 3.0 * kFloatStep * ((std::abs(l.u) * width + 1.0) * across +
                                                         (std::abs(l.v) * height + 1.0) * down) +
                                     6.0 * kFloatStep;
                const double error = max_channel_diff(glm::dvec4(colors[i]), expected);
                worst = std::max(worst, error / bound);
                CHECK(error <= bound, to_string(wrap) + " " + to_string(mode) + " at uv (" + show(l.u) + ", " +
                                          show(l.v) + "): " + show(glm::dvec4(colors[i])) + ", reference " +
                                          show(expected));
            }
            std::printf("wrap %s %s: worst error %.3g of its bound\n", to_string(wrap).c_str(), to_string(mode).c_str(),
                        worst);
        }
}

// OIIO's trilinear footprint (texturesys.cpp, compute_miplevels): the largest single gradient component f
// (in uv), times min(width, height), is the footprint F in texels; the levels are m − 1 and m for the first m with
// F / 2^m ≤ 1, blended linearly in F: weight 2F / 2^m − 1 on level m. A 64x32 texture of one-texel black and
// white columns: level 0 at a white texel's centre is 1, every level above 0.5 exactly (box averages of
// pairs), so the answer is 1 − w/2, w level 1's weight: 0 for F ≤ 1, F − 1 for 1 < F ≤ 2, 1 above. The
// spec's rule (λ = log2 of the longest gradient in texels of each axis) would give w = log2 F and 64 along u.
TEST_CASE("trilinear-level")
{
    const int width = 64, height = 32;
    Image image = make_image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.at(x, y) = glm::vec4(float(x % 2 == 0), 0.0f, 0.0f, 1.0f);
    const double u = 10.5 / width, v = 5.5 / height; // texel (10, 5): white
    struct Case {
        const char* what;
        double dudx, dvdx, dudy, dvdy;
        double footprint; // F in min(w, h) texels
    };
    const double s = 1.0 / height; // one texel of min(width, height)
    const std::vector<Case> cases = {
        {"magnified", 0.5 * s, 0, 0, 0.5 * s, 0.5},
        {"one texel", 1.0 * s, 0, 0, 0, 1.0},
        {"1.25 along u", 1.25 * s, 0, 0, 0, 1.25},
        {"1.5 along u", 1.5 * s, 0, 0, 0, 1.5},
        {"1.5 along v (y gradient)", 0, 0, 0, 1.5 * s, 1.5},
        {"1.75 along u, 0.25 along v", 1.75 * s, 0, 0, 0.25 * s, 1.75},
        {"1.5 diagonal (length 2.12)", 1.5 * s, 1.5 * s, 0, 0, 1.5},
        {"1.5 diagonal in y (length 2.12)", 0, 0, -1.5 * s, 1.5 * s, 1.5},
        {"two texels", 2.0 * s, 0, 0, 0, 2.0},
        {"three texels", 3.0 * s, 0, 0, 0, 3.0},
    };
    std::vector<Lookup> lookups;
    for (const Case& c : cases)
        lookups.push_back({u, v, c.dudx, c.dvdx, c.dudy, c.dvdy});
    lookups = as_float(lookups);
    const std::vector<glm::vec4> colors =
        oiio_lookups("trilinear-level", image, lookups, Wrap::repeat, {OiioMip::trilinear, OiioInterp::bilinear});
    for (size_t i = 0; i < cases.size(); ++i) {
        const double weight = std::clamp(cases[i].footprint - 1.0, 0.0, 1.0);
        const double expected = 1.0 - 0.5 * weight;
        // Exact blends of 1 and 0.5 but for the footprint's float rounding: F is off by ≤ 2·2^-24·F, w by as much.
        const double bound = 4.0 * kFloatStep * cases[i].footprint + 4.0 * kFloatStep;
        CHECK_NEAR(double(colors[i].r), expected, bound);
        // The spec's λ: log2 of the longer gradient in texels (u scaled by the width, v by the height).
        const double lambda = std::log2(std::max(std::hypot(cases[i].dudx * width, cases[i].dvdx * height),
                                                 std::hypot(cases[i].dudy * width, cases[i].dvdy * height)));
        std::printf("trilinear-level %-32s F %.2f: R %.6f (OIIO's rule %.6f; the spec's lambda %.2f would give %.6f)\n",
                    cases[i].what, cases[i].footprint, double(colors[i].r), expected, lambda,
                    1.0 - 0.5 * std::clamp(lambda, 0.0, 1.0));
    }
}

// Bad input is refused before anything is made, and no temporary outlives a call that fails.
TEST_CASE("bad-input")
{
    const ScopedTmpdir tmp("bad-input");
    const std::vector<Lookup> lookups = {{0.5, 0.5, 0.01, 0, 0, 0.01}};
    const OiioTextureMode mode{OiioMip::aniso, OiioInterp::bilinear};
    CHECK_THROWS_WITH(oiio_texture_lookups(Image{}, lookups, Wrap::repeat, mode), "an empty or inconsistent 0x0 texture");
    Image inconsistent = make_image(4, 4);
    inconsistent.texels.pop_back();
    CHECK_THROWS_WITH(oiio_texture_lookups(inconsistent, lookups, Wrap::repeat, mode), "inconsistent 4x4 texture");
    // No temporary directory to be had: the call fails naming where it tried.
    const fs::path missing = tmp.dir() / "missing";
    setenv("TMPDIR", missing.c_str(), 1);
    CHECK_THROWS_WITH(oiio_texture_lookups(make_image(4, 4), lookups, Wrap::repeat, mode), "missing");
    setenv("TMPDIR", tmp.dir().c_str(), 1);
    CHECK(!fs::exists(missing));
    // No lookups at all: nothing to answer, nothing left.
    CHECK(oiio_texture_lookups(make_image(4, 4), {}, Wrap::repeat, mode).empty());
    const std::string left = tmp.leftovers();
    CHECK(left.empty(), "left in TMPDIR:" + left);
}
