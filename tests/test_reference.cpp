// Tier-1 tests of the CPU reference against hand-computed facts (DESIGN.md section 5).
// Expected values are worked out by hand in the comments, never by calling the code under test.
#include "texture/error.h"
#include "core/filter.h"
#include "texture/image.h"
#include "texture/mip.h"
#include "core/procedural.h"
#include "reference/reference.h"
#include "support.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

using glm::dvec4;
using tf::Filter;
using tf::Wrap;
using tf::test::near;

namespace {

constexpr double kEps = 1e-12;

// A one-row (or one-level) chain from scalar values; channel g = 2*r, b = -r, a = 1 to catch swizzle bugs.
glm::vec4 texel(double r) { return glm::vec4(float(r), float(2 * r), float(-r), 1.0f); }
dvec4 expect(double r) { return dvec4(r, 2 * r, -r, 1.0); }

tf::Image image_from(int w, int h, const std::vector<double>& values) {
    tf::Image image = tf::make_image(w, h);
    for (int i = 0; i < w * h; ++i) image.texels[size_t(i)] = texel(values[size_t(i)]);
    return image;
}

tf::MipChain single_level(tf::Image image) {
    tf::MipChain chain;
    chain.levels.push_back(std::move(image));
    return chain;
}

TEST_CASE("wrap-tables")
{
    // n = 3, i = -7..7, worked out by hand.
    const int repeat[15] = {2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1};
    const int clamp[15] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 2, 2, 2, 2, 2};
    // Mirrored repeat, period 6: 0 1 2 2 1 0 | 0 1 2 ...; -1 maps to 0 (edge texel repeated).
    const int mirror[15] = {0, 0, 1, 2, 2, 1, 0, 0, 1, 2, 2, 1, 0, 0, 1};
    for (int k = 0; k < 15; ++k) {
        const long long i = k - 7;
        CHECK_EQ(tf::wrap_texel(i, 3, Wrap::repeat), repeat[k]);
        CHECK_EQ(tf::wrap_texel(i, 3, Wrap::clamp), clamp[k]);
        CHECK_EQ(tf::wrap_texel(i, 3, Wrap::mirror), mirror[k]);
    }
    for (Wrap w : {Wrap::repeat, Wrap::clamp, Wrap::mirror}) {
        CHECK_EQ(tf::wrap_texel(-5, 1, w), 0);
        CHECK_EQ(tf::wrap_texel(7, 1, w), 0);
    }
    // 10^15 = 1 (mod 3) since 10 = 1 (mod 3); mod 6 it is 4 -> mirror 2*3-1-4 = 1.
    CHECK_EQ(tf::wrap_texel(1000000000000000LL, 3, Wrap::repeat), 1);
    CHECK_EQ(tf::wrap_texel(-1000000000000000LL, 3, Wrap::repeat), 2);
    CHECK_EQ(tf::wrap_texel(1000000000000000LL, 3, Wrap::mirror), 1);
    CHECK_EQ(tf::wrap_texel(1000000000000000LL, 3, Wrap::clamp), 2);
    CHECK_EQ(tf::wrap_texel(-1000000000000000LL, 3, Wrap::clamp), 0);
}

TEST_CASE("nearest")
{
    const tf::Image row = image_from(4, 1, {1, 2, 4, 8});
    CHECK_NEAR(tf::reference_nearest(row, 0.3, 0.5, Wrap::repeat), expect(2), 0.0);   // 1.2 -> 1
    CHECK_NEAR(tf::reference_nearest(row, 0.999, 0.5, Wrap::repeat), expect(8), 0.0); // 3.996 -> 3
    CHECK_NEAR(tf::reference_nearest(row, 0.25, 0.5, Wrap::repeat), expect(2), 0.0);  // exactly 1.0 -> 1
    // u = -0.1 -> -0.4 -> texel -1.
    CHECK_NEAR(tf::reference_nearest(row, -0.1, 0.5, Wrap::repeat), expect(8), 0.0);
    CHECK_NEAR(tf::reference_nearest(row, -0.1, 0.5, Wrap::clamp), expect(1), 0.0);
    CHECK_NEAR(tf::reference_nearest(row, -0.1, 0.5, Wrap::mirror), expect(1), 0.0);
    // u = 1 -> texel 4.
    CHECK_NEAR(tf::reference_nearest(row, 1.0, 0.5, Wrap::repeat), expect(1), 0.0);
    CHECK_NEAR(tf::reference_nearest(row, 1.0, 0.5, Wrap::clamp), expect(8), 0.0);
    CHECK_NEAR(tf::reference_nearest(row, 1.0, 0.5, Wrap::mirror), expect(8), 0.0);
}

