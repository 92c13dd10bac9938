// EWA (shaders/texfilter/ewa.glsl, host/reference/ewa.cpp): the CPU reference and the GPU (lavapipe
// by default), both tap forms. One line per check with the measured number and its bound.
//
// usage: test_ewa PATH/TO/texfilter
// The GPU runs in this process through the harness library (tf::gpu_sample: any texture, per-lookup
// fetch counts) and, for the non-finite and huge footprints, through `texfilter sample --validate`
// (the command must return: the shader's loops are capped). TEXFILTER_VALIDATE=1 turns the
// validation layers on in-process too; any message fails the test.
#include "core/filter.h"
#include "vulkan/backend.h"
#include "texture/image.h"
#include "texture/mip.h"
#include "core/procedural.h"
#include "reference/reference.h"
#include "support.h"
#include "vulkan/device.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>

using namespace tf;
using tf::test::as_float;

namespace {

// TF_EWA_MAX_TEXELS's default: at most K rows of K texels per level.
constexpr int kMaxTexels = 95;
// TF_EWA_SUPPORT: R², the weight's support r² < R².
constexpr double kSupport = 2.0;

double max_abs(const glm::dvec4& d) { return std::max(std::max(std::abs(d.r), std::abs(d.g)), std::max(std::abs(d.b), std::abs(d.a))); }
bool finite(const glm::dvec4& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b) && std::isfinite(c.a); }

// ---------------------------------------------------------------- lookups

// Footprints from 1/16 texel to 512 texels, axis ratios 1..64 (past max_aniso 16), any angle, uv in [-1, 2].
std::vector<Lookup> random_lookups(int count, unsigned seed, int size = 256) {
    return as_float(test::random_footprint_lookups(count, seed, {.max_stretch = 6.0, .texture_size = double(size)}));
}

// Isotropic footprints (a rotated square pixel) of 2^lo .. 2^hi texels.
std::vector<Lookup> isotropic_lookups(int count, unsigned seed, double lo, double hi, int size = 256) {
    return as_float(test::random_footprint_lookups(
        count, seed, {.uv_min = 0.0, .uv_max = 1.0, .octave_min = lo, .octave_max = hi, .texture_size = double(size)}));
}

// ---------------------------------------------------------------- textures

MipChain constant_chain(int w, int h, glm::vec4 value) { return build_mip_chain(make_image(w, h, value)); }

// Sum of low-frequency waves, periodic over the texture (repeat wrap is seamless): smooth at every level.
// Level-0 gradient magnitude <= sum A·2π|k|/N, Hessian (|t_xx|+|t_yy|) <= sum A·(2π|k|/N)²·2.
struct Wave {
    double amplitude, kx, ky, phase;
};
const std::vector<Wave> kSmoothWaves = {{0.2, 1, 0, 0.3}, {0.15, 1, 2, 1.1}, {0.1, -2, 1, 2.0}};

MipChain wave_chain(int size, const std::vector<Wave>& waves) {
    Image img = make_image(size, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            double t = 0.5;
            for (const Wave& w : waves)
                t += w.amplitude *
                     std::sin(2 * std::numbers::pi * (w.kx * (x + 0.5) + w.ky * (y + 0.5)) / size + w.phase);
            img.at(x, y) = glm::vec4(float(t), float(1 - t), float(0.5 * t), 1.0f);
        }
    return build_mip_chain(img);
}

// Largest |t(i+1,j) - t(i,j)| or |t(i,j+1) - t(i,j)| (wrapped) and |t00 - t10 - t01 + t11| over all levels.
void texture_differences(const MipChain& chain, Wrap wrap, double& adjacent, double& mixed) {
    adjacent = mixed = 0;
    for (const Image& img : chain.levels)
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) {
                auto t = [&](int i, int j) {
                    return glm::dvec4(img.at(wrap_texel(i, img.width, wrap), wrap_texel(j, img.height, wrap)));
                };
                adjacent = std::max({adjacent, max_abs(t(x + 1, y) - t(x, y)), max_abs(t(x, y + 1) - t(x, y)),
                                     max_abs(t(x - 1, y) - t(x, y)), max_abs(t(x, y - 1) - t(x, y))});
                mixed = std::max(mixed, max_abs(t(x, y) - t(x + 1, y) - t(x, y + 1) + t(x + 1, y + 1)));
            }
}

// ---------------------------------------------------------------- GPU and reference runs

struct Gpu {
    VulkanContext context;
    // The test device, validation on; no validation message by the end.
    Gpu() : context(create_context(test::test_context_options())) {}
    ~Gpu()
    {
        destroy_context(context);
        CHECK_LE("Vulkan validation messages (in-process)", double(validation_message_count()), 0.0);
    }
    std::vector<glm::dvec4> sample(const MipChain& chain, const std::vector<Lookup>& lookups,
                                   const SamplerOptions& options, std::vector<LookupStats>* stats = nullptr) {
        GpuTexture texture = upload_texture(context, chain, false);
        std::vector<glm::vec4> out;
        try {
            out = gpu_sample(context, texture, lookups, options, stats);
        } catch (...) {
            destroy_texture(context, texture);
            throw;
        }
        destroy_texture(context, texture);
        return {out.begin(), out.end()};
    }
};
// What a GPU test case holds: the device and its subTexelPrecisionBits.
struct GpuCase {
    Gpu gpu;
    int bits = int(gpu.context.info.sub_texel_precision_bits);
    GpuCase() { std::printf("     device: %s, subTexelPrecisionBits %d\n", gpu.context.info.name.c_str(), bits); }
};

// The texfilter command's cases (no in-process device): the device's subTexelPrecisionBits.
int command_case() { return int(test::test_device_info().sub_texel_precision_bits); }

std::vector<glm::dvec4> reference(const MipChain& chain, const std::vector<Lookup>& lookups,
                                  const SamplerOptions& options) {
    std::vector<glm::dvec4> out;
    out.reserve(lookups.size());
    for (const Lookup& l : lookups) out.push_back(reference_sample(chain, options, l));
    return out;
}

SamplerOptions ewa_options(Wrap wrap, Taps taps, float alpha = 2.0f, float max_aniso = 16.0f) {
    SamplerOptions o;
    o.filter = Filter::ewa;
    o.wrap = wrap;
    o.taps = taps;
    o.alpha = alpha;
    o.max_aniso = max_aniso;
    return o;
}

std::string describe(Wrap wrap, Taps taps) { return to_string(wrap) + ", " + to_string(taps); }

double max_error(const std::vector<glm::dvec4>& a, const std::vector<glm::dvec4>& b) {
    double e = 0;
    for (size_t i = 0; i < a.size(); ++i) e = std::max(e, finite(a[i]) && finite(b[i]) ? max_abs(a[i] - b[i]) : INFINITY);
    return e;
}
double rms_error(const std::vector<glm::dvec4>& a, const std::vector<glm::dvec4>& b) {
    double s = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        const glm::dvec4 d = a[i] - b[i];
        s += glm::dot(d, d) / 4;
    }
    return std::sqrt(s / double(a.size()));
}

// ---------------------------------------------------------------- checks

constexpr double kUlp = 1.0 / 16777216.0; // 2^-24: float's unit roundoff

