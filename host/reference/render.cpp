#include "reference/render.h"
#include "reference/debug_view.h"
#include "reference/footprint.h"
#include "reference/ground_truth.h"
#include "reference/stochastic.h"
#include "texture/error.h"
#include "texture/threads.h"
#include <algorithm>
#include <optional>

namespace tf {

namespace {

// Once a batch, where the filter needs it (the sat filters quantise over the whole texture's range).
std::optional<SatLevels> sat_levels_for(const MipChain& chain, const SamplerOptions& options)
{
    if ((options.filter != Filter::sat && options.filter != Filter::sat_assembly) || chain.levels.empty())
        return std::nullopt;
    return reference_sat_levels(chain.levels[0]);
}

} // namespace

Image reference_render(const SceneParams& scene, const MipChain& chain, const SamplerOptions& options,
                       const RenderOptions& render)
{
    check_view(options.filter, render.view);
    check_reference_view(render.view);
    if (options.filter == Filter::ground_truth)
        return reference_ground_truth(scene, chain, options);
    if (options.stochastic && render.view == DebugView::color)
        return reference_render_stochastic(scene, chain, options, render);
    int width = scene.kind_size.y, height = scene.kind_size.z;
    // The stage does not change the math: compute quads are the fragment stage's quads.
    std::vector<PixelLookup> lookups = reference_lookups(scene, render.gradients, render.rasterize);
    const std::optional<SatLevels> sat = sat_levels_for(chain, options);
    Image out = make_image(width, height);
    parallel_for(size_t(height), [&](size_t y) {
        for (int x = 0; x < width; ++x) {
            size_t i = y * size_t(width) + size_t(x);
            if (!lookups[i].hit)
                out.texels[i] = scene.background;
            else if (render.view != DebugView::color)
                out.texels[i] = reference_view_pixel(render.view, lookup_footprint(chain, options, lookups[i].lookup));
            else
                out.texels[i] = glm::vec4(reference_sample(chain, options, lookups[i].lookup, sat ? &*sat : nullptr));
        }
    });
    return out;
}

std::vector<glm::dvec4> reference_sample_all(const MipChain& chain, const std::vector<Lookup>& lookups,
                                             const SamplerOptions& options, const std::vector<uint32_t>* rows)
{
    if (rows && rows->size() != lookups.size())
        throw Error("reference_sample_all: " + std::to_string(rows->size()) + " row indices for " +
                    std::to_string(lookups.size()) + " lookups");
    if (options.stochastic) // --stochastic: row i the mean of its frames, as gpu_sample's
        check_reference_stochastic(options);
    std::vector<glm::dvec4> out(lookups.size());
    const std::optional<SatLevels> sat = sat_levels_for(chain, options);
    const size_t chunk = 1024;
    parallel_for((lookups.size() + chunk - 1) / chunk, [&](size_t c) {
        for (size_t i = c * chunk; i < std::min(lookups.size(), (c + 1) * chunk); ++i)
            out[i] = options.stochastic ? reference_stochastic_mean(chain, options, lookups[i], 0, 0,
                                                                    rows ? (*rows)[i] : uint32_t(i))
                                        : reference_sample(chain, options, lookups[i], sat ? &*sat : nullptr);
    });
    return out;
}

} // namespace tf