TEST_CASE("bilinear-2x2")
{
    // Texels (0,0)=0, (1,0)=1, (0,1)=2, (1,1)=4. Centres at u,v = 0.25, 0.75.
    const tf::Image img = image_from(2, 2, {0, 1, 2, 4});
    CHECK_NEAR(tf::reference_bilinear(img, 0.25, 0.25, Wrap::clamp), expect(0), kEps);
    CHECK_NEAR(tf::reference_bilinear(img, 0.75, 0.25, Wrap::clamp), expect(1), kEps);
    CHECK_NEAR(tf::reference_bilinear(img, 0.25, 0.75, Wrap::clamp), expect(2), kEps);
    CHECK_NEAR(tf::reference_bilinear(img, 0.75, 0.75, Wrap::clamp), expect(4), kEps);
    CHECK_NEAR(tf::reference_bilinear(img, 0.5, 0.25, Wrap::clamp), expect(0.5), kEps);  // (0+1)/2
    CHECK_NEAR(tf::reference_bilinear(img, 0.5, 0.75, Wrap::clamp), expect(3), kEps);    // (2+4)/2
    CHECK_NEAR(tf::reference_bilinear(img, 0.5, 0.5, Wrap::clamp), expect(1.75), kEps);  // 7/4
    // x = 0.25, y = 0.5: .375*0 + .125*1 + .375*2 + .125*4 = 1.375
    CHECK_NEAR(tf::reference_bilinear(img, 0.375, 0.5, Wrap::clamp), expect(1.375), kEps);
    // Left edge of the row v=0.25 at u=0: x = -0.5 blends texel -1 and 0 half and half.
    CHECK_NEAR(tf::reference_bilinear(img, 0.0, 0.25, Wrap::clamp), expect(0), kEps);
    CHECK_NEAR(tf::reference_bilinear(img, 0.0, 0.25, Wrap::repeat), expect(0.5), kEps);
    CHECK_NEAR(tf::reference_bilinear(img, 0.0, 0.25, Wrap::mirror), expect(0), kEps);
}

TEST_CASE("bilinear-borders")
{
    const tf::Image row = image_from(4, 1, {1, 2, 4, 8});
    // u = -0.25: x = -1.5, texels -2, -1 at 1/2 each.
    //   clamp 0,0 -> 1; repeat 2,3 -> (4+8)/2 = 6; mirror 1,0 -> (2+1)/2 = 1.5
    CHECK_NEAR(tf::reference_bilinear(row, -0.25, 0.5, Wrap::clamp), expect(1), kEps);
    CHECK_NEAR(tf::reference_bilinear(row, -0.25, 0.5, Wrap::repeat), expect(6), kEps);
    CHECK_NEAR(tf::reference_bilinear(row, -0.25, 0.5, Wrap::mirror), expect(1.5), kEps);
    // u = 1: x = 3.5, texels 3, 4: clamp 8; repeat (8+1)/2; mirror 4 -> 3 -> 8.
    CHECK_NEAR(tf::reference_bilinear(row, 1.0, 0.5, Wrap::clamp), expect(8), kEps);
    CHECK_NEAR(tf::reference_bilinear(row, 1.0, 0.5, Wrap::repeat), expect(4.5), kEps);
    CHECK_NEAR(tf::reference_bilinear(row, 1.0, 0.5, Wrap::mirror), expect(8), kEps);
    // u = 1.25: x = 4.5, texels 4, 5: clamp 8; repeat (1+2)/2; mirror 3,2 -> (8+4)/2.
    CHECK_NEAR(tf::reference_bilinear(row, 1.25, 0.5, Wrap::clamp), expect(8), kEps);
    CHECK_NEAR(tf::reference_bilinear(row, 1.25, 0.5, Wrap::repeat), expect(1.5), kEps);
    CHECK_NEAR(tf::reference_bilinear(row, 1.25, 0.5, Wrap::mirror), expect(6), kEps);
    // 1/4 of the way from texel 0 to 1: x = 0.25 -> u = 0.75/4.
    CHECK_NEAR(tf::reference_bilinear(row, 0.1875, 0.5, Wrap::clamp), expect(1.25), kEps);
    // A one-row image: v is irrelevant for clamp (both rows are row 0).
    CHECK_NEAR(tf::reference_bilinear(row, 0.1875, 0.9, Wrap::clamp), expect(1.25), kEps);
}

TEST_CASE("huge-and-nonfinite-uv")
{
    const tf::Image row = image_from(4, 1, {1, 2, 4, 8});
    const tf::MipChain chain = single_level(row);
    // Clamped to the last / first texel; must not be UB for 1e30.
    CHECK_NEAR(tf::reference_nearest(row, 1e30, 0.5, Wrap::clamp), expect(8), 0.0);
    CHECK_NEAR(tf::reference_nearest(row, -1e30, 0.5, Wrap::clamp), expect(1), 0.0);
    CHECK_NEAR(tf::reference_bilinear(row, 1e30, 0.5, Wrap::clamp), expect(8), kEps);
    CHECK_NEAR(tf::reference_bilinear(row, -1e30, -1e30, Wrap::clamp), expect(1), kEps);
    const dvec4 rep = tf::reference_bilinear(row, 1e30, 1e30, Wrap::repeat);
    CHECK(std::isfinite(rep.x) && rep.x >= 1.0 && rep.x <= 8.0);
    const dvec4 mir = tf::reference_nearest(row, -1e30, 0.5, Wrap::mirror);
    CHECK(std::isfinite(mir.x) && mir.x >= 1.0 && mir.x <= 8.0);

    tf::SamplerOptions opt;
    const double inf = INFINITY, nan = NAN;
    for (Filter f : tf::all_filters()) {
        if (f == Filter::hw_aniso) continue;
        opt.filter = f;
        CHECK_NEAR(tf::reference_sample(chain, opt, {nan, 0.5, 0.01, 0, 0, 0.01}), dvec4(0.0), 0.0);
        CHECK_NEAR(tf::reference_sample(chain, opt, {0.5, inf, 0.01, 0, 0, 0.01}), dvec4(0.0), 0.0);
        CHECK_NEAR(tf::reference_sample(chain, opt, {-inf, 0.5, 0.01, 0, 0, 0.01}), dvec4(0.0), 0.0);
    }
}