// Reference value with the footprint scaled by `scale` (both gradients).
glm::dvec4 reference_scaled(const MipChain& chain, const SamplerOptions& o, Lookup l, double scale) {
    l.dudx *= scale, l.dvdx *= scale, l.dudy *= scale, l.dvdy *= scale;
    return reference_sample(chain, o, l);
}

// GPU (float) vs CPU reference (double) on random footprints, per lookup:
// (1) texels on the support's edge and the level choice: a float r² within ~1e-6 of R² can land on the
//     other side (the weight is continuous there now, so that moves little) and a float lambda on the
//     other side of a level's edge. The reference evaluated with the footprint 1e-5 larger and smaller
//     (r² moves by 2e-5; lambda by 1.4e-5) brackets both: the spread is allowed.
// (2) float: each of the n sums adds one ulp a term and values are in [0, 1]: 2n ulp, plus 8 for the
//     fit's and the blend's few operations (measured on lavapipe: below (8 + n) ulp at alpha 2). The
//     weights' own error grows with alpha: the exponent is -alpha·r² with r² (< R² = 2) rounded by
//     ~4 ulp relative, and Vulkan's exp() is good to 3 + 2|x| ulp, so a weight is off by up to
//     (3 + 6·alpha·R²) ulp relative, 2.5x that after subtracting exp(-alpha R²) (tfi_ewa_weight: the
//     difference keeps at least 1 - e^-1/2 of the value); a relative weight error e moves a normalised
//     result by at most e·max|t - result| <= e. In all (8 + 2n + 2.5·(3 + 6·alpha·R²)) ulp.
// Hardware taps add the sampler's own rounding: the tap is a float uv, so its texel position (< 2·size
//     + K = 580 texels here) is off by up to 2 float spacings of 512..1024 (2·2^-14 texel), and the
//     bilinear weights are rounded to subTexelPrecisionBits (Vulkan allows 8: 2^-8·(2·across + down)
//     per tap, as in test_hw_vs_manual), across/down = the largest adjacent-texel difference on any
//     level. The result is a weighted mean of taps, so its error is at most the worst tap's.
void check_gpu_vs_reference(Gpu& device, const std::string& texture, SamplerOptions o, const std::string& label, int bits) {
    const MipChain chain = make_procedural(texture, 256);
    const std::vector<Lookup> lookups = random_lookups(2048, 21);
    std::vector<LookupStats> stats;
    const auto gpu = device.sample(chain, lookups, o, &stats);
    const auto ref = reference(chain, lookups, o);
    double adjacent, mixed;
    texture_differences(chain, o.wrap, adjacent, mixed);
    const bool hw = o.taps == Taps::hardware;
    const double sampler = hw ? (std::exp2(-bits) * 3 + 2 * std::exp2(-14)) * adjacent : 0.0;
    double worst = 0, worst_ratio = 0;
    int edges = 0;
    for (size_t i = 0; i < lookups.size(); ++i) {
        const double edge = std::max(max_abs(reference_scaled(chain, o, lookups[i], 1 + 1e-5) - ref[i]),
                                     max_abs(reference_scaled(chain, o, lookups[i], 1 - 1e-5) - ref[i]));
        const double n = stats[i].texel_fetches + stats[i].hardware_lookups;
        const double err = finite(gpu[i]) ? max_abs(gpu[i] - ref[i]) : INFINITY;
        edges += edge > 1e-5;
        worst = std::max(worst, err);
        const double weights = 2.5 * (3 + 6 * double(o.alpha) * kSupport);
        // The magnification filter's share (bilinear on level 0): its texel coordinate rounds like any
        // bilinear lookup's, 2 ulp of |x| + 1/2 an axis, times the adjacent-texel contrast.
        const double x = std::max(std::abs(reduce_uv(lookups[i].u, o.wrap)), std::abs(reduce_uv(lookups[i].v, o.wrap))) * 256;
        const double magnified = magnified_share(chain, o, lookups[i]) * 4 * kUlp * (x + 0.5) * adjacent;
        worst_ratio = std::max(worst_ratio, (err - edge) / ((8 + 2 * n + weights) * kUlp + sampler + magnified));
    }
    std::printf("     %s %s: max |GPU - reference| %.3g, %d lookups with a texel on the edge\n", texture.c_str(),
                label.c_str(), worst, edges);
    CHECK_LE("GPU vs reference, error / tolerance: " + texture + ", " + to_string(o.wrap) + ", " + label, worst_ratio,
             1.0);
}

// Hardware vs manual taps on textures with detail (noise, checker, zoneplate), reference and GPU: measured
// and printed, not asserted. The two forms are different estimators since the line fit (manual) and
// the shifted bilinear taps (hardware): both reproduce a linear texture exactly (the ramp case) and both
// are close to trilinear on a smooth one (the isotropic-vs-trilinear case), but on a texture with detail
// they differ by how each treats its non-linear part, for which there is no tight bound (the merge
// identity "exact on f(x) + g(y)" of the unshifted taps no longer holds once every tap is shifted).
void report_hw_vs_manual(Gpu& device, const std::string& name, const MipChain& chain, Wrap wrap) {
    const std::vector<Lookup> lookups = random_lookups(1024, 31, chain.levels[0].width);
    const auto manual = reference(chain, lookups, ewa_options(wrap, Taps::manual));
    const auto hw = reference(chain, lookups, ewa_options(wrap, Taps::hardware));
    const auto gpu_manual = device.sample(chain, lookups, ewa_options(wrap, Taps::manual));
    const auto gpu_hw = device.sample(chain, lookups, ewa_options(wrap, Taps::hardware));
    std::printf("     hardware vs manual taps on %s (%s): reference RMS %.3g max %.3g; GPU RMS %.3g max %.3g\n",
                name.c_str(), to_string(wrap).c_str(), rms_error(hw, manual), max_error(hw, manual),
                rms_error(gpu_hw, gpu_manual), max_error(gpu_hw, gpu_manual));
}

// Hardware vs manual taps where they differed most: texels that alternate at the read level's Nyquist rate
// (a checker 512 with 64-texel cells seen at 64-256 texels a pixel reads levels 5-7, where a cell is 1-4
// texels; a zone plate at 2-8 texels) under rotated, near-isotropic footprints (anisotropy 1-4). One bilinear
// tap gives a 2x2 block separable weights, misweighing the block's checkerboard part by 4|w00 w11 - w10 w01| /
// total, the same sign in every block of a rotated ellipse, so the errors add up (RMS 0.013 on the checker and
// 0.004 on the zone plate here before such blocks got two taps). Blocks twisted by more than 0.005 of the level's
// weight are now two exact taps; the bound is what one block at that limit can misweigh on these [0, 1] textures
// (checkerboard part at most 0.5): 0.005 x 0.5 = 0.0025.
void check_twisted_blocks(Gpu& device, const char* texture, int size, double major_lo, double major_hi, Wrap wrap) {
    const MipChain chain = make_procedural(texture, size);
    std::mt19937 rng(47);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Lookup> lookups;
    for (int i = 0; i < 512; ++i) {
        const double major = major_lo * std::pow(major_hi / major_lo, unit(rng)) / size;
        const double minor = major / std::exp2(2 * unit(rng)), a = std::numbers::pi * unit(rng);
        lookups.push_back(as_float({unit(rng), unit(rng), major * std::cos(a), major * std::sin(a), -minor * std::sin(a),
                                    minor * std::cos(a)}));
    }
    const double bound = 0.005 * 0.5;
    const std::string what = std::string(texture) + " at " + std::to_string(int(major_lo)) + "-" +
                             std::to_string(int(major_hi)) + " texels";
    CHECK_LE("twisted blocks: RMS |hardware - manual|, reference, " + what,
             rms_error(reference(chain, lookups, ewa_options(wrap, Taps::hardware)),
                       reference(chain, lookups, ewa_options(wrap, Taps::manual))),
             bound);
    CHECK_LE("twisted blocks: RMS |hardware - manual|, GPU, " + what,
             rms_error(device.sample(chain, lookups, ewa_options(wrap, Taps::hardware)),
                       device.sample(chain, lookups, ewa_options(wrap, Taps::manual))),
             bound);
}

