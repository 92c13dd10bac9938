// brilinear and aniso (shaders/texfilter/brilinear.glsl, aniso.glsl; host/reference/aniso.cpp).
//
// Part 1, the CPU reference against facts worked out by hand: brilinear blend weights on mipcolors,
// band 1 == trilinear and band 0 == bilinear-mip exactly, the probe count, LOD and probe places of both
// aniso shapes for known footprints, probes 1 == trilinear, constant in => constant out, degenerate input.
// Part 2, the GPU (lavapipe) through `texfilter sample --validate --stats` on random lookups: manual taps
// vs the reference within float rounding, the special cases vs their GPU twins, hardware taps vs manual
// taps within the sampler's precision, and texel-fetch / hardware-lookup counts.
//
// usage: test_brilinear_aniso PATH/TO/texfilter
#include "texture/image.h"
#include "texture/mip.h"
#include "core/procedural.h"
#include "reference/reference.h"
#include "support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>
#include <vector>
#include <glm/glm.hpp>

using namespace tf;
using tf::test::max_channel_diff;
using tf::test::texel_contrast;
using tf::test::SampleResult;

namespace {

// ---------------------------------------------------------------------------------------------------
// Named checks (test::named_check, tests/support.h): each runs CHECKs and prints one result line.

// The detail lines' numbers: 9 digits.
std::string str(double x)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.9g", x);
    return buf;
}

// ---------------------------------------------------------------------------------------------------
// Textures and lookups.

SamplerOptions options_for(Filter filter, Wrap wrap = Wrap::repeat)
{
    SamplerOptions o;
    o.filter = filter;
    o.wrap = wrap;
    return o;
}

SamplerOptions brilinear(double band, Wrap wrap = Wrap::repeat)
{
    SamplerOptions o = options_for(Filter::brilinear, wrap);
    o.band = float(band);
    return o;
}

SamplerOptions aniso(int probes, AnisoShape shape, Wrap wrap = Wrap::repeat)
{
    SamplerOptions o = options_for(Filter::aniso, wrap);
    o.probes = probes;
    o.aniso_shape = shape;
    return o;
}

// A lookup from J's columns in level-0 texels of a size x size texture.
Lookup lookup_texels(double u, double v, double size, double jxu, double jxv, double jyu, double jyv)
{
    return {u, v, jxu / size, jxv / size, jyu / size, jyv / size};
}

// An n x n texture of hashed values in [0, 1) with its MIP chain (channels differ, alpha 1).
MipChain noise_chain(int n, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> value(0.0f, 1.0f);
    Image image = make_image(n, n);
    for (glm::vec4& t : image.texels)
        t = glm::vec4(value(rng), value(rng), value(rng), 1.0f);
    return build_mip_chain(image);
}

// Random footprints: size from 1/16 to 512 texels, any direction, stretch up to 8:1 and a shear (the
// columns of J are not orthogonal, so the feline axis differs from the gpu one), uv beyond [0, 1] for wraps.
std::vector<Lookup> random_lookups(int count, unsigned seed)
{
    return test::random_footprint_lookups(count, seed, {.max_stretch = 3.0, .max_shear = 1.0});
}

// Degenerate footprints the filters must survive: zero, NaN, ±Inf, one column zero, parallel columns.
std::vector<Lookup> degenerate_lookups()
{
    const double nan = std::nan(""), inf = INFINITY;
    return {{0.3, 0.7, 0, 0, 0, 0},           {0.3, 0.7, nan, 0, 0, 0.01},   {0.3, 0.7, inf, 0, 0, 0.01},
            {0.3, 0.7, 0.01, -inf, 0, 0},     {0.3, 0.7, 0.03, 0, 0, 0},     {0.3, 0.7, 0, 0, 0.01, 0.02},
            {0.3, 0.7, 0.02, 0.01, 0.04, 0.02}, {0.3, 0.7, 1e30, 0, 0, 1e30}, {0.3, 0.7, 1e-30, 0, 0, 3e-31}};
}

// ---------------------------------------------------------------------------------------------------
// The aniso probe layout, re-derived here (double) only to bound GPU errors: N, lambda, probe places
// and weights, the ratio that picks N (for knife-edge lookups) and the conditioning of the feline axis.

struct Layout {
    int count = 1;
    double lod = 0, ratio = 1;
    double axis_u = 0, axis_v = 0;
    std::vector<double> t, weight; // normalised weights
    double sigma1 = 0, sigma2 = 0;
};

double clamp_lod(const MipChain& chain, double d)
{
    if (std::isnan(d))
        d = INFINITY;
    return std::clamp(d, 0.0, double(chain.levels.size() - 1));
}

Layout layout_of(const MipChain& chain, const SamplerOptions& o, const Lookup& l)
{
    Layout p;
    const double w = chain.levels[0].width, h = chain.levels[0].height;
    const double a = l.dudx * w, c = l.dvdx * h, b = l.dudy * w, d = l.dvdy * h;
    const bool finite = std::isfinite(a) && std::isfinite(b) && std::isfinite(c) && std::isfinite(d);
    if (!finite) {
        p.lod = clamp_lod(chain, INFINITY);
    } else if (o.aniso_shape == AnisoShape::gpu) {
        double px = std::hypot(a, c), py = std::hypot(b, d);
        p.ratio = std::max(px, py) / std::min(px, py);
        if (px == 0 && py == 0) {
            p.lod = 0;
        } else {
            p.count = p.ratio >= o.probes ? o.probes : std::max(1, int(std::ceil(p.ratio - 1.0 / 64.0)));
            p.lod = clamp_lod(chain, std::log2(std::max(px, py) / p.count) + o.lod_bias);
            p.axis_u = px >= py ? l.dudx : l.dudy;
            p.axis_v = px >= py ? l.dvdx : l.dvdy;
        }
    } else {
        // Singular values from the invariants: sigma1^2 + sigma2^2 = |J|_F^2, sigma1 sigma2 = |det J|.
        double frob = a * a + b * b + c * c + d * d, det = std::abs(a * d - b * c);
        double s1 = std::sqrt(0.5 * (frob + std::sqrt(std::max(0.0, frob * frob - 4 * det * det))));
        p.sigma1 = s1;
        p.sigma2 = s1 > 0 ? det / s1 : 0;
        p.ratio = p.sigma1 / p.sigma2;
        if (s1 == 0) {
            p.lod = 0;
        } else {
            p.count = p.ratio >= o.probes ? o.probes : std::max(1, int(std::ceil(p.ratio - 1.0 / 64.0)));
            p.lod = clamp_lod(chain, std::log2(std::max(p.sigma2, s1 / p.count)) + o.lod_bias);
            // Major axis: the unit vector x maximising |J^T x|, from the 2x2 symmetric J J^T.
            double theta = 0.5 * std::atan2(2 * (a * c + b * d), (a * a + b * b) - (c * c + d * d));
            p.axis_u = s1 * std::cos(theta) / w;
            p.axis_v = s1 * std::sin(theta) / h;
        }
    }
    double sum = 0;
    for (int k = 0; k < p.count; ++k) {
        double t = (k + 0.5) / p.count - 0.5;
        p.t.push_back(t);
        p.weight.push_back(o.aniso_shape == AnisoShape::feline ? std::exp(-8 * t * t) : 1.0);
        sum += p.weight.back();
    }
    for (double& x : p.weight)
        x /= sum;
    return p;
}