// docs/API.md's degenerate-input table on the reference, every family, repeat and clamp,
// a 512² checker (u = 3e38 overflows u·512 in float; the reference reads values past float range as the
// ±Inf a float holds). tests/test_ewa.cpp runs the same table through `sample` on both backends.
// - gradients 1e-30 = zero gradients (the finest level);
// - gradients 1e30, 1e100, 1e154, 1e300, ±Inf, NaN: every mip family the 1x1 level's mean; sat the
//   mean too (a box of the whole texture; with clamp only where the footprint is non-finite, 1e100 up);
//   nearest, bilinear ignore gradients;
// - uv 1e37, 1e38, 3e38, -3e38: what uv reduced by the wrap gives (repeat 0, clamp 2 or -1);
// - uv or v 1e100, ±Inf, NaN: (0, 0, 0, 0).
TEST_CASE("degenerate-table")
{
    const tf::MipChain chain = tf::make_procedural("checker", 512);
    const dvec4 mean(chain.levels.back().at(0, 0));
    const double nan = NAN, inf = INFINITY, t = 1.0 / 512;
    struct Family {
        Filter filter;
        tf::AnisoShape shape;
        tf::Taps taps;
        bool mip, sat;
    };
    using tf::AnisoShape;
    using tf::Taps;
    const std::vector<Family> families = {
        {Filter::nearest, AnisoShape::gpu, Taps::manual, false, false},
        {Filter::bilinear, AnisoShape::gpu, Taps::manual, false, false},
        {Filter::nearest_mip, AnisoShape::gpu, Taps::manual, true, false},
        {Filter::bilinear_mip, AnisoShape::gpu, Taps::manual, true, false},
        {Filter::trilinear, AnisoShape::gpu, Taps::manual, true, false},
        {Filter::brilinear, AnisoShape::gpu, Taps::manual, true, false},
        {Filter::aniso, AnisoShape::gpu, Taps::manual, true, false},
        {Filter::aniso, AnisoShape::gpu, Taps::hardware, true, false},
        {Filter::aniso, AnisoShape::feline, Taps::manual, true, false},
        {Filter::aniso, AnisoShape::feline, Taps::hardware, true, false},
        {Filter::ewa, AnisoShape::gpu, Taps::manual, true, false},
        {Filter::ewa, AnisoShape::gpu, Taps::hardware, true, false},
        {Filter::sat, AnisoShape::gpu, Taps::manual, false, true},
        {Filter::sat_assembly, AnisoShape::gpu, Taps::manual, false, true},
    };
    for (Wrap wrap : {Wrap::repeat, Wrap::clamp})
        for (const Family& f : families) {
            tf::SamplerOptions o;
            o.filter = f.filter, o.aniso_shape = f.shape, o.taps = f.taps, o.wrap = wrap;
            const std::string name = tf::to_string(f.filter) + " " + tf::to_string(f.shape) + " " +
                                     tf::to_string(f.taps) + " " + tf::to_string(wrap);
            auto at = [&](tf::Lookup l) {
                try {
                    return tf::reference_sample(chain, o, l);
                } catch (const std::exception& e) {
                    CHECK(!"degenerate input threw");
                    std::fprintf(stderr, "  %s: %s\n", name.c_str(), e.what());
                    return dvec4(NAN);
                }
            };
            // eps: double rounding; sat's mean is of its 16-bit quantised texels (0.5/65535 from the float mean).
            auto same = [&](const dvec4& got, const dvec4& want, const char* what, double eps = 1e-9) {
                const bool ok = std::isfinite(got.x + got.y + got.z + got.w) && near(got, want, eps);
                if (!ok)
                    std::fprintf(stderr, "  degenerate table, %s, %s: got %s want %s\n", name.c_str(), what,
                                 tf::test::show(got).c_str(), tf::test::show(want).c_str());
                CHECK(ok);
            };
            const dvec4 zero = at({0.3, 0.6, 0, 0, 0, 0});
            // The comparisons are within the family (the reference against itself at simpler input), so
            // sat's quantisation cancels in all but the mean rows.
            same(at({0.3, 0.6, 1e-30, 0, 0, 1e-30}), zero, "gradients 1e-30");
            for (double g : {1e30, 1e100, 1e154, 1e300, inf, -inf, nan}) {
                const dvec4 got = at({0.3, 0.6, g, 0, 0, g});
                const std::string what = "gradients " + tf::test::show(g);
                if (f.mip) same(got, mean, what.c_str());
                else if (f.sat && !(g == 1e30 && wrap == Wrap::clamp)) same(got, mean, what.c_str(), 0.5 / 65535);
                else if (!f.sat) same(got, zero, "gradients ignored");
            }
            for (double u : {1e37, 1e38, 3e38, -3e38}) {
                const double uf = double(float(u)); // what the GPU reads
                const double r = wrap == Wrap::repeat ? 0.0 : uf > 0 ? 2.0 : -1.0;
                same(at({uf, 0.6, t, 0, 0, t}), at({r, 0.6, t, 0, 0, t}), "huge uv = reduced uv");
            }
            for (double u : {1e100, inf, -inf, nan}) {
                same(at({u, 0.6, t, 0, 0, t}), dvec4(0.0), "non-finite u");
                same(at({0.3, u, t, 0, 0, t}), dvec4(0.0), "non-finite v");
            }
        }
}