// ---------------------------------------------------------------- linear ramp (no bias)

// R = u, G = v in level-0 texels: texel (x, y) holds its centre (x + ½, y + ½). The box MIP chain of a
// power-of-two ramp is the same ramp on every level (each texel the mean of its children's centres),
// so a filter that is symmetric about uv and reproduces linear functions returns (u·w, v·h) exactly.
MipChain ramp_chain(int size) {
    Image img = make_image(size, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) img.at(x, y) = glm::vec4(float(x) + 0.5f, float(y) + 0.5f, 0.0f, 1.0f);
    return build_mip_chain(img);
}

// Random footprints of 2..24 texels (J's larger singular value), axis ratio 1..16, any angle and shear,
// uv in [0.35, 0.65] (the coarser level's support stays > 100 texels from the clamp edges).
std::vector<Lookup> ramp_lookups(int count, unsigned seed, int size) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uv(0.35, 0.65), angle(0.0, 2 * std::numbers::pi), octaves(1.0, std::log2(24.0)),
        stretch(0.0, 4.0), shear(-0.6, 0.6);
    std::vector<Lookup> lookups;
    for (int i = 0; i < count; ++i) {
        const double major = std::exp2(octaves(rng)) / size, a = angle(rng), minor = major / std::exp2(stretch(rng));
        const double b = a + std::numbers::pi / 2 + shear(rng);
        lookups.push_back(as_float({uv(rng), uv(rng), major * std::cos(a), major * std::sin(a), minor * std::cos(b),
                                    minor * std::sin(b)}));
    }
    return lookups;
}

// EWA's LOD for a lookup (the filter's rule, re-derived here in double only to bound errors): the
// coarser of the two levels it reads. The shader's own rounding of lambda is covered by taking ceil.
int ewa_coarse_level(const MipChain& chain, const Lookup& l, double max_aniso) {
    const double w = chain.levels[0].width, h = chain.levels[0].height;
    const double a = l.dudx * w, b = l.dudy * w, c = l.dvdx * h, d = l.dvdy * h;
    const double s = a * a + b * b, t = a * c + b * d, r = c * c + d * d;
    const double major2 = 0.5 * (s + r) + std::hypot(0.5 * (s - r), t);
    const double minor2 = std::max((a * d - b * c) * (a * d - b * c) / major2, major2 / (max_aniso * max_aniso));
    const double major_texels = (kMaxTexels - 3) / (4.0 * std::sqrt(kSupport));
    const double lambda = std::max(0.5 * std::log2(minor2) - 0.5, 0.5 * std::log2(major2) - std::log2(major_texels));
    return std::clamp(int(std::ceil(lambda + 1e-6)), 0, int(chain.levels.size()) - 1);
}

// ---------------------------------------------------------------- overshoot

// ---------------------------------------------------------------- non-finite and huge footprints

// Runs `texfilter sample --validate` under its time limit: a shader that hangs fails the check instead of
// blocking the test. False (and the command on stderr) if it failed.
bool run_cli(const std::string& flags, const std::string& lookups, bool stats, test::SampleResult& result) {
    try {
        result = test::run_sample_command(flags, lookups, stats);
        return true;
    } catch (const Error& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return false;
    }
}

// ---------------------------------------------------------------- degenerate input, every family

}  // namespace

// ewa's magnification spreads its lookups by k² = the weight's per-axis variance (reference_ewa_weight_variance,
// Simpson's rule in r²): against the closed form worked here by hand, with w(u) = e^(-αu) - e^(-αU), U = R² = 2,
// mass = ∫w du = (1 - e^(-αU))/α - U e^(-αU), ∫u w du = (1 - (1 + αU) e^(-αU))/α² - U² e^(-αU)/2, and the
// variance E[u]/2 = (∫u w)/(2 mass): 1/3 = U/6 as α -> 0 (w linear in u), 1/(2α) as α grows (a Gaussian). The
// quadrature's relative error at 8192 steps h = U/8192 is of Simpson's order (α·h)⁴, 6e-8 at α = 64 (the widest
// use, measured 1.3e-9): bound 1e-8. Below α = 1/64 the variance is α = 1/64's (the clamp).
TEST_CASE("weight-variance") {
    auto closed_form = [](double a) {
        const double U = kSupport, e = std::exp(-a * U);
        const double mass = (1 - e) / a - U * e, moment = (1 - (1 + a * U) * e) / (a * a) - 0.5 * U * U * e;
        return 0.5 * moment / mass;
    };
    double worst = 0;
    for (double a : {1.0 / 64, 0.1, 0.5, 1.0, 2.0, 8.0, 32.0, 64.0})
        worst = std::max(worst, std::abs(reference_ewa_weight_variance(a) / closed_form(a) - 1));
    CHECK_LE("|quadrature / closed form - 1| over alpha 1/64..64", worst, 1e-8);
    CHECK_LE("alpha 2 (the default): |variance - 0.2097|", std::abs(reference_ewa_weight_variance(2.0) - 0.2097), 1e-4);
    CHECK_LE("alpha 64: |variance · 2 alpha - 1| (a Gaussian: e^-128 of it cut off)",
             std::abs(reference_ewa_weight_variance(64.0) * 128 - 1), 1e-8);
    CHECK_LE("alpha 0: |variance - 1/3| (the clamp to 1/64)", std::abs(reference_ewa_weight_variance(0.0) - 1.0 / 3),
             0.002);
    CHECK_EQ(reference_ewa_weight_variance(0.0), reference_ewa_weight_variance(1.0 / 64));
}

