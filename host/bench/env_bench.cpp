#include "bench/env_bench.h"

#include "bench/metrics.h"
#include "core/environment.h"
#include "io/environment_source.h"
#include "io/pfm.h"
#include "reference/env_render.h"
#include "vulkan/device.h"
#include "vulkan/environment.h"
#include "vulkan/timing.h"
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace tf {

namespace {

namespace fs = std::filesystem;


std::vector<Image> environment_path(GpuRenderer& renderer, const SceneParams& scene, int count, int size)
{
    std::vector<Image> frames;
    for (int t = 0; t < count; ++t)
        frames.push_back(render_frame(renderer, scene_at_frame(scene, t, size)));
    return frames;
}

} // namespace

void bench_environment_scene(const VulkanContext& context, const BenchConfig& config, SceneKind kind,
                             const std::string& directory, BenchRun& run)
{
    const DeviceLimits limits = device_limits(context.info);
    const EnvironmentMap env = load_environment(config.texture, {false, &limits});
    const int size = environment_size(env);
    GpuEnvironment gpu = upload_environment(context, env);
    Cleanup cleanup;
    cleanup.add([&] { destroy_environment(context, gpu); });
    const SceneParams scene = make_scene(kind, config.width, config.height, size);
    const RenderOptions render = make_render_options(kind, Stage::fragment, Gradients::fine);
    const std::string folder = "images/" + to_string(kind) + "/";
    fs::create_directories(fs::path(directory) / folder);

    std::vector<Image> truth[2];
    for (PixelFilter pixel : {PixelFilter::box, PixelFilter::gaussian}) {
        SamplerOptions options;
        options.filter = Filter::ground_truth;
        options.pixel_filter = pixel;
        options.truth_side = config.truth_side;
        std::vector<Image>& frames = truth[pixel == PixelFilter::box ? 0 : 1];
        if (config.truth_on_cpu) {
            for (int t = 0; t < config.flicker_frames; ++t)
                frames.push_back(reference_render_environment(scene_at_frame(scene, t, size), env, options, render));
        } else {
            frames = environment_path(*create_environment_renderer(context, gpu, scene, options, render), scene,
                                      config.flicker_frames, size);
        }
    }
    run.truth_box[kind] = folder + "truth-box.pfm";
    run.truth_gaussian[kind] = folder + "truth-gaussian.pfm";
    write_pfm((fs::path(directory) / run.truth_box[kind]).string(), truth[0][0]);
    write_pfm((fs::path(directory) / run.truth_gaussian[kind]).string(), truth[1][0]);

    SamplerOptions none;
    none.filter = Filter::none;
    run.baseline[kind] = summarize_times(time_frames(*create_environment_renderer(context, gpu, scene, none, render),
                                                     config.warmup, config.frames, config.timer));
    const size_t first = run.results.size();
    for (const BenchFilter& filter : config.filters) {
        if (!has_environment_form(filter.options))
            continue;
        BenchResult r;
        r.scene = kind;
        r.filter = filter;
        r.stage = Stage::fragment;
        auto renderer = create_environment_renderer(context, gpu, scene, filter.options, render);
        r.time = summarize_times(time_frames(*renderer, config.warmup, config.frames, config.timer));
        r.vs_baseline = r.time.median / run.baseline[kind].median;
        const std::vector<Image> frames = environment_path(*renderer, scene, config.flicker_frames, size);
        r.rmse_box = display_rmse(frames[0], truth[0][0]);
        r.rmse_gaussian = display_rmse(frames[0], truth[1][0]);
        r.flicker_box = display_flicker(frames, truth[0]);
        r.flicker_gaussian = display_flicker(frames, truth[1]);
        r.image = folder + filter.label + ".pfm";
        write_pfm((fs::path(directory) / r.image).string(), frames[0]);
        run.results.push_back(r);
        std::printf("%-9s %-13s %8.3f ms  x%5.2f baseline  PSNR box %5.2f gauss %5.2f  flicker %.4f\n",
                    to_string(kind).c_str(), r.filter.label.c_str(), r.time.median, r.vs_baseline,
                    psnr_from_rmse(r.rmse_box), psnr_from_rmse(r.rmse_gaussian), r.flicker_gaussian);
        std::fflush(stdout);
    }
    set_vs_hw_trilinear(run, first);
}

} // namespace tf
