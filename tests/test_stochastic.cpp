// --stochastic (shaders/texfilter/stochastic.glsl, host/reference/stochastic.cpp): the one-texel estimator's
// expectation is the deterministic filter (bilinear, trilinear, aniso; ewa: the Gaussian-weighted mean, which a
// constant texture pins), and the mean of N frames converges to it at the rate its variance predicts, on the
// CPU reference and on the device, for white noise; blue noise no worse than white's prediction for N >= 4.
//
// The statistical bound: per pixel the error e of the mean of N frames has E[e²] = σ²/N. With texels in [0, 1]
// (|value − mean| <= 1, so E[(X−μ)⁴] <= σ²), E[e⁴] <= σ²/N³ + 3σ⁴/N²; pixels draw independent white numbers, so
// MSE = mean of e² over P pixels has mean Σσ²/(PN) and relative standard deviation at most
// sqrt(Σσ²/N + 3Σσ⁴)/Σσ². The checks allow 5 of those (plus the device's bias bound, squared).
#include "core/filter.h"
#include "core/procedural.h"
#include "reference/reference.h"
#include "reference/render.h"
#include "reference/stochastic.h"
#include "scene/scene.h"
#include "support.h"
#include "vulkan/backend.h"
#include "vulkan/device.h"
#include "vulkan/render.h"
#include "vulkan/textures.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace tf;

namespace {

constexpr int kSize = 64; // image and texture side
const int kFrames[] = {1, 4, 16, 64};

struct Family {
    const char* name;
    Filter filter;
    AnisoShape shape = AnisoShape::gpu;
    Taps taps = Taps::manual;
};
const Family kFamilies[] = {{"bilinear", Filter::bilinear},
                            {"trilinear", Filter::trilinear},
                            {"aniso", Filter::aniso},
                            {"aniso feline", Filter::aniso, AnisoShape::feline},
                            {"ewa", Filter::ewa}};

SamplerOptions options_for(const Family& f, Noise noise = Noise::white, int accumulate = 1) {
    SamplerOptions o;
    o.filter = f.filter;
    o.aniso_shape = f.shape;
    o.taps = f.taps;
    o.stochastic = true;
    o.noise = noise;
    o.accumulate = accumulate;
    return o;
}

// The slanted plane: minification and anisotropy vary over the image, so every family's choices matter, and no
// pixel is so far off that float's uv (the device's ray cast) reads other texels than double's: there the
// deterministic bilinear of the device and the reference agree to 2e-6 RMS (the plane's horizon: 0.013).
struct Setup {
    MipChain chain = make_procedural("noise", kSize);
    SceneParams scene = make_scene(SceneKind::slanted, kSize, kSize, kSize);
    RenderOptions render = make_render_options(SceneKind::slanted, Stage::fragment, Gradients::fine);
    std::vector<PixelLookup> lookups = reference_lookups(scene, render.gradients, render.rasterize);
};

// Per pixel (hit) its expectation and variance of channel r.
struct Expected {
    std::vector<double> mean, variance;
    std::vector<size_t> pixels;
    double sum_var = 0, sum_var2 = 0;
};
Expected expected(const Setup& s, const SamplerOptions& o) {
    Expected e;
    for (size_t i = 0; i < s.lookups.size(); ++i) {
        if (!s.lookups[i].hit) continue;
        const StochasticMoments m = reference_stochastic_moments(s.chain, o, s.lookups[i].lookup);
        e.pixels.push_back(i), e.mean.push_back(m.mean.r), e.variance.push_back(m.variance.r);
        e.sum_var += m.variance.r, e.sum_var2 += m.variance.r * m.variance.r;
    }
    return e;
}

double mse(const Image& image, const Expected& e) {
    double sum = 0;
    for (size_t k = 0; k < e.pixels.size(); ++k) {
        const double d = double(image.texels[e.pixels[k]].r) - e.mean[k];
        sum += d * d;
    }
    return sum / double(e.pixels.size());
}

// Relative standard deviation bound of the MSE for N frames (the file's header).
double relative_sd(const Expected& e, int n) { return std::sqrt(e.sum_var / n + 3.0 * e.sum_var2) / e.sum_var; }

// |observed / predicted − 1| within 5 standard deviations, with `bias2` (a per-pixel bias bound, squared) allowed.
void check_rate(const char* file, int line, const std::string& what, double observed, const Expected& e, int n,
                double bias2 = 0.0) {
    const double predicted = e.sum_var / double(e.pixels.size()) / n;
    const double sd = relative_sd(e, n) * predicted;
    std::printf("     %s: MSE %.4g, predicted σ²/N %.4g (RMS %.4g vs %.4g)\n", what.c_str(), observed, predicted,
                std::sqrt(observed), std::sqrt(predicted));
    test::check_bound(what + ": MSE above the prediction", observed - predicted - bias2, 5.0 * sd, true, file, line);
    test::check_bound(what + ": MSE below the prediction", predicted - observed, 5.0 * sd, true, file, line);
}

} // namespace