// The level rule's variance bookkeeping (ewa.glsl, "Math"), measured through the whole filter: on a texture
// that is a parabola along u, t = (x - c)²/S (x in level-0 texels), any filter returns (x0 - c)²/S plus its
// kernel's second moment along u over S. The Gaussian-pixel truth's is σ²·(J·Jᵀ)_uu + 1/6 (the bilinear
// tent); the level's is the box its texels average ((4^l - 1)/12 level-0 texels², exact on a parabola) plus
// 4^l·v·M_uu, M = S·J·Jᵀ·S + r₀·I with r₀ = (3·4^-l - 1)/(12v) where M needs no lift: in sum v·(J·Jᵀ)_uu + 1/6,
// alpha's own σ² = v in place of ¼. The lookup is held on one level (lodMin = lodMax = l) with the footprint's
// smaller eigenvalue 4 level texels² there (no lift). Bound 2 %: the sampled, truncated weight's second moment
// against the continuous v·M (σ ≈ 0.9 texel, cut at r² = R²) and the line fit's centroid correction; the rule
// before (M = S·J·Jᵀ·S + I) is 27-36 % over on these levels.
TEST_CASE("level-variance") {
    const int size = 256;
    const double c = size / 2.0, scale = c * c;
    Image img = make_image(size, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double t = (x + 0.5 - c) * (x + 0.5 - c) / scale;
            img.at(x, y) = glm::vec4(float(t), float(t), float(t), 1.0f);
        }
    const MipChain chain = build_mip_chain(img);
    const double v = reference_ewa_weight_variance(2.0);
    for (int level = 1; level <= 4; ++level) {
        SamplerOptions o = ewa_options(Wrap::clamp, Taps::manual);
        o.lod_min = o.lod_max = float(level);
        const double a = 2.0 * std::exp2(level), b = std::sqrt(2.0) * a; // (J·Jᵀ)_uu = 4·4^l, _vv = 8·4^l
        double worst = 0;
        for (double x0 : {128.0, 128.3, 129.7, 131.25}) {
            const Lookup l{x0 / size, 0.5 + 0.37 / size, a / size, 0.0, 0.0, b / size};
            const double excess = reference_sample(chain, o, l).r * scale - (x0 - c) * (x0 - c);
            const double target = v * a * a + 1.0 / 6.0;
            worst = std::max(worst, std::abs(excess / target - 1));
        }
        CHECK_LE("second moment along u / (v·(J·Jᵀ)_uu + 1/6) - 1, level " + std::to_string(level), worst, 0.02);
    }
}

TEST_SUITE_BEGIN("gpu");

// The position EWA returns on the ramp is uv·size up to rounding, on both backends and tap forms:
// - reference, manual and hardware taps (exact bilinear): double rounding, bound 1e-9 texels;
// - GPU, manual taps: the result is a fit over n float texel values t <= size: the sums of w·t, w·d·t
//   and the fit's few operations round by (2n + 16) ulp of the largest value (as the constant case), i.e.
//   (2n + 16)·2^-24·size texels, n the fetches of the lookup;
// - GPU, hardware taps: each tap's position is rounded to subTexelPrecisionBits (2^-bits/2 per axis)
//   and its float uv by 2 spacings of 2^-14 level texels (as check_gpu_vs_reference), on a level of
//   2^l level-0 texels, l the coarser level read; the fit is a weighted mean of those positions plus a
//   gradient term whose weights sum to 0, so its error is within 2x the worst tap's, plus the manual bound.
TEST_CASE("ramp")
{
    GpuCase c;
    Gpu& device = c.gpu;
    const int bits = c.bits;
    const int size = 512;
    const MipChain chain = ramp_chain(size);
    const std::vector<Lookup> lookups = ramp_lookups(2048, 51, size);
    for (Taps taps : {Taps::manual, Taps::hardware}) {
        const SamplerOptions o = ewa_options(Wrap::clamp, taps);
        const auto ref = reference(chain, lookups, o);
        std::vector<LookupStats> stats;
        const auto gpu = device.sample(chain, lookups, o, &stats);
        for (bool on_gpu : {false, true}) {
            const auto& out = on_gpu ? gpu : ref;
            std::vector<double> errors;
            double worst_ratio = 0;
            for (size_t i = 0; i < lookups.size(); ++i) {
                const double ex = std::abs(out[i].r - lookups[i].u * size), ey = std::abs(out[i].g - lookups[i].v * size);
                const double err = std::isfinite(ex + ey) ? std::max(ex, ey) : INFINITY;
                errors.push_back(err);
                double bound = 1e-9;
                if (on_gpu) {
                    const double n = stats[i].texel_fetches + stats[i].hardware_lookups;
                    bound = (2 * n + 16) * kUlp * size;
                    if (taps == Taps::hardware)
                        bound += 2 * (0.5 * std::exp2(-bits) + 2 * std::exp2(-14)) *
                                 std::exp2(ewa_coarse_level(chain, lookups[i], 16.0));
                }
                worst_ratio = std::max(worst_ratio, err / bound);
            }
            std::sort(errors.begin(), errors.end());
            const std::string who = std::string(on_gpu ? "GPU" : "reference") + ", " + to_string(taps);
            std::printf("     ramp 512², footprints 2..24 texels (%s): position error max %.3g, median %.3g texels\n",
                        who.c_str(), errors.back(), errors[errors.size() / 2]);
            CHECK_LE("ramp: EWA returns uv·size, error / bound (" + who + ")", worst_ratio, 1.0);
        }
    }
}

// Weights are normalised: a constant texture gives that constant for every footprint, wrap mode and
// tap form (a missing or wrong division by the weight sum scales it). NPOT, non-square: 61x47.
// Reference: exact to double rounding. GPU: sum(w·c) and sum(w) over n texels (or taps) each round
// by at most (n-1) ulp relative, the division and the level blend by a few more, so the result is
// within (2n + 4)·2^-24·c of c.
TEST_CASE("constant")
{
    GpuCase c;
    Gpu& device = c.gpu;
    const glm::vec4 value(0.25f, 0.5f, 0.75f, 1.0f);
    const MipChain chain = constant_chain(61, 47, value);
    std::vector<Lookup> lookups = random_lookups(1024, 11, 61);
    for (Wrap wrap : {Wrap::repeat, Wrap::clamp, Wrap::mirror})
        for (Taps taps : {Taps::manual, Taps::hardware}) {
            const SamplerOptions o = ewa_options(wrap, taps);
            const std::vector<glm::dvec4> expected(lookups.size(), glm::dvec4(value));
            CHECK_LE("constant 61x47 => constant, reference (" + describe(wrap, taps) + ")",
                     max_error(reference(chain, lookups, o), expected), 1e-14);
            std::vector<LookupStats> stats;
            const auto gpu = device.sample(chain, lookups, o, &stats);
            double worst = 0, worst_ratio = 0;
            for (size_t i = 0; i < gpu.size(); ++i) {
                const double n = stats[i].texel_fetches + stats[i].hardware_lookups;
                const double err = finite(gpu[i]) ? max_abs(gpu[i] - glm::dvec4(value)) : INFINITY;
                worst = std::max(worst, err);
                worst_ratio = std::max(worst_ratio, err / ((2 * n + 4) * kUlp * 1.0));
            }
            std::printf("     constant GPU (%s): max error %.3g\n", describe(wrap, taps).c_str(), worst);
            CHECK_LE("constant 61x47 => constant, GPU, error / ((2n+4) ulp) (" + describe(wrap, taps) + ")",
                     worst_ratio, 1.0);
        }
}

// Per-level normalisation and the level blend: on mipcolors every level is one flat colour, so EWA must
// return mix(colour[lo], colour[lo+1], frac(lambda)) — the GPU must agree with the reference's lambda.
// Adjacent colours differ by up to 1, so an error e in lambda shows as e: lambda ~ log2(texels) < 16 is
// float, a few ulp of 16 (1.9e-6 each) apart from the double one.
TEST_CASE("mipcolors")
{
    GpuCase c;
    Gpu& device = c.gpu;
    const MipChain chain = make_procedural("mipcolors", 256);
    const std::vector<Lookup> lookups = random_lookups(2048, 12);
    for (Taps taps : {Taps::manual, Taps::hardware}) {
        const SamplerOptions o = ewa_options(Wrap::repeat, taps);
        CHECK_LE("mipcolors: GPU vs reference, level blend (" + to_string(taps) + ")",
                 max_error(device.sample(chain, lookups, o), reference(chain, lookups, o)), 4 * 1.9e-6);
    }
}

