#include "reference_render.h"
#include <algorithm>
#include <atomic>
#include <thread>

namespace tf {

namespace {

// Runs body(i) for i in [0, count) on every core; exceptions from workers are rethrown here.
template <typename Body>
void parallel_for(size_t count, Body body)
{
    unsigned threads = std::max(1u, std::min(std::thread::hardware_concurrency(), 64u));
    std::atomic<size_t> next{0};
    std::exception_ptr failure;
    std::atomic<bool> failed{false};
    auto work = [&] {
        try {
            for (size_t i; !failed && (i = next.fetch_add(1)) < count;)
                body(i);
        } catch (...) {
            if (!failed.exchange(true))
                failure = std::current_exception();
        }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t)
        pool.emplace_back(work);
    work();
    for (std::thread& t : pool)
        t.join();
    if (failure)
        std::rethrow_exception(failure);
}

} // namespace

Image reference_render(const SceneParams& scene, const MipChain& chain, const SamplerOptions& options,
                       const RenderOptions& render)
{
    int width = scene.kind_size.y, height = scene.kind_size.z;
    // The stage does not change the math: compute quads are the fragment stage's quads.
    std::vector<PixelLookup> lookups = reference_lookups(scene, render.gradients, render.rasterize);
    Image out = make_image(width, height);
    parallel_for(size_t(height), [&](size_t y) {
        for (int x = 0; x < width; ++x) {
            size_t i = y * size_t(width) + size_t(x);
            out.texels[i] = lookups[i].hit ? glm::vec4(reference_sample(chain, options, lookups[i].lookup))
                                           : scene.background;
        }
    });
    return out;
}

std::vector<glm::dvec4> reference_sample_all(const MipChain& chain, const std::vector<Lookup>& lookups,
                                             const SamplerOptions& options)
{
    std::vector<glm::dvec4> out(lookups.size());
    const size_t chunk = 1024;
    parallel_for((lookups.size() + chunk - 1) / chunk, [&](size_t c) {
        for (size_t i = c * chunk; i < std::min(lookups.size(), (c + 1) * chunk); ++i)
            out[i] = reference_sample(chain, options, lookups[i]);
    });
    return out;
}

} // namespace tf