tf::MipChain square_chain(int size) { return single_level(tf::make_image(size, size)); }

TEST_CASE("lod")
{
    const tf::MipChain c256 = square_chain(256);
    tf::SamplerOptions opt;
    auto lod = [&](const tf::MipChain& c, double dudx, double dvdx, double dudy, double dvdy) {
        tf::Lookup l;
        l.u = l.v = 0.5;
        l.dudx = dudx;
        l.dvdx = dvdx;
        l.dudy = dudy;
        l.dvdy = dvdy;
        return tf::reference_lod(c, l, opt);
    };
    CHECK_NEAR(lod(c256, 4.0 / 256, 0, 0, 4.0 / 256), 2.0, kEps);   // 4 texels per pixel
    CHECK_NEAR(lod(c256, 4.0 / 256, 0, 0, 0), 2.0, kEps);           // one column only
    CHECK_NEAR(lod(c256, 1.0 / 256, 0, 0, 1.0 / 256), 0.0, kEps);   // 1:1
    CHECK_NEAR(lod(c256, 0.5 / 256, 0, 0, 0.5 / 256), -1.0, kEps);  // magnification
    CHECK_NEAR(lod(c256, 4.0 / 256, 0, 0, 16.0 / 256), 4.0, kEps);  // anisotropic: max of the two
    CHECK_NEAR(lod(c256, 0, 16.0 / 256, 2.0 / 256, 0), 4.0, kEps);  // column x is the long one
    CHECK_NEAR(lod(c256, 3.0 / 256, 4.0 / 256, 0, 0), 2.321928094887362, kEps); // log2(|(3,4)|) = log2 5
    CHECK_NEAR(lod(c256, -4.0 / 256, 0, 0, -4.0 / 256), 2.0, kEps); // sign does not matter
    // Non-square: 512x128, dv/dx = 2/128 -> 2 texels -> 1.
    CHECK_NEAR(lod(single_level(tf::make_image(512, 128)), 0, 2.0 / 128, 0, 0), 1.0, kEps);
    CHECK_NEAR(lod(single_level(tf::make_image(512, 128)), 2.0 / 512, 2.0 / 128, 0, 0), 1.5, kEps); // log2(2*sqrt2)
    opt.lod_bias = 0.5f;
    CHECK_NEAR(lod(c256, 4.0 / 256, 0, 0, 4.0 / 256), 2.5, kEps);
    opt.lod_bias = -1.0f;
    CHECK_NEAR(lod(c256, 4.0 / 256, 0, 0, 4.0 / 256), 1.0, kEps);
    opt.lod_bias = 0.0f;
    CHECK(lod(c256, 0, 0, 0, 0) == -INFINITY);
    CHECK(lod(c256, NAN, 0, 0, 0.01) == INFINITY);
    CHECK(lod(c256, 0.01, 0, 0, INFINITY) == INFINITY);
    CHECK(lod(c256, 0.01, -INFINITY, 0, 0) == INFINITY);
}

tf::Lookup lookup_at(double u, double v, double grad) { return {u, v, grad, 0, 0, grad}; }