// Isotropic footprints on a smooth texture: EWA ≈ trilinear, both tap forms. Both read the same two
// levels with the same blend weight (an isotropic footprint gets trilinear's lambda), and per level all
// three estimators reproduce a linear function exactly (bilinear; EWA's line fit or shifted taps,
// the ramp case), so they differ only through the texture's curvature: by at most half the difference of
// their kernels' per-axis second moments times |t_xx| + |t_yy|. EWA's is <= 0.2097·(σ² + 1) <= 1.05
// texel² on the finer level (σ < 2 texels there; 0.2097 is the per-axis variance, in units of M, of
// exp(-2 r²) - exp(-2 R²) on r² < R² = 2), bilinear's is in [0, ¼]; hardware taps add the sampler's
// rounding (as check_gpu_vs_reference). The Hessian on level l is the level-0 wave bound times 4^l; the
// bound of a lookup uses the coarser level it reads. (Before the fit, the discrete weights' centroid,
// up to ½ texel off uv, added gradient·½·2^l: the bias the fit removes.)
TEST_CASE("isotropic-vs-trilinear")
{
    GpuCase c;
    Gpu& device = c.gpu;
    const int bits = c.bits;
    const int size = 256;
    const MipChain chain = wave_chain(size, kSmoothWaves);
    const double lo = -3.0, hi = 2.0;
    const std::vector<Lookup> lookups = isotropic_lookups(2048, 13, lo, hi);
    double gradient = 0, hessian = 0;
    for (const Wave& w : kSmoothWaves) {
        const double k = 2 * std::numbers::pi * std::hypot(w.kx, w.ky) / size;
        gradient += w.amplitude * k;
        hessian += 2 * w.amplitude * k * k;
    }
    SamplerOptions tri;
    tri.filter = Filter::trilinear;
    tri.wrap = Wrap::repeat;
    const auto ref_tri = reference(chain, lookups, tri);
    const auto gpu_tri = device.sample(chain, lookups, tri);
    for (Taps taps : {Taps::manual, Taps::hardware}) {
        const SamplerOptions ewa = ewa_options(Wrap::repeat, taps);
        const auto ref_ewa = reference(chain, lookups, ewa), gpu_ewa = device.sample(chain, lookups, ewa);
        for (bool gpu : {false, true}) {
            const auto& e = gpu ? gpu_ewa : ref_ewa;
            const auto& t = gpu ? gpu_tri : ref_tri;
            double worst_ratio = 0, sum2 = 0, bound2 = 0;
            for (size_t i = 0; i < lookups.size(); ++i) {
                const double lambda = std::max(0.0, reference_lod(chain, lookups[i], tri));
                const double scale = std::exp2(std::ceil(lambda)); // the coarser level read
                // gradient·scale bounds one adjacent-texel difference on that level (the sampler term).
                const double sampler = gpu && taps == Taps::hardware
                                           ? (std::exp2(-bits) * 3 + 2 * std::exp2(-14)) * gradient * scale
                                           : 0.0;
                const double bound = 0.5 * 1.05 * hessian * scale * scale + sampler + 1e-6;
                const double err = max_abs(e[i] - t[i]);
                worst_ratio = std::max(worst_ratio, err / bound);
                sum2 += err * err;
                bound2 += bound * bound;
            }
            const std::string who = std::string(gpu ? "GPU" : "reference") + ", " + to_string(taps);
            CHECK_LE("isotropic smooth texture: RMS |ewa - trilinear|, " + who, std::sqrt(sum2 / lookups.size()),
                     std::sqrt(bound2 / lookups.size()));
            CHECK_LE("isotropic smooth texture: worst |ewa - trilinear| / its bound, " + who, worst_ratio, 1.0);
        }
    }
}

// A Gaussian that is too wide (small alpha) blurs, measured: standard deviation of lookups over the
// zoneplate's band of 0.2..0.45 cycles/texel, one lookup per texel, footprint 2 x 1 texels (trilinear's
// λ = 1, where the ellipse alone filters: below it the magnification filter takes level 0's share) on
// level 0: M = diag(5, 2). Along v the per-axis variances are 0.1717·2 (alpha 2) and 0.2396·2 texel²
// (alpha 0.25, nearly a flat disc); a Gaussian of those attenuates a wave of f cycles/texel by
// exp(-2π²·var·f²), a ratio of 1.11 at f = 0.2 to 1.72 at 0.45, and more along u (variances 5/2 as large).
// Asserted: at least 1.3 over the band.
TEST_CASE("alpha-blurs")
{
    GpuCase c;
    Gpu& device = c.gpu;
    const int size = 256;
    const MipChain chain = make_procedural("zoneplate", size);
    std::vector<Lookup> lookups;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double r = std::hypot(x + 0.5 - size / 2.0, y + 0.5 - size / 2.0);
            if (r >= 0.2 * size && r <= 0.45 * size)
                lookups.push_back(as_float({(x + 0.5) / size, (y + 0.5) / size, 2.0 / size, 0, 0, 1.0 / size}));
        }
    auto stddev = [](const std::vector<glm::dvec4>& c) {
        double s = 0, s2 = 0;
        for (const auto& v : c) s += v.r, s2 += v.r * v.r;
        const double n = double(c.size());
        return std::sqrt(std::max(0.0, s2 / n - (s / n) * (s / n)));
    };
    for (bool gpu : {false, true}) {
        const SamplerOptions sharp_o = ewa_options(Wrap::repeat, Taps::manual, 2.0f);
        const SamplerOptions wide_o = ewa_options(Wrap::repeat, Taps::manual, 0.25f);
        const auto sharp = gpu ? device.sample(chain, lookups, sharp_o) : reference(chain, lookups, sharp_o);
        const auto wide = gpu ? device.sample(chain, lookups, wide_o) : reference(chain, lookups, wide_o);
        std::printf("     zoneplate std dev over the band: alpha 2 %.4f, alpha 0.25 %.4f\n", stddev(sharp), stddev(wide));
        CHECK_GE(std::string("alpha 0.25 blurs: contrast ratio alpha 2 / alpha 0.25, ") + (gpu ? "GPU" : "reference"),
                 stddev(sharp) / stddev(wide), 1.3);
    }
}

// GPU vs reference on random footprints, each texture and option set with manual and hardware taps.
void gpu_vs_reference(const std::string& texture, Wrap wrap, Taps taps, float alpha = 2.0f)
{
    GpuCase c;
    const std::string name = to_string(taps);
    check_gpu_vs_reference(c.gpu, texture, ewa_options(wrap, taps, alpha), alpha == 2.0f ? name : name + ", alpha 8", c.bits);
}

// Bias, LOD clamp (the loop cap shrinks footprints past level 3), eccentricity clamp 4.
void gpu_vs_reference_clamps(Taps taps)
{
    GpuCase c;
    SamplerOptions o = ewa_options(Wrap::repeat, taps, 0.5f, 4.0f);
    o.lod_bias = -0.5f;
    o.lod_max = 3.0f;
    check_gpu_vs_reference(c.gpu, "grid", o, to_string(taps) + ", alpha 0.5, max-aniso 4, bias -0.5, lod-max 3", c.bits);
}