// N is ceil(ratio - 1/64): a ratio within float rounding of k + 1/64 may give N or N+1 on the GPU.
bool knife_edge_count(const Layout& p, int max_probes)
{
    if (!std::isfinite(p.ratio))
        return false;
    for (int k = 1; k < max_probes; ++k)
        if (std::abs(p.ratio - (k + 1.0 / 64.0)) <= 1e-5 * k)
            return true;
    return false;
}

// How far a bilinear lookup moves when its weights move by `step` (a fraction of a texel): a step in
// alpha moves both rows, a step in beta moves between rows (themselves moved by alpha).
double bilinear_bound(const Image& level, double u, double v, Wrap wrap, double step)
{
    double across, down;
    texel_contrast(level, u, v, wrap, across, down);
    return step * (across + down + across);
}

// Float rounding of the GPU's arithmetic on values <= 1, apart from positions and LOD (below): a bilinear
// lookup is 3 mixes, trilinear one more, each within ~2 ulps of 1 (2^-24 = 6e-8), and the probe sum (up to
// 16 adds) and its division add a relative ~(N + 2) 2^-24 <= 1e-6: 1e-6 covers it (worst measured: below).
const double kFloatArithmetic = 1e-6;

// Bound on |GPU manual - reference| for one lookup of brilinear (one probe at uv) or aniso (the layout),
// with every input the same float on both sides. Beyond kFloatArithmetic:
// - positions: the GPU rounds uv + t*axis (a product and a sum: 2^-24 (|t axis| + |uv_k|) of uv) and the
//   texel coordinate u*w_l - 1/2 (2^-24 (|u w_l| + 1/2) texels; u*w_l itself is exact for power-of-two
//   sizes, counted anyway). A shift of d texels moves a bilinear lookup by at most d times its contrast
//   along that axis (first order; alpha's row mix and beta's column mix).
//   On a 256 texture with uv up to 2 that is ~1.5e-5 texels: the largest term for contrasty textures.
// - feline's axis direction: a near-round ellipse's major axis is ill-conditioned; the float SVD's angle is
//   off by ~2^-23 sigma1/(sigma1 - sigma2), which moves probe k by that times its offset |t_k| sigma1.
// - the LOD: log2 of a float rho^2 (2^-24 relative -> 1e-7), float log2 and the bias sums (an ulp or two of
//   lambda); feline's sigma2 = |Q - R| loses log2(sigma1/sigma2) bits. Times |fine - coarse| and the blend's
//   slope (1 for trilinear probes, 1/band for brilinear).
double float_bound(const MipChain& chain, Wrap wrap, const Lookup& l, const Layout& p, bool feline, double lod_gain = 1)
{
    const int top = int(chain.levels.size()) - 1;
    const int lo = int(std::floor(p.lod)), hi = std::min(lo + 1, top);
    const double eps = std::exp2(-24.0);
    double lod_error = 2e-7 + 4 * eps * std::abs(p.lod);
    double angle_error = 0;
    if (feline && p.count > 1) {
        angle_error = 2 * eps * p.sigma1 / (p.sigma1 - p.sigma2);
        lod_error += 2 * eps * std::min(p.ratio, 16.0) / std::log(2.0);
    }
    const double w0 = chain.levels[0].width, h0 = chain.levels[0].height;
    double bound = kFloatArithmetic;
    for (int k = 0; k < p.count; ++k) {
        const double t = p.t[size_t(k)];
        const double u = l.u + t * p.axis_u, v = l.v + t * p.axis_v;
        const double off_u = std::abs(t * p.axis_u), off_v = std::abs(t * p.axis_v); // uv
        const double turn = angle_error * std::abs(t) * std::hypot(p.axis_u * w0, p.axis_v * h0); // level-0 texels
        double probe = 0;
        for (int level : {lo, hi}) {
            const Image& img = chain.levels[size_t(level)];
            const double w = img.width, h = img.height;
            const double du = eps * (2 * (off_u + std::abs(u)) * w + 0.5) + turn * w / w0;
            const double dv = eps * (2 * (off_v + std::abs(v)) * h + 0.5) + turn * h / h0;
            double across, down;
            texel_contrast(img, u, v, wrap, across, down);
            probe = std::max(probe, du * across + dv * down);
        }
        glm::dvec4 fine = reference_bilinear(chain.levels[size_t(lo)], u, v, wrap);
        glm::dvec4 coarse = reference_bilinear(chain.levels[size_t(hi)], u, v, wrap);
        bound += p.weight[size_t(k)] * (probe + lod_gain * lod_error * max_channel_diff(fine, coarse));
    }
    return bound;
}