TEST_CASE("level-selection")
{
    // mipcolors 16: 5 levels, each flat. rho = 1 texel (grad 1/16) -> lambda 0; the bias picks d.
    const tf::MipChain chain = tf::make_procedural("mipcolors", 16);
    CHECK_EQ(int(chain.levels.size()), 5);
    auto colour = [&](int l) { return dvec4(chain.levels[size_t(l)].at(0, 0)); };
    tf::SamplerOptions opt;
    const tf::Lookup one = lookup_at(0.3, 0.6, 1.0 / 16);
    auto sample = [&](Filter f, float bias) {
        opt.filter = f;
        opt.lod_bias = bias;
        return tf::reference_sample(chain, opt, one);
    };
    for (Filter f : {Filter::nearest_mip, Filter::bilinear_mip}) {
        CHECK_NEAR(sample(f, 0.0f), colour(0), 0.0);
        CHECK_NEAR(sample(f, 0.5f), colour(0), 0.0);  // ceil(0.5 + 0.5) - 1 = 0
        CHECK_NEAR(sample(f, 0.51f), colour(1), 0.0); // ceil(1.01) - 1 = 1
        CHECK_NEAR(sample(f, 1.49f), colour(1), 0.0);
        CHECK_NEAR(sample(f, 1.5f), colour(1), 0.0);
        CHECK_NEAR(sample(f, 1.6f), colour(2), 0.0);
        CHECK_NEAR(sample(f, 50.0f), colour(4), 0.0); // clamped to the top level
        CHECK_NEAR(sample(f, -3.0f), colour(0), 0.0);
    }
    // Level colours from the palette: red, orange, yellow.
    CHECK_NEAR(colour(0), dvec4(1, 0, 0, 1), 0.0);
    CHECK_NEAR(colour(1), dvec4(1, 0.5, 0, 1), 0.0);
    CHECK_NEAR(colour(2), dvec4(1, 1, 0, 1), 0.0);
    for (Filter f : {Filter::trilinear, Filter::hw_trilinear}) {
        CHECK_NEAR(sample(f, 1.5f), dvec4(1, 0.75, 0, 1), kEps);        // halfway between levels 1 and 2
        CHECK_NEAR(sample(f, 0.25f), dvec4(1, 0.125, 0, 1), kEps);      // 3/4 red + 1/4 orange
        CHECK_NEAR(sample(f, 1.0f), colour(1), kEps);
        CHECK_NEAR(sample(f, 4.0f), colour(4), kEps);                   // d == levels-1
        CHECK_NEAR(sample(f, 9.0f), colour(4), kEps);
        CHECK_NEAR(sample(f, -2.0f), colour(0), kEps);
    }
    // Level 0 filters ignore the LOD.
    for (Filter f : {Filter::nearest, Filter::bilinear, Filter::hw_nearest, Filter::hw_bilinear})
        CHECK_NEAR(sample(f, 3.0f), colour(0), 0.0);

    // lod_min / lod_max clamp the biased LOD before the level clamp.
    opt.filter = Filter::trilinear;
    opt.lod_bias = 10.0f;
    opt.lod_max = 2.0f;
    CHECK_NEAR(tf::reference_sample(chain, opt, one), colour(2), kEps);
    opt.lod_bias = 0.0f;
    opt.lod_max = 1000.0f;
    opt.lod_min = 3.0f;
    CHECK_NEAR(tf::reference_sample(chain, opt, lookup_at(0.3, 0.6, 0.0)), colour(3), kEps);
    opt.lod_min = 0.0f;
    // Zero gradients -> -inf -> level 0; non-finite gradients -> +inf -> top level.
    CHECK_NEAR(tf::reference_sample(chain, opt, lookup_at(0.3, 0.6, 0.0)), colour(0), kEps);
    CHECK_NEAR(tf::reference_sample(chain, opt, lookup_at(0.3, 0.6, NAN)), colour(4), kEps);
    opt.filter = Filter::nearest_mip;
    CHECK_NEAR(tf::reference_sample(chain, opt, lookup_at(0.3, 0.6, INFINITY)), colour(4), kEps);

    // NaN in the LOD clamps, one rule for every family that picks levels (docs/API.md, "Degenerate input"):
    // a NaN lambda counts as +inf (the coarsest level lod_max allows), a NaN lod_min or lod_max as no bound.
    for (Filter f : {Filter::nearest_mip, Filter::trilinear, Filter::brilinear, Filter::aniso, Filter::ewa}) {
        opt.filter = f;
        opt.lod_bias = NAN;
        opt.lod_max = 2.0f;
        CHECK_NEAR(tf::reference_sample(chain, opt, one), colour(2), kEps);
        opt.lod_bias = 10.0f;
        opt.lod_max = NAN;
        CHECK_NEAR(tf::reference_sample(chain, opt, one), colour(4), kEps);
        opt.lod_bias = -10.0f;
        opt.lod_min = NAN;
        CHECK_NEAR(tf::reference_sample(chain, opt, one), colour(0), kEps);
        opt.lod_bias = 0.0f, opt.lod_min = 0.0f, opt.lod_max = 1000.0f;
    }

    opt.filter = Filter::hw_aniso;
    CHECK_THROWS(tf::reference_sample(chain, opt, one));
}

TEST_CASE("mip-level-count")
{
    CHECK_EQ(tf::mip_level_count(1, 1), 1);
    CHECK_EQ(tf::mip_level_count(2, 1), 2);
    CHECK_EQ(tf::mip_level_count(3, 3), 2);
    CHECK_EQ(tf::mip_level_count(7, 5), 3);
    CHECK_EQ(tf::mip_level_count(255, 1), 8);
    CHECK_EQ(tf::mip_level_count(256, 256), 9);
    CHECK_EQ(tf::mip_level_count(256, 3), 9);
    CHECK_EQ(tf::mip_level_count(1, 1024), 11);
    CHECK_EQ(tf::mip_level_count(16384, 16384), 15);
}