TEST_CASE("gpu-vs-reference-noise-manual") { gpu_vs_reference("noise", Wrap::repeat, Taps::manual); }
TEST_CASE("gpu-vs-reference-checker-manual") { gpu_vs_reference("checker", Wrap::clamp, Taps::manual); }
TEST_CASE("gpu-vs-reference-zoneplate-manual") { gpu_vs_reference("zoneplate", Wrap::mirror, Taps::manual); }
TEST_CASE("gpu-vs-reference-noise-alpha-8-manual") { gpu_vs_reference("noise", Wrap::repeat, Taps::manual, 8.0f); }
TEST_CASE("gpu-vs-reference-grid-clamps-manual") { gpu_vs_reference_clamps(Taps::manual); }
TEST_CASE("gpu-vs-reference-noise-hardware") { gpu_vs_reference("noise", Wrap::repeat, Taps::hardware); }
TEST_CASE("gpu-vs-reference-checker-hardware") { gpu_vs_reference("checker", Wrap::clamp, Taps::hardware); }
TEST_CASE("gpu-vs-reference-zoneplate-hardware") { gpu_vs_reference("zoneplate", Wrap::mirror, Taps::hardware); }
TEST_CASE("gpu-vs-reference-noise-alpha-8-hardware") { gpu_vs_reference("noise", Wrap::repeat, Taps::hardware, 8.0f); }
TEST_CASE("gpu-vs-reference-grid-clamps-hardware") { gpu_vs_reference_clamps(Taps::hardware); }

// Reported, not asserted beyond what report_hw_vs_manual checks.
TEST_CASE("hw-vs-manual-noise") { GpuCase c; report_hw_vs_manual(c.gpu, "noise", make_procedural("noise", 256), Wrap::repeat); }
TEST_CASE("hw-vs-manual-checker") { GpuCase c; report_hw_vs_manual(c.gpu, "checker", make_procedural("checker", 256), Wrap::clamp); }
TEST_CASE("hw-vs-manual-zoneplate")
{
    GpuCase c;
    report_hw_vs_manual(c.gpu, "zoneplate", make_procedural("zoneplate", 256), Wrap::mirror);
}

TEST_CASE("twisted-blocks-checker") { GpuCase c; check_twisted_blocks(c.gpu, "checker", 512, 64.0, 256.0, Wrap::repeat); }
TEST_CASE("twisted-blocks-zoneplate") { GpuCase c; check_twisted_blocks(c.gpu, "zoneplate", 256, 2.0, 8.0, Wrap::repeat); }
// The line fit can overshoot a step edge (the fitted gradient times the samples' centroid offset); each
// level's result is clamped to the range of the texels it read. On a 0/1 checker of 2-texel squares at
// alpha 8 (narrow weights, so the few texels near uv dominate and their centroid is off uv), small and
// anisotropic footprints at any angle and shear: unclamped, 2405 of 20000 lookups left [0, 1], down to
// -0.021 and up to 1.018 (both backends). With the clamp every result is in [0, 1]: the reference
// exactly, the GPU within float rounding of the blend (2 ulp). Hardware taps are a positive-weighted
// mean of bilinear taps: inside [0, 1] by construction, checked too.
TEST_CASE("overshoot")
{
    GpuCase c;
    Gpu& device = c.gpu;
    const int size = 256;
    Image img = make_image(size, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) img.at(x, y) = glm::vec4(float(((x / 2) + (y / 2)) % 2), 0.0f, 0.0f, 1.0f);
    const MipChain chain = build_mip_chain(img);
    std::mt19937 rng(61);
    std::uniform_real_distribution<double> uv(0.1, 0.9), angle(0.0, 2 * std::numbers::pi), octaves(-4.0, 4.0),
        stretch(0.0, 5.0), shear(-0.7, 0.7);
    std::vector<Lookup> lookups;
    for (int i = 0; i < 20000; ++i) {
        const double major = std::exp2(octaves(rng)) / size, a = angle(rng), minor = major / std::exp2(stretch(rng));
        const double b = a + std::numbers::pi / 2 + shear(rng);
        lookups.push_back(as_float({uv(rng), uv(rng), major * std::cos(a), major * std::sin(a), minor * std::cos(b),
                                    minor * std::sin(b)}));
    }
    for (Taps taps : {Taps::manual, Taps::hardware})
        for (bool gpu : {false, true}) {
            const SamplerOptions o = ewa_options(Wrap::repeat, taps, 8.0f);
            const auto out = gpu ? device.sample(chain, lookups, o) : reference(chain, lookups, o);
            double lo = INFINITY, hi = -INFINITY;
            for (const auto& c : out) lo = std::min(lo, c.r), hi = std::max(hi, c.r);
            const std::string who = std::string(gpu ? "GPU" : "reference") + ", " + to_string(taps);
            std::printf("     2-texel checker, alpha 8 (%s): results in [%.9g, %.9g]\n", who.c_str(), lo, hi);
            const double slack = gpu ? 2 * kUlp : 0.0;
            CHECK_LE("overshoot: distance below 0 (" + who + ")", std::max(0.0, -lo), slack);
            CHECK_LE("overshoot: distance above 1 (" + who + ")", std::max(0.0, hi - 1.0), slack);
        }
}

// Texel fetches and hardware lookups per lookup (the shader's TF_COUNT_* hooks): manual never more
// than K² per level; hardware about a quarter of manual's fetches, as lookups.
TEST_CASE("counts")
{
    GpuCase c;
    Gpu& device = c.gpu;
    const MipChain chain = make_procedural("noise", 256);
    struct Case {
        const char* name;
        std::vector<Lookup> lookups;
    };
    std::vector<Case> cases = {{"random footprints", random_lookups(2048, 41)},
                               {"isotropic 1..64 texels", isotropic_lookups(1024, 42, 0.0, 6.0)}};
    // Anisotropic 16:1 with a minor axis of 1..4 texels: the ellipses EWA is for.
    std::vector<Lookup> aniso;
    std::mt19937 rng(43);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 1024; ++i) {
        const double minor = std::exp2(2 * unit(rng)) / 256, major = 16 * minor, a = 2 * std::numbers::pi * unit(rng);
        aniso.push_back(as_float({unit(rng), unit(rng), major * std::cos(a), major * std::sin(a), -minor * std::sin(a),
                                  minor * std::cos(a)}));
    }
    cases.push_back({"anisotropic 16:1", aniso});
    for (const Case& c : cases) {
        std::vector<LookupStats> manual, hw;
        device.sample(chain, c.lookups, ewa_options(Wrap::repeat, Taps::manual), &manual);
        device.sample(chain, c.lookups, ewa_options(Wrap::repeat, Taps::hardware), &hw);
        double fetches = 0, lookups = 0;
        uint32_t most = 0, most_hw = 0;
        for (size_t i = 0; i < manual.size(); ++i) {
            fetches += manual[i].texel_fetches;
            lookups += hw[i].hardware_lookups;
            most = std::max(most, manual[i].texel_fetches + manual[i].hardware_lookups);
            most_hw = std::max(most_hw, hw[i].hardware_lookups + hw[i].texel_fetches);
        }
        fetches /= double(manual.size()), lookups /= double(hw.size());
        std::printf("     %s: manual %.1f texel fetches a lookup (max %u), hardware %.1f lookups (max %u)\n", c.name,
                    fetches, most, lookups, most_hw);
        CHECK_LE(std::string("fetches: most manual fetches in one lookup <= 2K² (") + c.name + ")", most,
                 2.0 * kMaxTexels * kMaxTexels);
        CHECK_LE(std::string("fetches: hardware lookups / manual fetches (") + c.name + ")", lookups / fetches,
                 std::string(c.name).starts_with("isotropic") ? 0.6 : 0.5);
    }
}

