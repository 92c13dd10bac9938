#include "reference/ground_truth.h"
#include "core/analytic_texture.h"
#include "texture/error.h"
#include "core/hash.h"
#include "texture/threads.h"
#include "reference/reference.h"
#include <atomic>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <unistd.h>

namespace tf {

namespace {

const double two_pi = 6.283185307179586;

// 24 hash bits as a float in [0, 1): exact in float and double, so both backends jitter identically.
double unit(uint32_t h) { return double(h >> 8) * (1.0 / 16777216.0); }

// A 40-character bar redrawn as rows finish; silent when stderr is not a terminal (logs, CI).
struct ProgressBar {
    size_t total;
    bool shown = isatty(2) != 0;
    std::atomic<size_t> done{0};
    std::mutex mutex;
    int drawn = -1;

    void step()
    {
        size_t now = ++done;
        if (!shown)
            return;
        int percent = int(100 * now / total);
        std::lock_guard<std::mutex> lock(mutex);
        if (percent == drawn)
            return;
        drawn = percent;
        int filled = percent * 40 / 100;
        std::fprintf(stderr, "\rground truth [%-40.*s] %3d%%", filled, "########################################", percent);
        if (now == total)
            std::fputc('\n', stderr);
        std::fflush(stderr);
    }
};

} // namespace

glm::dvec2 ground_truth_sample(int x, int y, int i, int side, PixelFilter filter)
{
    uint32_t h = mix32(uint32_t(i) + mix32(uint32_t(y) + mix32(uint32_t(x))));
    double a = (double(i % side) + unit(h)) / side;
    double b = (double(i / side) + unit(mix32(h))) / side;
    if (filter == PixelFilter::box)
        return {x + a, y + b};
    // 1 - a is in (0, 1]: the log is finite, and the radius at most sigma * sqrt(2 ln(side * 2^24)) (~3.3 px).
    double r = ground_truth_sigma * std::sqrt(-2.0 * std::log(1.0 - a));
    return {x + 0.5 + r * std::cos(two_pi * b), y + 0.5 + r * std::sin(two_pi * b)};
}

Image reference_ground_truth(const SceneParams& scene, const MipChain& chain, const SamplerOptions& options)
{
    // The sample range, checked (a range past the grid is refused, naming it) as the GPU host checks it.
    const TruthRange range = truth_range(options);
    const int width = scene.kind_size.y, height = scene.kind_size.z, side = options.truth_side;
    const int first = range.first, end = range.first + range.count;
    const Image& base = chain.levels.at(0);
    const glm::dvec4 background(scene.background);
    // --truth analytic: the procedural texture's function at level 0's size instead of its bilinear texels.
    check_analytic_truth(options);
    const bool analytic = options.truth == Truth::analytic;
    const AnalyticTexture function{options.analytic, base.width};
    Image out = make_image(width, height);
    ProgressBar progress{size_t(height)};
    parallel_for(size_t(height), [&](size_t row) {
        int y = int(row);
        for (int x = 0; x < width; ++x) {
            glm::dvec4 sum(0.0);
            for (int i = first; i < end; ++i) {
                glm::dvec2 p = ground_truth_sample(x, y, i, side, options.pixel_filter);
                PixelHit hit = reference_hit(scene, p.x, p.y);
                if (!hit.hit)
                    sum += background;
                else if (analytic)
                    sum += analytic_value(function, hit.uv, options.wrap);
                else
                    sum += reference_bilinear(base, hit.uv.x, hit.uv.y, options.wrap);
            }
            out.texels[row * size_t(width) + size_t(x)] = glm::vec4(sum / double(range.count));
        }
        progress.step();
    });
    return out;
}

} // namespace tf