TEST_CASE("expectation") {
    // bilinear, trilinear, aniso: the estimator's mean is the deterministic reference, to rounding; the
    // probabilities sum to 1 (a constant texture gives its value with variance 0), ewa too.
    Setup s;
    for (const Family& f : kFamilies) {
        SamplerOptions o = options_for(f);
        SamplerOptions deterministic = o;
        deterministic.stochastic = false;
        double worst = 0, var = 0;
        for (const PixelLookup& p : s.lookups) {
            if (!p.hit) continue;
            const StochasticMoments m = reference_stochastic_moments(s.chain, o, p.lookup);
            var = std::max(var, test::max_channel_diff(m.variance, glm::dvec4(0.0)));
            if (f.filter != Filter::ewa)
                worst = std::max(worst, test::max_channel_diff(m.mean, reference_sample(s.chain, deterministic, p.lookup)));
        }
        if (f.filter != Filter::ewa) // ewa's expectation is the weighted mean, not its fit: the constant case below
            CHECK_LE(std::string(f.name) + ": |E[one texel] - deterministic filter|", worst, 1e-12);
        CHECK_LE(std::string(f.name) + ": some pixel has variance (the test can see noise)", -var, -1e-3);
        MipChain flat = make_procedural("noise", kSize);
        for (Image& level : flat.levels)
            for (glm::vec4& t : level.texels) t = glm::vec4(0.25f, 0.5f, 0.75f, 1.0f);
        double off = 0, flat_var = 0;
        for (const PixelLookup& p : s.lookups) {
            if (!p.hit) continue;
            const StochasticMoments m = reference_stochastic_moments(flat, o, p.lookup);
            off = std::max(off, test::max_channel_diff(m.mean, glm::dvec4(0.25, 0.5, 0.75, 1.0)));
            flat_var = std::max(flat_var, test::max_channel_diff(m.variance, glm::dvec4(0.0)));
        }
        CHECK_LE(std::string(f.name) + ": constant texture, |E - constant| (probabilities sum to 1)", off, 1e-12);
        CHECK_LE(std::string(f.name) + ": constant texture, variance", flat_var, 1e-12);
    }
}

TEST_CASE("reference-convergence") {
    Setup s;
    for (const Family& f : kFamilies) {
        const Expected e = expected(s, options_for(f));
        for (int n : kFrames) {
            const Image white = reference_render(s.scene, s.chain, options_for(f, Noise::white, n), s.render);
            const double white_mse = mse(white, e);
            check_rate(__FILE__, __LINE__, std::string(f.name) + " reference, white, N " + std::to_string(n), white_mse, e, n);
            if (n < 4) continue;
            const Image blue = reference_render(s.scene, s.chain, options_for(f, Noise::blue, n), s.render);
            const double predicted = e.sum_var / double(e.pixels.size()) / n;
            CHECK_LE(std::string(f.name) + " reference, blue MSE / white's prediction, N " + std::to_string(n),
                     mse(blue, e) / predicted, 1.0 + 5.0 * relative_sd(e, n));
        }
    }
}