// Through the CLI (flags --taps, --alpha, --max-aniso, --lod-max end to end): NaN, ±Inf, 0, 1e30,
// -1e30, 1e-38, one gradient huge and the other zero, huge uv, NaN uv. Every command returns; every
// result is finite. Documented results: NaN/±Inf gradients -> the last level with M = I, which for a
// square power-of-two texture is its 1x1 mean; 1e30 -> the same level; 0 -> level 0, M = I (as the
// reference); NaN uv -> 0. With --lod-max 0 a 1e30 footprint stays on level 0, shrunk to the loop cap.
TEST_CASE("non-finite")
{
    const std::string texture = "checker";
    const MipChain chain = make_procedural(texture, 256);
    const glm::dvec4 mean(chain.levels.back().at(0, 0));
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = INFINITY;
    struct Row {
        const char* what;
        Lookup l;
        bool expect_mean, expect_zero;
    };
    const double t = 1.0 / 256;
    const std::vector<Row> rows = {
        {"NaN gradients", {0.3, 0.6, nan, nan, nan, nan}, true, false},
        {"one NaN component", {0.3, 0.6, t, 0, 0, nan}, true, false},
        {"+Inf gradients", {0.3, 0.6, inf, 0, 0, inf}, true, false},
        {"-Inf gradients", {0.3, 0.6, -inf, -inf, -inf, -inf}, true, false},
        {"Inf and NaN", {0.3, 0.6, inf, nan, -inf, 0}, true, false},
        {"zero gradients", {0.3, 0.6, 0, 0, 0, 0}, false, false},
        {"1e30 gradients", {0.3, 0.6, 1e30, 0, 0, 1e30}, true, false},
        {"-1e30 gradients, slanted", {0.3, 0.6, -1e30, 1e30, 1e30, 1e30}, true, false},
        {"1e30 and 0 (degenerate)", {0.3, 0.6, 1e30, 1e30, 0, 0}, true, false},
        {"3e38 gradients (float max)", {0.3, 0.6, 3e38, -3e38, 3e38, 3e38}, true, false},
        {"1e-38 gradients (denormal)", {0.3, 0.6, 1e-38, 0, 0, 1e-38}, false, false},
        {"1 texel x 1e30 (extreme aniso)", {0.3, 0.6, t, 0, 0, 1e30}, false, false},
        {"uv 1e30, gradients 1 texel", {1e30, -1e30, t, 0, 0, t}, false, false},
        {"uv NaN", {nan, 0.5, t, 0, 0, t}, false, true},
        {"uv Inf", {inf, 0.5, t, 0, 0, t}, false, true},
    };
    const std::string in = (test::work_dir() / "nonfinite.csv").string();
    std::vector<Lookup> lookups;
    for (const Row& r : rows) lookups.push_back(r.l);
    test::write_lookups_csv(in, lookups, false); // as they are: the GPU rounds them, the reference does not
    struct Run {
        std::string flags;
        SamplerOptions options;
    };
    std::vector<Run> runs;
    for (Taps taps : {Taps::manual, Taps::hardware}) {
        SamplerOptions o = ewa_options(Wrap::repeat, taps, 0.5f, 64.0f);
        runs.push_back({"--taps " + to_string(taps) + " --alpha 0.5 --max-aniso 64", o});
        SamplerOptions c = ewa_options(Wrap::clamp, taps);
        c.lod_max = 0.0f;
        runs.push_back({"--taps " + to_string(taps) + " --wrap clamp --lod-max 0", c});
    }
    for (const Run& run : runs) {
        const std::string args = "--texture " + texture + " --filter ewa " + run.flags;
        test::SampleResult gpu_run, ref_run;
        const bool ok_gpu = run_cli(args, in, true, gpu_run);
        const bool ok_ref = run_cli(args + " --backend reference", in, false, ref_run);
        CHECK_TRUE("non-finite/huge: `sample --validate " + run.flags + "` returns", ok_gpu && ok_ref,
                   ok_gpu && ok_ref ? "exit 0 (GPU and reference)" : "command failed");
        if (!ok_gpu || !ok_ref) continue;
        const auto& gpu = gpu_run.colors;
        const auto& ref = ref_run.colors;
        const auto& stats = gpu_run.stats;
        if (gpu.size() != rows.size() || ref.size() != rows.size() || stats.size() != rows.size()) {
            CHECK_TRUE("non-finite/huge: one result per lookup", false, "wrong row count");
            continue;
        }
        double worst_ref = 0, worst_doc = 0;
        uint32_t most = 0;
        bool all_finite = true;
        for (size_t i = 0; i < rows.size(); ++i) {
            all_finite = all_finite && finite(gpu[i]) && finite(ref[i]);
            worst_ref = std::max(worst_ref, max_abs(gpu[i] - ref[i]));
            const bool mean_expected = rows[i].expect_mean && run.options.lod_max > 0;
            if (mean_expected) worst_doc = std::max({worst_doc, max_abs(gpu[i] - mean), max_abs(ref[i] - mean)});
            if (rows[i].expect_zero) worst_doc = std::max({worst_doc, max_abs(gpu[i]), max_abs(ref[i])});
            most = std::max(most, stats[i].texel_fetches + stats[i].hardware_lookups);
            if (!(max_abs(gpu[i] - ref[i]) <= 1e-5))
                std::printf("     %s: GPU (%g %g %g %g) reference (%g %g %g %g)\n", rows[i].what, gpu[i].r, gpu[i].g,
                            gpu[i].b, gpu[i].a, ref[i].r, ref[i].g, ref[i].b, ref[i].a);
        }
        CHECK_TRUE("non-finite/huge: all results finite (" + run.flags + ")", all_finite, all_finite ? "yes" : "no");
        // The special results are flat colours or one level's Gaussian on a checker: float-exact up to the
        // 8-digit CSV (5e-9) and a hardware tap's coordinate rounding.
        CHECK_LE("non-finite/huge: max |GPU - reference| (" + run.flags + ")", worst_ref, 1e-5);
        CHECK_LE("non-finite/huge: max |result - documented value| (" + run.flags + ")", worst_doc, 1e-6);
        CHECK_LE("non-finite/huge: most fetches + lookups in one lookup <= 2K² (" + run.flags + ")", most,
                 2.0 * kMaxTexels * kMaxTexels);
    }
}
TEST_SUITE_END();