// Bound on |hardware taps - manual taps| (as tests/test_hw_vs_manual.cpp derives it): each probe is one
// textureLod at an explicit LOD (no scale factor to approximate), whose level blend delta the sampler
// quantises to the device's mipmapPrecisionBits (Vulkan spec, "Image Level(s) Selection": "quantized to the
// number of mipmap precision bits"; 4 on lavapipe: within 1/16), and whose bilinear weights it rounds to
// subTexelPrecisionBits (8 on lavapipe: within 1/256 of a texel). Trilinear is piecewise linear in lambda,
// so its extremes over [lambda - e, lambda + e] are at the ends or at whole levels in between.
double hardware_bound(const MipChain& chain, Wrap wrap, const Lookup& l, const Layout& p)
{
    const DeviceInfo& device = test::test_device_info();
    const double kSubTexelStep = std::ldexp(1.0, -int(device.sub_texel_precision_bits));
    // textureLod's λ: "computed with mipmapPrecisionBits of accuracy" and its blend fraction "quantized" to as
    // many bits, two steps (as test_hw_vs_manual.cpp's lod_error; an NVIDIA H200 truncates the fraction to 8 bits).
    const double kLodError = 2.0 * std::ldexp(1.0, -int(device.mipmap_precision_bits));
    const int top = int(chain.levels.size()) - 1;
    double bound = kFloatArithmetic;
    for (int k = 0; k < p.count; ++k) {
        double u = l.u + p.t[size_t(k)] * p.axis_u, v = l.v + p.t[size_t(k)] * p.axis_v;
        glm::dvec4 centre = reference_trilinear_at(chain, p.lod, u, v, wrap);
        std::vector<double> lods = {p.lod - kLodError, p.lod + kLodError};
        for (int d = int(std::ceil(p.lod - kLodError)); d <= int(std::floor(p.lod + kLodError)); ++d)
            lods.push_back(d);
        double spread = 0, weights = 0;
        for (double d : lods)
            spread = std::max(spread, max_channel_diff(reference_trilinear_at(chain, d, u, v, wrap), centre));
        for (int level = std::max(0, int(p.lod - kLodError)); level <= std::min(top, int(p.lod + kLodError) + 1); ++level)
            weights = std::max(weights, bilinear_bound(chain.levels[size_t(level)], u, v, wrap, kSubTexelStep));
        bound += p.weight[size_t(k)] * (spread + weights);
    }
    return bound;
}

// ---------------------------------------------------------------------------------------------------
// Part 1: the CPU reference.

const glm::dvec4 kLevel[4] = {{1, 0, 0, 1}, {1, 0.5, 0, 1}, {1, 1, 0, 1}, {0.5, 1, 0, 1}}; // mipcolors 0..3