TEST_CASE("gpu-convergence") {
    // The device's mean of N = 1, 4, 16 frames (prefixes of one 16-frame run: each prefix is a valid mean of its
    // own; blue: N = 4) against the reference's expectation; feline's probe choice is the reference's test; N = 64 is the reference's test (the device's frames cost ~10 ms
    // each on lavapipe). Manual forms: float vs double filtering is ~1e-6 (no bias term). Tap forms: the sampler
    // rounds each bilinear weight to subTexelPrecisionBits (trilinear's taps: on one level) and aniso's trilinear
    // taps also the level blend to mipmapPrecisionBits: a bias of at most 2·2^-sub (+ 2^-mip) a pixel.
    Setup s;
    constexpr int kDeviceFrames = 16;
    VulkanContext context = create_context(test::test_context_options());
    const double sub = std::ldexp(1.0, -int(context.info.sub_texel_precision_bits));
    const double mip = std::ldexp(1.0, -int(context.info.mipmap_precision_bits));
    {
        GpuTexture texture = upload_texture(context, s.chain, false);
        RenderPipelineCache cache; // one pipeline a filter: taps and shape are push constants
        std::vector<Family> families;
        for (const Family& f : kFamilies)
            if (f.shape == AnisoShape::gpu) families.push_back(f);
        families.push_back({"trilinear taps", Filter::trilinear, AnisoShape::gpu, Taps::hardware});
        families.push_back({"aniso taps", Filter::aniso, AnisoShape::gpu, Taps::hardware});
        for (const Family& f : families) {
            const Expected e = expected(s, options_for(f));
            const double bias = f.taps == Taps::manual ? 0.0 : f.filter == Filter::aniso ? 2.0 * sub + mip : 2.0 * sub;
            for (Noise noise : {Noise::white, Noise::blue}) {
                const SamplerOptions o = options_for(f, noise);
                const int frames = noise == Noise::white ? kDeviceFrames : 4; // blue: its check at N = 4
                auto renderer = create_renderer(context, texture, s.scene, o, s.render, &cache);
                std::vector<glm::dvec4> sum(s.lookups.size(), glm::dvec4(0.0));
                for (int frame = 0; frame < frames; ++frame) {
                    renderer->push.stochastic = stochastic_push(o, uint32_t(frame));
                    const Image image = render_frame(*renderer, s.scene);
                    for (size_t i = 0; i < sum.size(); ++i) sum[i] += glm::dvec4(image.texels[i]);
                    if (frame == 0 && noise == Noise::white && f.taps == Taps::manual && f.shape == AnisoShape::gpu) {
                        // The same numbers pick the same texel: a flip needs xi within float rounding of a weight
                        // boundary (or of frac(λ)), ~1e-6 of the pixels; 1 % is a generous cap. (Not feline: its
                        // axis is defined up to sign, and the device's and the reference's may differ, which mirrors
                        // the probes: the same distribution, other picks.)
                        const Image cpu = reference_render(s.scene, s.chain, options_for(f, Noise::white, 1), s.render);
                        size_t differ = 0;
                        for (size_t i : e.pixels) differ += std::abs(image.texels[i].r - cpu.texels[i].r) > 1e-5f ? 1 : 0;
                        CHECK_LE(std::string(f.name) + " device vs reference, frame 0: share of pixels that differ",
                                 double(differ) / double(e.pixels.size()), 0.01);
                    }
                    const int n = frame + 1;
                    if (n != 1 && n != 4 && n != 16) continue;
                    Image mean = image;
                    for (size_t i = 0; i < sum.size(); ++i) mean.texels[i] = glm::vec4(sum[i] / double(n));
                    const std::string what = std::string(f.name) + " device, " + to_string(noise) + ", N " + std::to_string(n);
                    if (noise == Noise::white) {
                        check_rate(__FILE__, __LINE__, what, mse(mean, e), e, n, bias * bias);
                    } else if (n >= 4) {
                        const double predicted = e.sum_var / double(e.pixels.size()) / n;
                        CHECK_LE(what + ": MSE / white's prediction", (mse(mean, e) - bias * bias) / predicted,
                                 1.0 + 5.0 * relative_sd(e, n));
                    }
                }
            }
        }
        destroy_texture(context, texture);
    }
    destroy_context(context);
    CHECK_LE("Vulkan validation messages (in-process)", double(validation_message_count()), 0.0);
}