TEST_CASE("downsample")
{
    // 3x1 [a,b,c] -> 1x1 = (a+b+c)/3, per channel including alpha.
    tf::Image three = tf::make_image(3, 1);
    three.texels = {{0.3f, 0.0f, 1.0f, 1.0f}, {0.6f, 0.5f, 0.0f, 1.0f}, {0.9f, 1.0f, 0.5f, 0.0f}};
    const tf::Image one = tf::downsample(three);
    CHECK_EQ(one.width, 1);
    CHECK_EQ(one.height, 1);
    CHECK_NEAR(dvec4(one.at(0, 0)), dvec4(0.6, 0.5, 0.5, 2.0 / 3.0), 1e-6);

    // 5 -> 2: (1*1 + 1*2 + 0.5*3)/2.5 = 1.8 and (0.5*3 + 1*4 + 1*5)/2.5 = 4.2.
    const tf::Image five = tf::downsample(image_from(5, 1, {1, 2, 3, 4, 5}));
    CHECK_EQ(five.width, 2);
    CHECK_EQ(five.height, 1);
    CHECK_NEAR(dvec4(five.at(0, 0)), expect(1.8), 1e-6);
    CHECK_NEAR(dvec4(five.at(1, 0)), expect(4.2), 1e-6);

    // 3x3 of 1..9 -> 1x1 mean 5.
    const tf::Image nine = tf::downsample(image_from(3, 3, {1, 2, 3, 4, 5, 6, 7, 8, 9}));
    CHECK_EQ(nine.width, 1);
    CHECK_NEAR(dvec4(nine.at(0, 0)), expect(5), 1e-6);

    // Even: 4x2 -> 2x1, plain 2x2 box.
    const tf::Image even = tf::downsample(image_from(4, 2, {0, 1, 2, 3, 4, 5, 6, 7}));
    CHECK_EQ(even.width, 2);
    CHECK_EQ(even.height, 1);
    CHECK_NEAR(dvec4(even.at(0, 0)), expect(2.5), 1e-6); // (0+1+4+5)/4
    CHECK_NEAR(dvec4(even.at(1, 0)), expect(4.5), 1e-6); // (2+3+6+7)/4

    // 7 -> 3 horizontally on a ramp 0..6: scale 7/3.
    //   [0, 7/3): 0*1 + 1*1 + 2*(1/3), over 7/3 = 5/7
    //   [7/3, 14/3): 2*(2/3) + 3 + 4*(2/3) = 7, over 7/3 = 3
    //   [14/3, 7): 4*(1/3) + 5 + 6 = 37/3, over 7/3 = 37/7
    std::vector<double> ramp7x5, ramp5;
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) ramp7x5.push_back(x);
    const tf::Image h7 = tf::downsample(image_from(7, 5, ramp7x5));
    CHECK_EQ(h7.width, 3);
    CHECK_EQ(h7.height, 2);
    for (int y = 0; y < 2; ++y) {
        CHECK_NEAR(dvec4(h7.at(0, y)), expect(5.0 / 7.0), 1e-6);
        CHECK_NEAR(dvec4(h7.at(1, y)), expect(3.0), 1e-6);
        CHECK_NEAR(dvec4(h7.at(2, y)), expect(37.0 / 7.0), 1e-6);
    }
    // 5 -> 2 vertically on rows 0..4: 0.8 and 3.2.
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) ramp5.push_back(y);
    const tf::Image v5 = tf::downsample(image_from(7, 5, ramp5));
    for (int x = 0; x < 3; ++x) {
        CHECK_NEAR(dvec4(v5.at(x, 0)), expect(0.8), 1e-6);
        CHECK_NEAR(dvec4(v5.at(x, 1)), expect(3.2), 1e-6);
    }
    // 1-wide axis stays 1 and is copied.
    const tf::Image tall = tf::downsample(image_from(1, 4, {1, 3, 5, 9}));
    CHECK_EQ(tall.width, 1);
    CHECK_EQ(tall.height, 2);
    CHECK_NEAR(dvec4(tall.at(0, 0)), expect(2), 1e-6);
    CHECK_NEAR(dvec4(tall.at(0, 1)), expect(7), 1e-6);
}

TEST_CASE("mip-chain")
{
    const tf::MipChain c = tf::build_mip_chain(tf::make_image(7, 5, glm::vec4(0.25f, 0.5f, 0.75f, 1.0f)));
    CHECK_EQ(int(c.levels.size()), 3);
    CHECK_EQ(c.levels[0].width, 7);
    CHECK_EQ(c.levels[0].height, 5);
    CHECK_EQ(c.levels[1].width, 3);
    CHECK_EQ(c.levels[1].height, 2);
    CHECK_EQ(c.levels[2].width, 1);
    CHECK_EQ(c.levels[2].height, 1);
    // Weights sum to one: a constant stays constant on every level.
    for (const tf::Image& level : c.levels)
        for (const glm::vec4& t : level.texels) CHECK_NEAR(dvec4(t), dvec4(0.25, 0.5, 0.75, 1.0), 1e-6);

    const tf::MipChain wide = tf::build_mip_chain(tf::make_image(256, 3));
    CHECK_EQ(int(wide.levels.size()), 9);
    CHECK_EQ(wide.levels[1].width, 128);
    CHECK_EQ(wide.levels[1].height, 1);
    CHECK_EQ(wide.levels[8].width, 1);
    CHECK_EQ(wide.levels[8].height, 1);

    // Texels that do not match the size are refused up front, a 1x1 level 0 (never downsampled) included.
    tf::Image one_holding_five = tf::make_image(1, 1);
    one_holding_five.texels.resize(5);
    CHECK_THROWS_WITH(tf::build_mip_chain(one_holding_five), "1x1 image holding 5 texels");
    tf::Image short_of_one = tf::make_image(4, 4);
    short_of_one.texels.pop_back();
    CHECK_THROWS_WITH(tf::build_mip_chain(short_of_one), "4x4 image holding 15 texels");
    CHECK_THROWS_WITH(tf::build_mip_chain(tf::Image{}), "empty image");
}

TEST_CASE("srgb")
{
    CHECK_EQ(tf::srgb_to_linear(0.0), 0.0);
    CHECK_NEAR(tf::srgb_to_linear(1.0), 1.0, 1e-15);
    CHECK_NEAR(tf::srgb_to_linear(0.04045), 0.04045 / 12.92, 1e-15); // 0.0031308049...
    CHECK_NEAR(tf::srgb_to_linear(0.5), 0.214041140482232, 1e-12);
    CHECK_NEAR(tf::linear_to_srgb(1.0), 1.0, 1e-15);
    CHECK_EQ(tf::linear_to_srgb(0.0), 0.0);
    CHECK_NEAR(tf::linear_to_srgb(0.214041140482232), 0.5, 1e-12);
    double worst = 0.0; // round trip over [0,1], both sides of the 0.04045 breakpoint
    for (int k = 0; k <= 1000; ++k) {
        const double x = k / 1000.0;
        worst = std::max(worst, std::fabs(tf::linear_to_srgb(tf::srgb_to_linear(x)) - x));
    }
    CHECK_NEAR(worst, 0.0, 1e-12);
}