void reference_checks()
{
    const MipChain colors = make_procedural("mipcolors", 256);
    // rho = 2 texels (log2 = 1 exactly) and a bias of f: lambda = 1 + f, between level 1 (1, .5, 0) and
    // level 2 (1, 1, 0), so green = 0.5 + 0.5 w. f values are exact in float (SamplerOptions holds floats).
    const Lookup two = lookup_texels(0.3, 0.6, 256, 2, 0, 0, 2);
    auto green = [&](double band, double f) {
        SamplerOptions o = brilinear(band);
        o.lod_bias = float(f);
        return reference_sample(colors, o, two);
    };
    auto blend = [](double w) { return glm::dvec4(1, 0.5 + 0.5 * w, 0, 1); };

    test::named_check("ref brilinear band 0.25: weights at f = 5/16 .. 11/16", [&] {
        // (1 - B)/2 = 3/8; w = clamp((f - 3/8) / (1/4), 0, 1): 0, 1/4, 1/2, 3/4, 1.
        CHECK_NEAR(green(0.25, 0.3125), blend(0.0), 1e-15);
        CHECK_NEAR(green(0.25, 0.375), blend(0.0), 1e-15);
        CHECK_NEAR(green(0.25, 0.4375), blend(0.25), 1e-15);
        CHECK_NEAR(green(0.25, 0.5), blend(0.5), 1e-15);
        CHECK_NEAR(green(0.25, 0.5625), blend(0.75), 1e-15);
        CHECK_NEAR(green(0.25, 0.625), blend(1.0), 1e-15);
        CHECK_NEAR(green(0.25, 0.6875), blend(1.0), 1e-15);
        return std::string();
    });
    test::named_check("ref brilinear band 0.5 / 1 / 0: weights by hand", [&] {
        CHECK_NEAR(green(0.5, 0.3125), blend(0.125), 1e-15); // (5/16 - 1/4) / (1/2)
        CHECK_NEAR(green(0.5, 0.25), blend(0.0), 1e-15);
        CHECK_NEAR(green(1.0, 0.3125), blend(0.3125), 1e-15); // band 1: w = f
        CHECK_NEAR(green(0.0, 0.4375), blend(0.0), 1e-15);    // band 0: nearest level
        CHECK_NEAR(green(0.0, 0.5), blend(0.0), 1e-15);       // the tie stays on the finer level, as ceil(d + 1/2) - 1
        CHECK_NEAR(green(0.0, 0.5 + 1.0 / 1024), blend(1.0), 1e-15);
        return std::string();
    });
    test::named_check("ref brilinear: clamps (lod-max, last level, magnification)", [&] {
        SamplerOptions o = brilinear(0.25);
        o.lod_max = 1.5f; // lambda 9 clamps to 1.5: w = 1/2
        CHECK_NEAR(reference_sample(colors, o, lookup_texels(0.3, 0.6, 256, 512, 0, 0, 512)), blend(0.5), 1e-15);
        const MipChain& c = colors; // lambda 20 clamps to the last level (8): its colour, no level 9
        CHECK_NEAR(reference_sample(c, brilinear(0.25), lookup_texels(0.3, 0.6, 256, 1 << 20, 0, 0, 1)),
                   glm::dvec4(c.levels[8].at(0, 0)), 0.0);
        CHECK_NEAR(reference_sample(c, brilinear(0.25), lookup_texels(0.3, 0.6, 256, 0.25, 0, 0, 0.25)), kLevel[0], 0.0);
        return std::string();
    });

    const MipChain noise = make_procedural("noise", 256);
    const std::vector<Lookup> lookups = random_lookups(2000, 7);
    test::named_check("ref brilinear band 1 == trilinear (exact, 2000 x 3 wraps)", [&] {
        for (Wrap wrap : {Wrap::repeat, Wrap::clamp, Wrap::mirror})
            for (const Lookup& l : lookups)
                CHECK_NEAR(reference_sample(noise, brilinear(1.0, wrap), l),
                           reference_sample(noise, options_for(Filter::trilinear, wrap), l), 0.0);
        return std::string();
    });
    test::named_check("ref brilinear band 0 == bilinear-mip (exact, 2000 x 3 wraps)", [&] {
        for (Wrap wrap : {Wrap::repeat, Wrap::clamp, Wrap::mirror})
            for (const Lookup& l : lookups)
                CHECK_NEAR(reference_sample(noise, brilinear(0.0, wrap), l),
                           reference_sample(noise, options_for(Filter::bilinear_mip, wrap), l), 0.0);
        return std::string();
    });

    // aniso, gpu shape. J = diag(8, 2) texels: Pmax/Pmin = 4 -> N = 4, lambda = log2(8/4) = 1: on mipcolors
    // every probe reads level 1 alone.
    const Lookup j82 = lookup_texels(0.3, 0.6, 256, 8, 0, 0, 2);
    test::named_check("ref aniso gpu J=diag(8,2): N=4, lambda=1 (mipcolors)", [&] {
        CHECK_NEAR(reference_sample(colors, aniso(16, AnisoShape::gpu), j82), kLevel[1], 0.0);
        CHECK_NEAR(reference_sample(colors, aniso(4, AnisoShape::gpu), j82), kLevel[1], 0.0);
        // probes 2: N = 2, lambda = log2(8/2) = 2.
        CHECK_NEAR(reference_sample(colors, aniso(2, AnisoShape::gpu), j82), kLevel[2], 0.0);
        // J = diag(8, 3): N = ceil(8/3) = 3, lambda = log2(8/3) = 1.41503749927884381 -> green 0.5 + f/2.
        CHECK_NEAR(reference_sample(colors, aniso(16, AnisoShape::gpu), lookup_texels(0.3, 0.6, 256, 8, 0, 0, 3)),
                   glm::dvec4(1, 0.707518749639421907, 0, 1), 1e-15);
        // The y column major (J = [[1, 0], [0, 6]]... rotated): N = 6, lambda = 0.
        CHECK_NEAR(reference_sample(colors, aniso(16, AnisoShape::gpu), lookup_texels(0.3, 0.6, 256, 0, 1, 6, 0)),
                   kLevel[0], 0.0);
        return std::string();
    });

    // Probe places on a 16x16 noise texture: J = diag(8, 2) texels -> 4 probes at u +- 1, +- 3 texels
    // (1/16 uv each), v unchanged, on LOD 1, equal weights. J = [[0, 2], [8, 0]] (y major... x column
    // (0, 8)): probes along v.
    const MipChain small = noise_chain(16, 11);
    test::named_check("ref aniso gpu: probe places and weights by hand (16x16)", [&] {
        for (Wrap wrap : {Wrap::repeat, Wrap::mirror}) {
            auto tri = [&](double u, double v) { return reference_trilinear_at(small, 1.0, u, v, wrap); };
            double u = 0.41, v = 0.23, t = 1.0 / 16;
            glm::dvec4 along_u = (tri(u - 3 * t, v) + tri(u - t, v) + tri(u + t, v) + tri(u + 3 * t, v)) / 4.0;
            glm::dvec4 along_v = (tri(u, v - 3 * t) + tri(u, v - t) + tri(u, v + t) + tri(u, v + 3 * t)) / 4.0;
            CHECK_NEAR(reference_sample(small, aniso(16, AnisoShape::gpu, wrap), lookup_texels(u, v, 16, 8, 0, 0, 2)),
                       along_u, 1e-15);
            CHECK_NEAR(reference_sample(small, aniso(16, AnisoShape::gpu, wrap), lookup_texels(u, v, 16, 0, 8, 2, 0)),
                       along_v, 1e-15);
            // Sheared J: columns (8, 0) and (3, 2): Px = 8 > Py = sqrt(13), N = ceil(2.219) = 3,
            // lambda = log2(8/3); probes along the x column at -1/3, 0, +1/3 of it.
            glm::dvec4 sheared(0.0);
            double lambda = std::log2(8.0 / 3.0);
            for (double s : {-1.0 / 3, 0.0, 1.0 / 3})
                sheared += reference_trilinear_at(small, lambda, u + s * 8 / 16, v, wrap) / 3.0;
            CHECK_NEAR(reference_sample(small, aniso(16, AnisoShape::gpu, wrap), lookup_texels(u, v, 16, 8, 0, 3, 2)),
                       sheared, 1e-15);
            // Nearly isotropic (ratio 1 + 1/100, below the 1/64 slack): one probe, i.e. trilinear at log2(4.04).
            CHECK_NEAR(reference_sample(small, aniso(16, AnisoShape::gpu, wrap), lookup_texels(u, v, 16, 4.04, 0, 0, 4)),
                       reference_trilinear_at(small, std::log2(4.04), u, v, wrap), 1e-15);
            // Ratio 1 + 1/32, above it: two probes at +-1/4 of the x column.
            glm::dvec4 two(0.0);
            for (double s : {-0.25, 0.25})
                two += reference_trilinear_at(small, std::log2(4.125 / 2), u + s * 4.125 / 16, v, wrap) / 2.0;
            CHECK_NEAR(reference_sample(small, aniso(16, AnisoShape::gpu, wrap), lookup_texels(u, v, 16, 4.125, 0, 0, 4)),
                       two, 1e-15);
        }
        return std::string();
    });

    // Feline: J = R(30 deg) diag(8, 2) R(-55 deg)^T has singular values 8, 2 and major axis (cos 30, sin 30):
    // N = 4, lambda = log2(max(2, 8/4)) = 1, probes at t = -3/8, -1/8, 1/8, 3/8 of the 8-texel axis
    // (-3, -1, 1, 3 texels), weights exp(-2 (2t)^2) = exp(-1.125), exp(-0.125), exp(-0.125), exp(-1.125).
    test::named_check("ref aniso feline: SVD axis, N=4, lambda=1, Gaussian weights", [&] {
        const double pi = 3.14159265358979323846, a = 30 * pi / 180, b = -55 * pi / 180;
        // J = [U0 U1] diag(8, 2) [[cos b, -sin b], [sin b, cos b]], U0 = (cos a, sin a), U1 = (-sin a, cos a).
        const double s1 = 8, s2 = 2, ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b);
        const double jxu = ca * s1 * cb - sa * s2 * sb, jxv = sa * s1 * cb + ca * s2 * sb;
        const double jyu = ca * s1 * (-sb) - sa * s2 * cb, jyv = sa * s1 * (-sb) + ca * s2 * cb;
        double u = 0.41, v = 0.23;
        glm::dvec4 sum(0.0);
        double wsum = 0;
        for (int k = 0; k < 4; ++k) {
            double texels = -3.0 + 2 * k, w = std::exp(-2 * std::pow(texels / 4, 2));
            sum += w * reference_trilinear_at(small, 1.0, u + texels * ca / 16, v + texels * sa / 16, Wrap::repeat);
            wsum += w;
        }
        CHECK_NEAR(reference_sample(small, aniso(16, AnisoShape::feline), lookup_texels(u, v, 16, jxu, jxv, jyu, jyv)),
                   sum / wsum, 1e-12);
        // On mipcolors: LOD 1 (N = 4), and with probes 2 LOD log2(max(2, 8/2)) = 2.
        CHECK_NEAR(reference_sample(colors, aniso(16, AnisoShape::feline), lookup_texels(u, v, 256, jxu, jxv, jyu, jyv)),
                   kLevel[1], 1e-12);
        CHECK_NEAR(reference_sample(colors, aniso(2, AnisoShape::feline), lookup_texels(u, v, 256, jxu, jxv, jyu, jyv)),
                   kLevel[2], 1e-12);
        return std::string();
    });

    test::named_check("ref aniso probes 1 == trilinear (gpu exact, feline 1e-12)", [&] {
        // Feline's single probe sits on log2(sigma1), trilinear's on log2(max column): equal only where the
        // columns are orthogonal, as they are in this set (no shear).
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> uv(-1, 2), ang(0, 6.283185307179586), oct(-4, 9), st(0, 3);
        for (int i = 0; i < 2000; ++i) {
            double s = std::exp2(oct(rng)) / 256, a = ang(rng), r = std::exp2(st(rng));
            Lookup l{uv(rng), uv(rng), s * std::cos(a), s * std::sin(a), -s / r * std::sin(a), s / r * std::cos(a)};
            glm::dvec4 tri = reference_sample(noise, options_for(Filter::trilinear), l);
            CHECK_NEAR(reference_sample(noise, aniso(1, AnisoShape::gpu), l), tri, 0.0);
            CHECK_NEAR(reference_sample(noise, aniso(1, AnisoShape::feline), l), tri, 1e-12);
        }
        for (const Lookup& l : lookups) // sheared too, for the gpu shape
            CHECK_NEAR(reference_sample(noise, aniso(1, AnisoShape::gpu), l),
                       reference_sample(noise, options_for(Filter::trilinear), l), 0.0);
        return std::string();
    });

    test::named_check("ref constant texture -> constant (weights sum to 1)", [&] {
        Image flat = make_image(64, 48, glm::vec4(0.25f, 0.5f, 0.75f, 1.0f)); // NPOT-ish chain
        MipChain chain = build_mip_chain(flat);
        glm::dvec4 c(0.25, 0.5, 0.75, 1.0);
        std::vector<Lookup> all = random_lookups(500, 3);
        for (const Lookup& l : degenerate_lookups())
            all.push_back(l);
        for (const Lookup& l : all) {
            for (double band : {0.0, 0.25, 1.0})
                CHECK_NEAR(reference_sample(chain, brilinear(band), l), c, 1e-14);
            for (int probes : {1, 3, 16})
                for (AnisoShape shape : {AnisoShape::gpu, AnisoShape::feline})
                    CHECK_NEAR(reference_sample(chain, aniso(probes, shape), l), c, 1e-14);
        }
        return std::string();
    });

    test::named_check("ref degenerate: zero -> finest, NaN/Inf -> coarsest, 0-column -> N max", [&] {
        const glm::dvec4 last(colors.levels.back().at(0, 0));
        for (AnisoShape shape : {AnisoShape::gpu, AnisoShape::feline}) {
            SamplerOptions o = aniso(16, shape);
            CHECK_NEAR(reference_sample(colors, o, {0.3, 0.7, 0, 0, 0, 0}), kLevel[0], 0.0);
            CHECK_NEAR(reference_sample(colors, o, {0.3, 0.7, std::nan(""), 0, 0, 0.01}), last, 0.0);
            CHECK_NEAR(reference_sample(colors, o, {0.3, 0.7, 0.01, -INFINITY, 0, 0}), last, 0.0);
            // One column zero: N = 16 and lambda = log2(64/16) = 2 (gpu: Pmax = 64; feline: sigma1 = 64,
            // sigma2 = 0, max(0, 64/16) = 4).
            CHECK_NEAR(reference_sample(colors, o, lookup_texels(0.3, 0.7, 256, 64, 0, 0, 0)), kLevel[2], 1e-12);
            // Parallel columns: sigma2 = 0 too; gpu: Pmax/Pmin = 2 -> N = 2, lambda = log2(64/2) = 5.
        }
        CHECK_NEAR(reference_sample(colors, aniso(16, AnisoShape::gpu), lookup_texels(0.3, 0.7, 256, 64, 0, 32, 0)),
                   glm::dvec4(colors.levels[5].at(0, 0)), 1e-12);
        CHECK_NEAR(reference_sample(colors, brilinear(0.25), {0.3, 0.7, std::nan(""), 0, 0, 0}), last, 0.0);
        CHECK_NEAR(reference_sample(colors, brilinear(0.25), {0.3, 0.7, 0, 0, 0, 0}), kLevel[0], 0.0);
        return std::string();
    });
}

