#include "bench/stochastic_bench.h"
#include "bench/metrics.h"
#include "vulkan/timing.h"
#include "vulkan/render.h"
#include <algorithm>
#include <cstdio>

namespace tf {

std::vector<StochasticRow> run_stochastic_rows(const VulkanContext& context, const GpuTexture& texture,
                                               const BenchConfig& config, SceneKind scene_kind,
                                               const SceneParams& scene, const Image& truth_box,
                                               const Image& truth_gaussian)
{
    const std::vector<int> checkpoints = {1, 4, 16, 64};
    const RenderOptions render = make_render_options(scene_kind, scene_kind == SceneKind::mesh ? Stage::fragment : config.stage,
                                                     Gradients::fine);
    std::vector<StochasticRow> rows;
    for (const BenchFilter& filter : config.filters) {
        if (filter.options.taps != Taps::manual || filter.options.magnify != Reconstruction::bilinear ||
            !takes_stochastic(filter.options.filter))
            continue;
        for (Noise noise : {Noise::white, Noise::blue}) {
            SamplerOptions options = filter.options;
            options.stochastic = true;
            options.noise = noise;
            auto renderer = create_renderer(context, texture, scene, options, render);
            renderer->push.stochastic = stochastic_push(options, 0);
            StochasticRow row;
            row.scene = scene_kind;
            row.label = filter.label;
            row.noise = noise;
            row.time = summarize_times(time_frames(*renderer, config.warmup, config.frames, config.timer));
            row.frames = checkpoints;
            // The running mean of frames 0, 1, ... (each its own numbers), scored at each checkpoint.
            std::vector<glm::dvec4> sum(size_t(renderer->width) * renderer->height, glm::dvec4(0.0));
            Image mean = make_image(int(renderer->width), int(renderer->height));
            for (int f = 0; f < checkpoints.back(); ++f) {
                renderer->push.stochastic = stochastic_push(options, uint32_t(f));
                const Image frame = render_frame(*renderer, scene);
                for (size_t i = 0; i < sum.size(); ++i)
                    sum[i] += glm::dvec4(frame.texels[i]);
                if (std::find(checkpoints.begin(), checkpoints.end(), f + 1) == checkpoints.end())
                    continue;
                for (size_t i = 0; i < sum.size(); ++i)
                    mean.texels[i] = glm::vec4(sum[i] / double(f + 1));
                row.rmse_box.push_back(display_rmse(mean, truth_box));
                row.rmse_gaussian.push_back(display_rmse(mean, truth_gaussian));
            }
            std::printf("%-9s %-13s %-5s %8.3f ms a frame  PSNR box", to_string(scene_kind).c_str(),
                        (filter.label + "-stoch").c_str(), to_string(noise).c_str(), row.time.median);
            for (size_t k = 0; k < checkpoints.size(); ++k)
                std::printf(" %d:%.2f", checkpoints[k], psnr_from_rmse(row.rmse_box[k]));
            std::printf("  gauss");
            for (size_t k = 0; k < checkpoints.size(); ++k)
                std::printf(" %d:%.2f", checkpoints[k], psnr_from_rmse(row.rmse_gaussian[k]));
            std::printf("\n");
            rows.push_back(row);
        }
    }
    return rows;
}

} // namespace tf