// Small deterministic generator for "random" lookups (splitmix-style).
struct Rng {
    uint64_t state;
    double next() {
        uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        z ^= z >> 31;
        return double(z >> 11) * (1.0 / 9007199254740992.0);
    }
    double range(double lo, double hi) { return lo + (hi - lo) * next(); }
};

TEST_CASE("constant-texture")
{
    const glm::vec4 c(0.25f, 0.5f, 0.75f, 1.0f);
    const dvec4 expected(0.25, 0.5, 0.75, 1.0);
    const tf::MipChain chain = tf::build_mip_chain(tf::make_image(13, 6, c));
    Rng rng{42};
    int bad = 0;
    for (Filter f : tf::all_filters()) {
        if (f == Filter::hw_aniso) continue;
        for (Wrap w : {Wrap::repeat, Wrap::clamp, Wrap::mirror}) {
            tf::SamplerOptions opt;
            opt.filter = f;
            opt.wrap = w;
            for (int k = 0; k < 200; ++k) {
                opt.lod_bias = float(rng.range(-2, 2));
                const double g = std::exp2(rng.range(-8, 6));
                const tf::Lookup l{rng.range(-3, 4), rng.range(-3, 4), g * rng.range(-1, 1),
                                   g * rng.range(-1, 1), g * rng.range(-1, 1), g * rng.range(-1, 1)};
                const dvec4 got = tf::reference_sample(chain, opt, l);
                if (!near(got, expected, 1e-12) && bad++ < 5) CHECK_NEAR(got, expected, 1e-12);
            }
            // Huge uv still lands on a texel.
            const dvec4 huge = tf::reference_sample(chain, opt, {1e30, -1e30, 0.01, 0, 0, 0.01});
            CHECK_NEAR(huge, expected, 1e-12);
        }
    }
    CHECK_EQ(bad, 0);
}

TEST_CASE("procedural")
{
    // mipcolors: first 12 levels pairwise distinct, flat, floor-rule sizes.
    const tf::MipChain mc = tf::make_procedural("mipcolors", 4096);
    CHECK_EQ(int(mc.levels.size()), 13);
    for (size_t a = 0; a < 12; ++a)
        for (size_t b = a + 1; b < 12; ++b) CHECK(mc.levels[a].at(0, 0) != mc.levels[b].at(0, 0));
    CHECK(mc.levels[12].at(0, 0) == mc.levels[0].at(0, 0)); // palette wraps after 12
    CHECK_EQ(mc.levels[3].width, 512);
    CHECK(mc.levels[3].at(100, 200) == mc.levels[3].at(0, 0));
    const tf::MipChain mc_npot = tf::make_procedural("mipcolors", 100);
    CHECK_EQ(int(mc_npot.levels.size()), 7);
    CHECK_EQ(mc_npot.levels[1].width, 50);
    CHECK_EQ(mc_npot.levels[2].width, 25);
    CHECK_EQ(mc_npot.levels[3].width, 12);
    CHECK_EQ(mc_npot.levels[6].width, 1);

    // checker 16: 2-texel cells.
    const tf::MipChain ck = tf::make_procedural("checker", 16);
    CHECK_NEAR(dvec4(ck.levels[0].at(0, 0)), dvec4(0.9f, 0.9f, 0.9f, 1.0), 0.0);
    CHECK_NEAR(dvec4(ck.levels[0].at(1, 1)), dvec4(0.9f, 0.9f, 0.9f, 1.0), 0.0);
    CHECK_NEAR(dvec4(ck.levels[0].at(2, 0)), dvec4(0.05f, 0.05f, 0.05f, 1.0), 0.0);
    CHECK_NEAR(dvec4(ck.levels[0].at(2, 2)), dvec4(0.9f, 0.9f, 0.9f, 1.0), 0.0);
    CHECK_NEAR(dvec4(ck.levels[0].at(15, 0)), dvec4(0.05f, 0.05f, 0.05f, 1.0), 0.0);
    CHECK_EQ(int(ck.levels.size()), 5);
    // Level 1 of a 2-texel checker: each texel is one cell. Level 3 (2x2): each covers 4x4 cells -> mean.
    CHECK_NEAR(double(ck.levels[1].at(1, 0).x), 0.05, 1e-6);
    CHECK_NEAR(double(ck.levels[3].at(0, 0).x), 0.475, 1e-6);
    // checker 12: cell index floor(x*8/12): x=1 -> 0, x=2 -> 1.
    const tf::MipChain ck12 = tf::make_procedural("checker", 12);
    CHECK_NEAR(double(ck12.levels[0].at(1, 0).x), double(0.9f), 0.0);
    CHECK_NEAR(double(ck12.levels[0].at(2, 0).x), double(0.05f), 0.0);

    // zoneplate 5: centre (2.5, 2.5) is texel (2,2)'s centre -> 1. Texel (4,2): r^2 = 4,
    // 0.5 + 0.5*cos(4*pi/5) = 0.5 - 0.5*0.80901699437 = 0.095491502812.
    const tf::MipChain zp = tf::make_procedural("zoneplate", 5);
    CHECK_NEAR(dvec4(zp.levels[0].at(2, 2)), dvec4(1.0, 1.0, 1.0, 1.0), 1e-7);
    CHECK_NEAR(double(zp.levels[0].at(4, 2).x), 0.095491502812, 1e-7);
    CHECK_NEAR(double(zp.levels[0].at(2, 4).y), 0.095491502812, 1e-7);

    // grid 64: lines at multiples of 4, 1 texel wide. grid 512: lines 2 texels wide every 32.
    const glm::vec4 line(0.9f, 0.85f, 0.6f, 1.0f), bg(0.02f, 0.03f, 0.08f, 1.0f);
    const tf::MipChain g64 = tf::make_procedural("grid", 64);
    CHECK(g64.levels[0].at(0, 5) == line);
    CHECK(g64.levels[0].at(4, 1) == line);
    CHECK(g64.levels[0].at(6, 8) == line);
    CHECK(g64.levels[0].at(1, 1) == bg);
    CHECK(g64.levels[0].at(5, 5) == bg);
    CHECK(g64.levels[0].at(63, 63) == bg);
    const tf::MipChain g512 = tf::make_procedural("grid", 512);
    CHECK(g512.levels[0].at(1, 5) == line);
    CHECK(g512.levels[0].at(2, 5) == bg);
    CHECK(g512.levels[0].at(33, 3) == line);
    CHECK(g512.levels[0].at(34, 3) == bg);

    // noise: deterministic, in [0,1), alpha 1, mean near 1/2.
    const tf::MipChain n1 = tf::make_procedural("noise", 64), n2 = tf::make_procedural("noise", 64);
    CHECK(n1.levels[0].texels == n2.levels[0].texels);
    double sum = 0;
    bool in_range = true;
    for (const glm::vec4& t : n1.levels[0].texels) {
        for (int c = 0; c < 3; ++c) in_range = in_range && t[c] >= 0.0f && t[c] < 1.0f;
        in_range = in_range && t.a == 1.0f;
        sum += t.r + t.g + t.b;
    }
    CHECK(in_range);
    CHECK_NEAR(sum / (64 * 64 * 3), 0.5, 0.02);
    CHECK(n1.levels[0].at(0, 0) != n1.levels[0].at(1, 0));
    CHECK(n1.levels[0].at(3, 7).r != n1.levels[0].at(3, 7).g);

    // Every texture: full chain, alpha 1 at level 0.
    for (const std::string& name : tf::procedural_names()) {
        CHECK(tf::is_procedural(name));
        const tf::MipChain c = tf::make_procedural(name, 37);
        CHECK_EQ(int(c.levels.size()), 6);
        CHECK_EQ(c.levels[1].width, 18);
        CHECK_EQ(c.levels[5].width, 1);
        CHECK_EQ(double(c.levels[0].at(36, 36).a), 1.0);
        const tf::MipChain tiny = tf::make_procedural(name, 1);
        CHECK_EQ(int(tiny.levels.size()), 1);
    }
    CHECK_EQ(int(tf::procedural_names().size()), 6); // checker, zoneplate, grid, noise, mipcolors, dynamic
    CHECK(!tf::is_procedural("Checker"));
    CHECK_THROWS(tf::make_procedural("bogus", 64));
    CHECK_THROWS(tf::make_procedural("checker", 0));
    CHECK_THROWS(tf::make_procedural("checker", 16385));
    CHECK_THROWS(tf::make_procedural("noise", -4));
    try {
        tf::make_procedural("bogus", 64);
    } catch (const tf::Error& e) {
        const std::string msg = e.what();
        CHECK_CONTAINS(msg, "bogus");
        CHECK_CONTAINS(msg, "zoneplate", "mipcolors");
    }
}