// ---------------------------------------------------------------------------------------------------
// Part 2: the GPU through `texfilter sample`.


// `texfilter sample --validate --stats` of a lookups CSV on a procedural texture.
SampleResult sample(const std::string& texture, const std::string& flags, const std::string& lookups)
{
    return test::run_sample("--texture " + texture + " " + flags, lookups, true);
}

// Worst error over the lookups, as a ratio to each lookup's bound.
struct Tally {
    int checked = 0, skipped = 0, worst_at = -1;
    double worst_error = 0, worst_ratio = 0;
    void add(double error, double bound)
    {
        if (error > worst_error)
            worst_at = checked + skipped;
        ++checked;
        worst_error = std::max(worst_error, error);
        worst_ratio = std::max(worst_ratio, error / bound);
    }
    std::string summary() const
    {
        char buf[200];
        std::snprintf(buf, sizeof buf, "%d lookups (%d knife-edge skipped), max error %.3g (lookup %d), worst error/bound %.3f",
                      checked, skipped, worst_error, worst_at, worst_ratio);
        return buf;
    }
};

struct Case {
    std::string texture;
    Wrap wrap;
};

// Two filters that must agree bit for bit on the same lookups: colours and texel fetch counts.
std::string same_results(const SampleResult& a, const SampleResult& b)
{
    CHECK_EQ(double(a.colors.size()), double(b.colors.size()));
    double worst = 0;
    for (size_t i = 0; i < std::min(a.colors.size(), b.colors.size()); ++i) {
        worst = std::max(worst, max_channel_diff(a.colors[i], b.colors[i]));
        CHECK_NEAR(a.colors[i], b.colors[i], 0.0);
        CHECK_EQ(double(a.stats[i].texel_fetches), double(b.stats[i].texel_fetches));
    }
    return "max difference " + str(worst);
}