TEST_SUITE_BEGIN("gpu slow");
// docs/API.md's degenerate-input table, end to end through `texfilter sample` on both
// backends, for every family: a 64² checker (the smallest power of two where every huge u below, 1e37 up,
// overflows the texel coordinate u·size in float: 1e37·64 > 3.4e38; 512² gave the same rows at 8x the cost
// a launch), wraps repeat and clamp. Per family and wrap, every result must be finite, the GPU within the
// family's tolerance of the reference, and each row equal to what the table says:
// - gradients 1e-30 give what zero gradients give (the finest level);
// - gradients 1e30, 1e100, 1e154, 1e300, ±Inf, NaN give the coarsest level: for every mip family and
//   (NaN/±Inf/past float range, and any huge box with repeat) sat, the 1x1 level's mean; nearest and
//   bilinear ignore gradients (the zero-gradient result);
// - uv 1e37, 1e38, 3e38, -3e38 (finite floats: even integers) give what uv reduced by the wrap gives:
//   u = 0 for repeat, u = 2 or -1 for clamp (the same texels, whatever uv·size would be);
// - an 8:1 footprint at u = 1000000.3125 gives what it gives at u = 0.3125 (repeat) or 2 (clamp), and a huge
//   footprint at u = 3.4e38 the 1x1 level's mean (mip families; sat with repeat);
// - uv 1e100 (past float range: +Inf to the GPU), ±Inf, NaN give (0, 0, 0, 0).
// Tolerances: 1e-5 (float vs double on footprints of a texel or flat results); hardware-tap forms add
// the sampler's weight rounding 3·2^-bits (contrast 1, as test_hw_vs_manual); sat its 16-bit
// quantisation 0.5/65535.
TEST_CASE("degenerate-all-families")
{
    const int bits = command_case();
    const int size = 64;
    const MipChain chain = make_procedural("checker", size);
    const glm::dvec4 mean(chain.levels.back().at(0, 0));
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = INFINITY, t = 1.0 / size;
    std::vector<Lookup> lookups;
    const std::vector<double> grads = {0, 1e-30, 1e30, 1e100, 1e154, 1e300, inf, -inf, nan};
    for (double g : grads) lookups.push_back({0.3, 0.6, g, 0, 0, g}); // rows 0..8
    const size_t first_uv = lookups.size();
    const std::vector<double> huge = {1e37, 1e38, 3e38, -3e38}, gone = {1e100, inf, -inf, nan};
    for (double u : huge) lookups.push_back({u, 0.6, t, 0, 0, t});
    bool all_overflow = true; // the premise above: u·size is past float range for each huge u
    for (double u : huge) all_overflow = all_overflow && std::isinf(float(u) * float(size));
    CHECK_TRUE("degenerate input: every huge u overflows u·" + std::to_string(size) + " in float", all_overflow,
               all_overflow ? "yes" : "no");
    const size_t first_gone = lookups.size();
    for (double u : gone) lookups.push_back({u, 0.6, t, 0, 0, t});
    for (double u : gone) lookups.push_back({0.3, u, t, 0, 0, t}); // v too
    const size_t reduced = lookups.size(); // u = 0, 2, -1 (what the huge uv reduce to)
    for (double u : {0.0, 2.0, -1.0}) lookups.push_back({u, 0.6, t, 0, 0, t});
    // A long footprint (8:1) at a large uv (an exact float) gives what it gives at the reduced uv: aniso's
    // probe offsets were once added to the large uv and lost to its rounding (to 1/16 at 1e6).
    const size_t long_far = lookups.size();
    lookups.push_back({1000000.3125, 0.6, 8 * t, 0, 0, t});
    lookups.push_back({0.3125, 0.6, 8 * t, 0, 0, t}); // repeat's reduction
    lookups.push_back({2.0, 0.6, 8 * t, 0, 0, t}); // clamp's: past the edge, as 1000000.3125 is
    // A huge footprint near float's range: the coarsest level's mean; aniso's probes once overflowed to
    // ±Inf there and counted as (0, 0, 0, 0).
    const size_t near_max = lookups.size();
    lookups.push_back({3.4e38, 0.5, 1.3e36, 0, 0, 1e34});
    const std::string in = (test::work_dir() / "degenerate.csv").string();
    test::write_lookups_csv(in, lookups, false, 17); // 1000000.3125 has 11 digits
    struct Family {
        std::string flags;
        bool mip, hardware, sat;
    };
    const std::vector<Family> families = {
        {"--filter nearest", false, false, false},
        {"--filter bilinear", false, false, false},
        {"--filter nearest-mip", true, false, false},
        {"--filter bilinear-mip", true, false, false},
        {"--filter trilinear", true, false, false},
        {"--filter brilinear", true, false, false},
        {"--filter aniso --aniso-shape gpu --taps manual", true, false, false},
        {"--filter aniso --aniso-shape gpu --taps hardware", true, true, false},
        {"--filter aniso --aniso-shape feline --taps manual", true, false, false},
        {"--filter aniso --aniso-shape feline --taps hardware", true, true, false},
        {"--filter ewa --taps manual", true, false, false},
        {"--filter ewa --taps hardware", true, true, false},
        {"--filter sat", false, false, true},
        {"--filter sat-assembly", false, false, true},
    };
    for (const std::string wrap : {"repeat", "clamp"})
        for (const Family& f : families) {
            const std::string args =
                "--texture checker --texture-size " + std::to_string(size) + " --wrap " + wrap + " " + f.flags;
            test::SampleResult gpu_run, ref_run;
            const bool ok = run_cli(args, in, false, gpu_run) && run_cli(args + " --backend reference", in, false, ref_run);
            const std::string what = "degenerate input (" + f.flags.substr(9) + ", " + wrap + ")";
            if (!ok || gpu_run.colors.size() != lookups.size() || ref_run.colors.size() != lookups.size()) {
                CHECK_TRUE(what + ": `sample` runs", false, "command failed or wrong row count");
                continue;
            }
            const double tol = 1e-5 + (f.hardware ? 3 * std::exp2(-bits) : 0.0) + (f.sat ? 0.5 / 65535 : 0.0);
            double worst_backends = 0, worst_table = 0;
            bool all_finite = true;
            std::string worst_row;
            for (bool gpu : {false, true}) {
                const auto& c = gpu ? gpu_run.colors : ref_run.colors;
                auto expect = [&](size_t row, const glm::dvec4& want) {
                    const double e = finite(c[row]) ? max_abs(c[row] - want) : INFINITY;
                    if (e > worst_table) worst_table = e, worst_row = (gpu ? "GPU row " : "reference row ") + std::to_string(row);
                };
                expect(1, c[0]);
                for (size_t row = 2; row < grads.size(); ++row) {
                    const bool huge_box = row == 2 && f.sat && wrap == "clamp"; // 1e30 is a finite float: box W x H
                    if (f.mip || (f.sat && !huge_box)) expect(row, mean);
                    else if (!f.sat) expect(row, c[0]);
                }
                for (size_t k = 0; k < huge.size(); ++k)
                    expect(first_uv + k, c[reduced + (wrap == "repeat" ? 0 : huge[k] > 0 ? 1 : 2)]);
                for (size_t row = first_gone; row < reduced; ++row) expect(row, glm::dvec4(0.0));
                expect(long_far, c[long_far + (wrap == "repeat" ? 1 : 2)]);
                if (f.mip || (f.sat && wrap == "repeat")) expect(near_max, mean); // sat clamp: a box W x H at u = 2
            }
            for (size_t row = 0; row < lookups.size(); ++row) {
                all_finite = all_finite && finite(gpu_run.colors[row]) && finite(ref_run.colors[row]);
                worst_backends = std::max(worst_backends, max_abs(gpu_run.colors[row] - ref_run.colors[row]));
            }
            CHECK_TRUE(what + ": all results finite", all_finite, all_finite ? "yes" : "no");
            CHECK_LE(what + ": max |GPU - reference|", worst_backends, tol);
            CHECK_LE(what + ": max |result - table| " + worst_row, worst_table, tol);
        }
}
TEST_SUITE_END();