TEST_CASE("names")
{
    const char* names[] = {"nearest",    "bilinear",    "trilinear",    "nearest-mip", "bilinear-mip",
                           "hw-nearest", "hw-bilinear", "hw-trilinear", "hw-aniso",    "brilinear",
                           "aniso",      "ewa",         "sat",          "sat-assembly", "bspline",
                           "catmull-rom", "ewa-fast"};
    CHECK_EQ(int(tf::all_filters().size()), 17);
    for (const char* n : names) CHECK(tf::to_string(tf::parse_filter(n)) == n);
    for (Filter f : tf::all_filters()) CHECK(tf::parse_filter(tf::to_string(f)) == f);
    CHECK(tf::parse_filter("nearest-mip") == Filter::nearest_mip);
    CHECK(tf::parse_filter("hw-aniso") == Filter::hw_aniso);
    CHECK(tf::is_hardware(Filter::hw_aniso) && tf::is_hardware(Filter::hw_nearest));
    CHECK(!tf::is_hardware(Filter::trilinear) && !tf::is_hardware(Filter::bilinear_mip));
    CHECK_THROWS(tf::parse_filter("foo"));
    CHECK_THROWS(tf::parse_filter(""));
    CHECK_THROWS(tf::parse_filter("Bilinear"));
    CHECK_THROWS(tf::parse_filter("nearest_mip"));
    try {
        tf::parse_filter("foo");
    } catch (const tf::Error& e) {
        const std::string msg = e.what();
        CHECK_CONTAINS(msg, "'foo'");
        CHECK_CONTAINS(msg, "nearest, bilinear", "hw-aniso");
    }
    for (const char* n : {"repeat", "clamp", "mirror"}) CHECK(tf::to_string(tf::parse_wrap(n)) == n);
    CHECK(tf::parse_wrap("mirror") == Wrap::mirror);
    CHECK_THROWS(tf::parse_wrap("Repeat"));
    CHECK_THROWS(tf::parse_wrap("clamp-to-edge"));
}

} // namespace