void gpu_checks()
{
    std::vector<Lookup> lookups = random_lookups(4096, 2026);
    for (const Lookup& l : degenerate_lookups())
        lookups.push_back(l);
    lookups = test::as_float(lookups); // the reference sees the float values the GPU sees
    const std::string path = (test::work_dir() / "lookups.csv").string();
    test::write_lookups_csv(path, lookups);
    auto flags = [](const std::string& filter, Wrap wrap) { return "--filter " + filter + " --wrap " + to_string(wrap); };

    // Every lookup of a texfilter filter reads at most 16 probes x 8 texels.
    auto check_caps = [&](const SampleResult& r) {
        for (size_t i = 0; i < r.colors.size(); ++i) {
            const LookupStats& s = r.stats[i];
            CHECK(s.texel_fetches <= 128 && s.hardware_lookups <= 16,
                  "lookup " + std::to_string(i) + ": " + std::to_string(s.texel_fetches) + " fetches, " +
                      std::to_string(s.hardware_lookups) + " hw lookups");
            CHECK(std::isfinite(r.colors[i].x) && std::isfinite(r.colors[i].w), "lookup " + std::to_string(i));
        }
    };

    // --- brilinear -----------------------------------------------------------------------------------
    for (const Case& c : {Case{"noise", Wrap::repeat}, Case{"zoneplate", Wrap::mirror}}) {
        const MipChain chain = make_procedural(c.texture, 256);
        const SamplerOptions o = brilinear(0.25, c.wrap);
        SampleResult gpu;
        test::named_check("gpu brilinear 0.25 vs reference (" + c.texture + ", " + to_string(c.wrap) + ")", [&] {
            gpu = sample(c.texture, flags("brilinear", c.wrap) + " --band 0.25", path);
            Tally tally;
            for (size_t i = 0; i < lookups.size(); ++i) {
                const Lookup& l = lookups[i];
                Layout p; // one "probe" at uv, on lambda
                p.lod = clamp_lod(chain, reference_lod(chain, l, o));
                p.t = {0.0};
                p.weight = {1.0};
                double bound = float_bound(chain, c.wrap, l, p, false, 4.0); // the blend's slope is 1/B = 4 in the band
                double error = max_channel_diff(gpu.colors[i], reference_sample(chain, o, l));
                tally.add(error, bound);
                CHECK(error <= bound, "lookup " + std::to_string(i) + ": error " + str(error) + " > " + str(bound));
            }
            check_caps(gpu);
            return tally.summary();
        });
        test::named_check("gpu brilinear 0.25 fetches: 4 outside the band, 8 inside (" + c.texture + ")", [&] {
            if (gpu.colors.empty()) // run on its own (each check is its own ctest test)
                gpu = sample(c.texture, flags("brilinear", c.wrap) + " --band 0.25", path);
            int outside = 0, inside = 0, skipped = 0;
            for (size_t i = 0; i < lookups.size(); ++i) {
                double d = clamp_lod(chain, reference_lod(chain, lookups[i], o)), f = d - std::floor(d);
                if (std::abs(f - 0.375) < 1e-4 || std::abs(f - 0.625) < 1e-4) {
                    ++skipped;
                    continue;
                }
                unsigned expected = f > 0.375 && f < 0.625 ? 8 : 4;
                (expected == 8 ? inside : outside)++;
                const unsigned fetches = gpu.stats[i].texel_fetches;
                CHECK(fetches == expected,
                      "lookup " + std::to_string(i) + ": f " + str(f) + ", " + std::to_string(fetches) + " fetches");
            }
            CHECK(inside > 100 && outside > 100, std::to_string(inside) + " inside");
            return std::to_string(outside) + " outside (4), " + std::to_string(inside) + " inside (8), " +
                   std::to_string(skipped) + " at the band's edge skipped";
        });
    }
    {
        const std::string t = "noise";
        test::named_check("gpu brilinear band 1 == trilinear (bit for bit)", [&] {
            return same_results(sample(t, flags("brilinear", Wrap::repeat) + " --band 1", path),
                                sample(t, flags("trilinear", Wrap::repeat), path));
        });
        test::named_check("gpu brilinear band 0 == bilinear-mip (bit for bit)", [&] {
            SampleResult band = sample(t, flags("brilinear", Wrap::clamp) + " --band 0", path);
            for (const LookupStats& stats : band.stats)
                CHECK_EQ(double(stats.texel_fetches), 4.0);
            return same_results(band, sample(t, flags("bilinear-mip", Wrap::clamp), path));
        });
    }

    // The nearest-level tie: rho = 1 texel and a bias of 3/2 gives lambda = 1.5 exactly (level 1, the finer);
    // 1.5 + 2^-23 (the next float) must pick level 2, as ceil(d + 1/2) - 1 does in exact arithmetic.
    test::named_check("gpu brilinear band 0 at the tie f = 1/2 and 1/2 + 1 ulp", [&] {
        const std::string tie = (test::work_dir() / "tie.csv").string();
        test::write_lookups_csv(tie, {{0.3, 0.6, 1.0 / 256, 0, 0, 1.0 / 256}});
        const MipChain colors = make_procedural("mipcolors", 256);
        std::string note;
        for (const char* bias : {"1.5", "1.50000012"}) {
            SampleResult band = sample("mipcolors", "--filter brilinear --band 0 --lod-bias " + std::string(bias), tie);
            SamplerOptions o = brilinear(0.0);
            o.lod_bias = std::strtof(bias, nullptr);
            glm::dvec4 expected = reference_sample(colors, o, {0.3, 0.6, 1.0 / 256, 0, 0, 1.0 / 256});
            CHECK_NEAR(band.colors[0], expected, 0.0);
            // tf_bilinear_mip (lod.glsl's tf_mip_level_nearest) rounds lambda + 1/2 in float: not checked here.
            SampleResult mip = sample("mipcolors", "--filter bilinear-mip --lod-bias " + std::string(bias), tie);
            if (max_channel_diff(mip.colors[0], expected) > 0)
                note += std::string(note.empty() ? "note: bilinear-mip differs from the reference at bias " : ", ") + bias;
        }
        return note;
    });

    // A footprint one float step above a power of two: λ = 1 + 1.7e-7, within log2's own error of level 1, so
    // one level is read (lod.glsl tfi_log2; without it trilinear read 8 texels, aniso 32, for a level-2 weight
    // of ~1e-7), and the colour is level 1's. J = 2 (1 + 2^-23) texels (trilinear, brilinear's band 0.25 is
    // the same), diag(8 (1 + 2^-23), 2) for aniso (N = 4).
    test::named_check("gpu lod within float rounding of a level reads that level alone", [&] {
        const std::string path = (test::work_dir() / "near-level.csv").string();
        const double t = 1.0 / 256, up = 1.0 + std::ldexp(1.0, -23);
        test::write_lookups_csv(path, {{0.3, 0.6, 2 * up * t, 0, 0, 2 * up * t}, {0.3, 0.6, 8 * up * t, 0, 0, 2 * t}});
        const SampleResult tri = sample("mipcolors", "--filter trilinear", path);
        const SampleResult an = sample("mipcolors", "--filter aniso --probes 16", path);
        CHECK_NEAR(tri.colors[0], kLevel[1], 0.0);
        CHECK_EQ(double(tri.stats[0].texel_fetches), 4.0);
        CHECK_NEAR(an.colors[1], kLevel[1], 0.0);
        CHECK_EQ(double(an.stats[1].texel_fetches), 16.0);
        return std::string();
    });

    // Known footprints on mipcolors (each level one colour), counted: J = diag(8, 2) texels -> N = 4 on
    // LOD 1 exactly (4 fetches a probe: 16); diag(8, 3) -> N = 3, LOD log2(8/3) (24 fetches); one column
    // (64, 0) -> N = 16, LOD 2 (64 fetches); zero -> level 0, NaN -> the last level, one probe (4 fetches).
    test::named_check("gpu aniso known footprints: N, LOD, fetches (mipcolors)", [&] {
        const std::string known = (test::work_dir() / "known.csv").string();
        const double t = 1.0 / 256;
        const std::vector<Lookup> ls = {{0.3, 0.6, 8 * t, 0, 0, 2 * t},  {0.3, 0.6, 8 * t, 0, 0, 3 * t},
                                        {0.3, 0.6, 64 * t, 0, 0, 0},     {0.3, 0.6, 0, 0, 0, 0},
                                        {0.3, 0.6, std::nan(""), 0, 0, 0}};
        test::write_lookups_csv(known, ls);
        const MipChain colors = make_procedural("mipcolors", 256);
        const unsigned fetches[] = {16, 24, 64, 4, 4}, probes[] = {4, 3, 16, 1, 1};
        // The hardware taps take the probes' λ through textureLod, which may round it by two mipmapPrecisionBits
        // steps (hardware_bound), times the neighbouring levels' largest difference (mipcolors: 0.5 a channel).
        const double hardware_error = 2.0 * std::ldexp(1.0, -int(test::test_device_info().mipmap_precision_bits)) * 0.5 + 1e-6;
        for (AnisoShape shape : {AnisoShape::gpu, AnisoShape::feline}) {
            SampleResult manual = sample("mipcolors", "--filter aniso --probes 16 --aniso-shape " + to_string(shape), known);
            SampleResult hardware = sample("mipcolors", "--filter aniso --probes 16 --taps hardware --aniso-shape " + to_string(shape), known);
            for (size_t i = 0; i < ls.size(); ++i) {
                glm::dvec4 expected = reference_sample(colors, aniso(16, shape), ls[i]);
                CHECK_NEAR(manual.colors[i], expected, 1e-6);
                CHECK_NEAR(hardware.colors[i], expected, hardware_error);
                CHECK_EQ(double(manual.stats[i].texel_fetches), double(fetches[i]));
                CHECK_EQ(double(hardware.stats[i].hardware_lookups), double(probes[i]));
            }
            CHECK_NEAR(manual.colors[0], kLevel[1], 0.0);
            CHECK_NEAR(manual.colors[2], kLevel[2], 0.0);
            CHECK_NEAR(manual.colors[3], kLevel[0], 0.0);
            CHECK_NEAR(manual.colors[4], glm::dvec4(colors.levels.back().at(0, 0)), 0.0);
        }
        return std::string();
    });

    // --- aniso ---------------------------------------------------------------------------------------
    for (AnisoShape shape : {AnisoShape::gpu, AnisoShape::feline}) {
        const std::string s = to_string(shape);
        const bool feline = shape == AnisoShape::feline;
        for (const Case& c : {Case{"noise", Wrap::repeat}, Case{"checker", Wrap::clamp}}) {
            const MipChain chain = make_procedural(c.texture, 256);
            const SamplerOptions o = aniso(16, shape, c.wrap);
            const std::string f = flags("aniso", c.wrap) + " --probes 16 --aniso-shape " + s;
            SampleResult manual, hardware;
            std::vector<Layout> layouts;
            std::vector<bool> edge;
            for (const Lookup& l : lookups) {
                layouts.push_back(layout_of(chain, o, l));
                edge.push_back(knife_edge_count(layouts.back(), 16));
            }
            test::named_check("gpu aniso " + s + " manual vs reference (" + c.texture + ", " + to_string(c.wrap) + ")", [&] {
                manual = sample(c.texture, f + " --taps manual", path);
                Tally tally;
                for (size_t i = 0; i < lookups.size(); ++i) {
                    if (edge[i]) {
                        ++tally.skipped;
                        continue;
                    }
                    double bound = float_bound(chain, c.wrap, lookups[i], layouts[i], feline);
                    double error = max_channel_diff(manual.colors[i], reference_sample(chain, o, lookups[i]));
                    tally.add(error, bound);
                    CHECK(error <= bound, "lookup " + std::to_string(i) + ": N " + std::to_string(layouts[i].count) +
                                              ", ratio " + str(layouts[i].ratio) + ", error " + str(error) + " > " + str(bound));
                }
                check_caps(manual);
                return tally.summary();
            });
            test::named_check("gpu aniso " + s + " manual fetches = 8N (4N on a level) (" + c.texture + ")", [&] {
                if (manual.colors.empty()) // run on its own (each check is its own ctest test)
                    manual = sample(c.texture, f + " --taps manual", path);
                double mean = 0;
                int checked = 0;
                for (size_t i = 0; i < lookups.size(); ++i) {
                    if (edge[i])
                        continue;
                    const Layout& p = layouts[i];
                    unsigned expected = unsigned(p.count) * (p.lod == std::floor(p.lod) ? 4 : 8);
                    const LookupStats& st = manual.stats[i];
                    CHECK(st.texel_fetches == expected && st.hardware_lookups == 0,
                          "lookup " + std::to_string(i) + ": N " + std::to_string(p.count) + ", lod " + str(p.lod) +
                              ", " + std::to_string(st.texel_fetches) + " fetches");
                    mean += st.texel_fetches;
                    ++checked;
                }
                return "mean " + str(mean / checked) + " fetches over " + std::to_string(checked) + " lookups";
            });
            test::named_check("gpu aniso " + s + " hardware vs manual taps (" + c.texture + ", " + to_string(c.wrap) + ")", [&] {
                hardware = sample(c.texture, f + " --taps hardware", path);
                if (manual.colors.empty())
                    manual = sample(c.texture, f + " --taps manual", path);
                Tally tally;
                for (size_t i = 0; i < lookups.size(); ++i) {
                    if (edge[i]) { // the same shader code picks N on both sides, but the layout here may not
                        ++tally.skipped;
                        continue;
                    }
                    double bound = hardware_bound(chain, c.wrap, lookups[i], layouts[i]);
                    double error = max_channel_diff(hardware.colors[i], manual.colors[i]);
                    tally.add(error, bound);
                    CHECK(error <= bound, "lookup " + std::to_string(i) + ": error " + str(error) + " > " + str(bound));
                    const LookupStats& st = hardware.stats[i];
                    CHECK(st.texel_fetches == 0 && st.hardware_lookups == unsigned(layouts[i].count),
                          "lookup " + std::to_string(i) + ": " + std::to_string(st.hardware_lookups) + " hw lookups, N " +
                              std::to_string(layouts[i].count));
                }
                check_caps(hardware);
                return tally.summary();
            });
        }
    }
    test::named_check("gpu aniso gpu --probes 1 == trilinear (bit for bit)", [&] {
        return same_results(sample("zoneplate", flags("aniso", Wrap::mirror) + " --probes 1", path),
                            sample("zoneplate", flags("trilinear", Wrap::mirror), path));
    });
    // A finite uv whose texel coordinate overflows float (u * 512 > 3.4e38) once gave NaN weights (Inf - Inf)
    // in every bilinear-based manual form; the coordinate is clamped to +-2^24 now. The value is that of some
    // texel, so only finiteness and the [0, 1] range of a checker are asserted.
    test::named_check("gpu huge finite uv: manual bilinear-based forms stay finite", [&] {
        const std::vector<Lookup> huge = {{1e38, 0.5, 0.001, 0, 0, 0.001}, {-3e38, 1e38, 0.01, 0, 0, 0.02},
                                          {3.4e38, -3.4e38, 0.003, 0.002, -0.001, 0.004}};
        const std::string huge_path = (test::work_dir() / "huge.csv").string();
        test::write_lookups_csv(huge_path, huge);
        for (const std::string filter : {"bilinear", "bilinear-mip", "trilinear", "brilinear", "aniso"}) {
            SampleResult r = sample("checker", flags(filter, Wrap::repeat), huge_path);
            for (size_t i = 0; i < huge.size(); ++i)
                for (int c = 0; c < 4; ++c)
                    CHECK(std::isfinite(r.colors[i][c]) && r.colors[i][c] >= 0.0 && r.colors[i][c] <= 1.0,
                          filter + " lookup " + std::to_string(i) + " channel " + std::to_string(c));
        }
        return std::string("5 filters x 3 lookups finite");
    });
}

} // namespace

TEST_SUITE_BEGIN("reference");
TEST_CASE("reference") { reference_checks(); }
TEST_SUITE_END();

TEST_SUITE_BEGIN("gpu");
TEST_CASE("gpu")
{
    gpu_checks();
}
TEST_SUITE_END();