TEST_CASE("sample-backends") {
    // texfilter sample --stochastic: lookup row i draws the numbers of pixel (0, 0), lookup i, frame f on both
    // backends, so the device and the reference pick the same texel except where xi lies within float rounding
    // of a weight boundary (~1e-6 of the rows; 1 % is the cap, as gpu-convergence's). With N frames a row's mean
    // is off only where one of its N picks flipped. The check can fail: a device that ignored the row index (every
    // row the same numbers) or the frame would agree on frame 0 and not on the mean, and one that read the
    // deterministic filter agrees with neither (it is asserted noisy below).
    MipChain chain = make_procedural("noise", kSize);
    std::vector<Lookup> lookups;
    uint32_t h = 12345u;
    auto unit = [&] { h = mix32(h); return double(h >> 8) / 16777216.0; };
    for (int i = 0; i < 2048; ++i) { // footprints from magnified to ~16 texels, anisotropy up to ~8
        const double u = unit() * 3.0 - 1.0, v = unit() * 3.0 - 1.0;
        const double size = std::exp2(unit() * 6.0 - 2.0) / kSize, angle = unit() * 6.283185307179586;
        const double ratio = 1.0 + 7.0 * unit();
        lookups.push_back({u, v, size * std::cos(angle), size * std::sin(angle),
                           -size / ratio * std::sin(angle), size / ratio * std::cos(angle)});
    }
    VulkanContext context = create_context(test::test_context_options());
    {
        GpuTexture texture = upload_texture(context, chain, false);
        for (const Family& f : kFamilies) {
            if (f.shape != AnisoShape::gpu) continue; // feline's axis sign may differ (gpu-convergence)
            SamplerOptions deterministic = options_for(f);
            deterministic.stochastic = false;
            const std::vector<glm::dvec4> exact = reference_sample_all(chain, lookups, deterministic);
            for (auto [noise, n] : {std::pair{Noise::white, 1}, std::pair{Noise::white, 8}, std::pair{Noise::blue, 8}}) {
                const SamplerOptions o = options_for(f, noise, n);
                const std::vector<glm::vec4> gpu = gpu_sample(context, texture, lookups, o, nullptr);
                const std::vector<glm::dvec4> cpu = reference_sample_all(chain, lookups, o);
                size_t differ = 0, noisy = 0;
                for (size_t i = 0; i < lookups.size(); ++i) {
                    differ += test::max_channel_diff(glm::dvec4(gpu[i]), cpu[i]) > 1e-5 ? 1 : 0;
                    noisy += test::max_channel_diff(cpu[i], exact[i]) > 1e-3 ? 1 : 0;
                }
                const std::string what = std::string(f.name) + ", " + to_string(noise) + ", N " + std::to_string(n);
                CHECK_LE(what + ": share of rows where device and reference differ", double(differ) / lookups.size(), 0.01);
                CHECK_LE(what + ": share of rows off the deterministic filter (noise is there)", -double(noisy) / lookups.size(), -0.25);
            }
        }
        destroy_texture(context, texture);
    }
    destroy_context(context);
    CHECK_LE("Vulkan validation messages (in-process)", double(validation_message_count()), 0.0);
}
