#include "bench/ewa_sweep.h"
#include "bench/metrics.h"
#include "reference/render.h"
#include "vulkan/render.h"

namespace tf {

const std::vector<double>& ewa_sweep_sizes()
{
    static const std::vector<double> sizes = {1, 2, 4, 8, 16, 32, 64};
    return sizes;
}

std::vector<EwaSweepPoint> run_ewa_sweep(const VulkanContext& context, const GpuTexture& texture, const MipChain& chain,
                                         const BenchConfig& config)
{
    const int texture_width = chain.levels[0].width;
    const RenderOptions render = make_render_options(SceneKind::minify, config.stage, Gradients::fine);
    SamplerOptions truth;
    truth.filter = Filter::ground_truth;
    truth.pixel_filter = PixelFilter::gaussian;
    truth.truth_side = config.truth_side;
    SamplerOptions manual, hardware;
    manual.filter = hardware.filter = Filter::ewa;
    hardware.taps = Taps::hardware;
    RenderPipelineCache cache; // each form's pipeline compiled once for every size
    std::vector<EwaSweepPoint> points;
    for (double size : ewa_sweep_sizes()) {
        const SceneParams scene = make_minified_scene(config.width, config.height, texture_width, size);
        const Image reference = config.truth_on_cpu ? reference_render(scene, chain, truth, RenderOptions{})
                                                    : render_frame(*create_renderer(context, texture, scene, truth,
                                                                                    RenderOptions{}, &cache),
                                                                   scene);
        auto psnr = [&](const SamplerOptions& options) {
            return psnr_from_rmse(
                display_rmse(render_frame(*create_renderer(context, texture, scene, options, render, &cache), scene),
                             reference));
        };
        points.push_back({size, psnr(manual), psnr(hardware)});
    }
    return points;
}

} // namespace tf
