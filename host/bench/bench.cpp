#include "bench/bench.h"
#include "bench/env_bench.h"
#include "bench/ewa_sweep.h"
#include "bench/stochastic_bench.h"
#include "core/analytic_texture.h"
#include "core/diff.h"
#include "vulkan/render.h"
#include "texture/error.h"
#include "io/pfm.h"
#include "reference/render.h"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>

namespace tf {

namespace {

namespace fs = std::filesystem;

BenchFilter make_filter(const std::string& label, Filter filter, const std::string& extra = "")
{
    BenchFilter f{label, SamplerOptions{}, "--filter " + to_string(filter) + (extra.empty() ? "" : " " + extra)};
    f.options.filter = filter;
    return f;
}

std::string today()
{
    std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char text[16];
    std::strftime(text, sizeof text, "%Y-%m-%d", &local);
    return text;
}

// The mesh scene is rasterized, so it always takes the graphics pipeline; the others take config.stage.
RenderOptions render_options_for(SceneKind kind, Stage stage)
{
    return make_render_options(kind, kind == SceneKind::mesh ? Stage::fragment : stage, Gradients::fine);
}

std::string image_path(SceneKind scene, const std::string& name)
{
    return "images/" + to_string(scene) + "/" + name + ".pfm";
}

// Frames 0..count-1 of the camera path.
std::vector<Image> render_path(GpuRenderer& renderer, const SceneParams& scene, int count, int texture_width)
{
    std::vector<Image> frames;
    for (int t = 0; t < count; ++t)
        frames.push_back(render_frame(renderer, scene_at_frame(scene, t, texture_width)));
    return frames;
}

// A scene's truths along the camera path: the box and Gaussian pixels over the bilinear texels, and, where
// the texture has an analytic definition, the box pixel over that function (else empty). On the device
// the three renderers share one pipeline: only their push constants differ.
struct TruthPaths {
    std::vector<Image> box, gaussian, analytic;
};

TruthPaths truth_paths(const VulkanContext& context, const GpuTexture& texture, const MipChain& chain,
                       const BenchConfig& config, const SceneParams& scene)
{
    auto truth_options = [&](PixelFilter pixel_filter, Truth truth) {
        SamplerOptions options;
        options.filter = Filter::ground_truth;
        options.pixel_filter = pixel_filter;
        options.truth_side = config.truth_side;
        options.truth = truth;
        resolve_analytic_truth(options, config.texture.name_or_path);
        return options;
    };
    const int texture_width = chain.levels[0].width;
    RenderOptions render; // ray-cast in a fragment shader; the mesh through its ray-cast twin
    RenderPipelineCache cache;
    auto path = [&](const SamplerOptions& options) {
        if (config.truth_on_cpu) {
            std::vector<Image> frames;
            for (int t = 0; t < config.flicker_frames; ++t)
                frames.push_back(reference_render(scene_at_frame(scene, t, texture_width), chain, options, RenderOptions{}));
            return frames;
        }
        auto renderer = create_renderer(context, texture, scene, options, render, &cache);
        return render_path(*renderer, scene, config.flicker_frames, texture_width);
    };
    TruthPaths paths;
    paths.box = path(truth_options(PixelFilter::box, Truth::texels));
    paths.gaussian = path(truth_options(PixelFilter::gaussian, Truth::texels));
    if (has_analytic_definition(config.texture.name_or_path))
        paths.analytic = path(truth_options(PixelFilter::box, Truth::analytic));
    return paths;
}

// Texel fetches and hardware lookups a covered pixel, counted by the sample harness on the scene's own lookups.
void count_fetches(const VulkanContext& context, const GpuTexture& texture, const std::vector<Lookup>& lookups,
                   const SamplerOptions& options, BenchResult& result)
{
    if (lookups.empty())
        return;
    std::vector<LookupStats> stats;
    gpu_sample(context, texture, lookups, options, &stats);
    double fetches = 0, hardware = 0;
    for (const LookupStats& s : stats) {
        fetches += s.texel_fetches;
        hardware += s.hardware_lookups;
    }
    result.fetches_per_pixel = fetches / double(stats.size());
    result.hw_lookups_per_pixel = hardware / double(stats.size());
}

// One line a result as it finishes (the JSON has everything): reads are texel fetches plus hardware lookups.
void print_result(const BenchResult& r)
{
    std::printf("%-9s %-13s %8.3f ms  x%5.2f baseline  %6.1f reads/px  PSNR box %5.2f gauss %5.2f", to_string(r.scene).c_str(),
                r.filter.label.c_str(), r.time.median, r.vs_baseline, r.fetches_per_pixel + r.hw_lookups_per_pixel,
                psnr_from_rmse(r.rmse_box), psnr_from_rmse(r.rmse_gaussian));
    if (std::isfinite(r.rmse_analytic))
        std::printf(" analytic %5.2f", psnr_from_rmse(r.rmse_analytic));
    std::printf("  flicker %.4f\n", r.flicker_gaussian);
    std::fflush(stdout);
}

} // namespace

void set_vs_hw_trilinear(BenchRun& run, size_t first)
{
    double hw_trilinear = NAN; // NaN if it was left out
    for (size_t i = first; i < run.results.size(); ++i)
        if (run.results[i].filter.label == "hw-trilinear")
            hw_trilinear = run.results[i].time.median;
    for (size_t i = first; i < run.results.size(); ++i)
        run.results[i].vs_hw_trilinear = run.results[i].time.median / hw_trilinear;
}

std::vector<BenchFilter> bench_filters()
{
    std::vector<BenchFilter> filters = {
        make_filter("nearest", Filter::nearest),
        make_filter("bilinear", Filter::bilinear),
        make_filter("nearest-mip", Filter::nearest_mip),
        make_filter("bilinear-mip", Filter::bilinear_mip),
        make_filter("trilinear", Filter::trilinear),
        make_filter("brilinear", Filter::brilinear, "--band 0.25"),
        make_filter("aniso16", Filter::aniso, "--probes 16"),
        make_filter("aniso16-hw", Filter::aniso, "--probes 16 --taps hardware"),
        make_filter("ewa", Filter::ewa),
        make_filter("ewa-hw", Filter::ewa, "--taps hardware"),
        make_filter("ewa-fast", Filter::ewa_fast),
        make_filter("sat", Filter::sat),
        make_filter("sat-assembly", Filter::sat_assembly, "--boxes 4"),
        make_filter("hw-nearest", Filter::hw_nearest),
        make_filter("hw-bilinear", Filter::hw_bilinear),
        make_filter("hw-trilinear", Filter::hw_trilinear),
        make_filter("hw-aniso16", Filter::hw_aniso, "--aniso 16"),
        make_filter("bspline", Filter::bspline),
        make_filter("bspline-hw", Filter::bspline, "--taps hardware"),
        make_filter("catmull-rom", Filter::catmull_rom),
        make_filter("catmull-rom-hw", Filter::catmull_rom, "--taps hardware"),
        make_filter("trilinear-catmull-rom", Filter::trilinear, "--magnify catmull-rom"),
        make_filter("ewa-bspline", Filter::ewa, "--magnify bspline"),
    };
    for (BenchFilter& f : filters) {
        if (f.label.ends_with("-hw"))
            f.options.taps = Taps::hardware;
        if (f.label.ends_with("-catmull-rom"))
            f.options.magnify = Reconstruction::catmull_rom;
        if (f.label.ends_with("-bspline"))
            f.options.magnify = Reconstruction::bspline;
    }
    return filters;
}

namespace {

void print_yardsticks(const BenchRun& run, SceneKind kind)
{
    if (!run.minimal.count(kind))
        return;
    const double lean = run.minimal.at(kind).median;
    std::printf("%-9s no-texture frame %8.3f ms  x%5.2f the minimal pass (%.3f ms)", to_string(kind).c_str(),
                run.baseline.at(kind).median, run.baseline.at(kind).median / lean, lean);
    if (run.minimal_trilinear.count(kind))
        std::printf("  minimal trilinear %.3f ms", run.minimal_trilinear.at(kind).median);
    std::printf("\n");
}

// The yardsticks a run times beside its baseline: in the compute stage at one lookup a pixel (the minimal pass makes
// one) the minimal pass, and with a float texture that is square and a power of two (what its mask repeat assumes)
// the minimal trilinear pass too.
std::vector<MinimalPass> minimal_passes(const BenchConfig& config, const GpuTexture& texture, int texture_width,
                                        int texture_height)
{
    if (config.stage != Stage::compute || config.lookups_per_pixel != 1)
        return {};
    const bool power_of_two = texture_width == texture_height && (texture_width & (texture_width - 1)) == 0;
    if (format_info(texture.format).integer || !power_of_two)
        return {MinimalPass::no_texture};
    return {MinimalPass::no_texture, MinimalPass::trilinear};
}

double minimal_trilinear_difference(const VulkanContext& context, const GpuTexture& texture, const SceneParams& scene,
                                    const RenderOptions& render, RenderPipelineCache& pipelines, const Image& trilinear)
{
    RenderOptions lean = render;
    lean.minimal = MinimalPass::trilinear;
    SamplerOptions none;
    none.filter = Filter::none;
    const Image frame = render_frame(*create_renderer(context, texture, scene, none, lean, &pipelines), scene);
    return diff_images(frame, trilinear, DiffThresholds{}).max_error;
}

// The frame times of a scene's baseline (result 0), of each filter (result i + 1) and of each minimal pass
// (result filters + 1 + k), taken in turn. All of them
// alive at once would hold every renderer's targets (~32 bytes a pixel each: at 4096x4096, 0.5 GiB a filter), so
// at most 1 GiB of them is: a large image times the filters in groups, each group in turn with the baseline,
// whose times from every group are pooled.
std::vector<std::vector<double>> time_scene_filters(const VulkanContext& context, const GpuTexture& texture,
                                                    const SceneParams& scene, const RenderOptions& render,
                                                    const BenchConfig& config, RenderPipelineCache& pipelines,
                                                    const std::vector<MinimalPass>& minimal)
{
    const size_t filters = config.filters.size();
    const size_t per_renderer = size_t(config.width) * size_t(config.height) * 32;
    const size_t group = std::clamp<size_t>((size_t(1) << 30) / std::max<size_t>(per_renderer, 1), 2, filters + 1) - 1;
    SamplerOptions none;
    none.filter = Filter::none;
    const std::unique_ptr<GpuRenderer> baseline = create_renderer(context, texture, scene, none, render, &pipelines);
    std::vector<std::unique_ptr<GpuRenderer>> yardsticks;
    for (MinimalPass pass : minimal) {
        RenderOptions lean = render;
        lean.minimal = pass;
        yardsticks.push_back(create_renderer(context, texture, scene, none, lean, &pipelines));
    }
    std::vector<std::vector<double>> times(filters + 1 + minimal.size());
    // The yardsticks are timed with each group, as the baseline, and their times pooled the same way.
    auto time_group = [&](size_t begin, size_t end) {
        std::vector<std::unique_ptr<GpuRenderer>> renderers;
        std::vector<GpuRenderer*> timed = {baseline.get()};
        for (size_t i = begin; i < end; ++i) {
            renderers.push_back(create_renderer(context, texture, scene, config.filters[i].options, render, &pipelines));
            timed.push_back(renderers.back().get());
        }
        for (const auto& y : yardsticks)
            timed.push_back(y.get());
        const std::vector<std::vector<double>> t = time_frames_interleaved(timed, config.warmup, config.frames, config.timer);
        times[0].insert(times[0].end(), t[0].begin(), t[0].end());
        for (size_t k = 1; k <= end - begin; ++k)
            times[begin + k] = t[k];
        for (size_t k = 0; k < yardsticks.size(); ++k) {
            const std::vector<double>& y = t[1 + end - begin + k];
            times[filters + 1 + k].insert(times[filters + 1 + k].end(), y.begin(), y.end());
        }
    };
    for (size_t begin = 0; begin < filters; begin += group)
        time_group(begin, std::min(begin + group, filters));
    if (filters == 0)
        time_group(0, 0);
    return times;
}

} // namespace

BenchRun run_bench(const VulkanContext& context, const BenchConfig& config, const MipChain& chain,
                   const std::string& directory)
{
    BenchRun run;
    run.device = context.info;
    run.date = today();
    run.config = config;
    run.texture_width = chain.levels[0].width;
    run.texture_height = chain.levels[0].height;
    const int texture_width = run.texture_width;
    with_texture(context, chain, true, config.texture.format, config.texture.build, [&](const GpuTexture& texture) {
        for (SceneKind kind : config.scenes) {
            if (is_environment_scene(kind)) { // directions, not uv: their own map and renderers
                bench_environment_scene(context, config, kind, directory, run);
                continue;
            }
            SceneParams scene = make_scene(kind, config.width, config.height, texture_width);
            RenderOptions render = render_options_for(kind, config.stage);
            fs::create_directories(fs::path(directory) / "images" / to_string(kind));

            const TruthPaths truths = truth_paths(context, texture, chain, config, scene);
            const std::vector<Image>& truth_box = truths.box;
            const std::vector<Image>& truth_gaussian = truths.gaussian;
            run.truth_box[kind] = image_path(kind, "truth-box");
            run.truth_gaussian[kind] = image_path(kind, "truth-gaussian");
            write_pfm((fs::path(directory) / run.truth_box[kind]).string(), truth_box[0]);
            write_pfm((fs::path(directory) / run.truth_gaussian[kind]).string(), truth_gaussian[0]);
            if (!truths.analytic.empty()) {
                run.truth_analytic[kind] = image_path(kind, "truth-analytic");
                write_pfm((fs::path(directory) / run.truth_analytic[kind]).string(), truths.analytic[0]);
            }

            // The baseline and the filters timed in turn (time_frames_interleaved), so their ratios share
            // conditions; each filter's pipeline made once (for its timing and its images).
            RenderPipelineCache pipelines;
            RenderOptions timed = render;
            timed.lookups = config.lookups_per_pixel;
            const std::vector<MinimalPass> minimal =
                minimal_passes(config, texture, run.texture_width, run.texture_height);
            const std::vector<std::vector<double>> times =
                time_scene_filters(context, texture, scene, timed, config, pipelines, minimal);
            run.baseline[kind] = summarize_times(times[0]);
            for (size_t k = 0; k < minimal.size(); ++k)
                (minimal[k] == MinimalPass::no_texture ? run.minimal : run.minimal_trilinear)[kind] =
                    summarize_times(times[config.filters.size() + 1 + k]);
            print_yardsticks(run, kind);

            std::vector<Lookup> lookups;
            for (const PixelLookup& p : reference_lookups(scene, Gradients::fine, render.rasterize))
                if (p.hit)
                    lookups.push_back(p.lookup);

            size_t first = run.results.size();
            for (size_t i = 0; i < config.filters.size(); ++i) {
                const BenchFilter& filter = config.filters[i];
                BenchResult r;
                r.scene = kind;
                r.filter = filter;
                r.stage = render.stage;
                auto renderer = create_renderer(context, texture, scene, filter.options, render, &pipelines);
                r.time = summarize_times(times[i + 1]);
                r.vs_baseline = r.time.median / run.baseline[kind].median;
                std::vector<Image> frames = render_path(*renderer, scene, config.flicker_frames, texture_width);
                r.rmse_box = display_rmse(frames[0], truth_box[0]);
                r.rmse_gaussian = display_rmse(frames[0], truth_gaussian[0]);
                r.flicker_box = display_flicker(frames, truth_box);
                r.flicker_gaussian = display_flicker(frames, truth_gaussian);
                if (!truths.analytic.empty()) {
                    r.rmse_analytic = display_rmse(frames[0], truths.analytic[0]);
                    r.flicker_analytic = display_flicker(frames, truths.analytic);
                }
                if (filter.label == "trilinear" && run.minimal_trilinear.count(kind))
                    run.minimal_trilinear_difference[kind] =
                        minimal_trilinear_difference(context, texture, scene, render, pipelines, frames[0]);
                r.image = image_path(kind, filter.label);
                write_pfm((fs::path(directory) / r.image).string(), frames[0]);
                count_fetches(context, texture, lookups, filter.options, r);
                run.results.push_back(r);
                print_result(r);
            }
            set_vs_hw_trilinear(run, first);
            // Stochastic filtering on the first 2D scene of the run (its cost: 64 frames a filter and noise).
            if (config.stochastic && run.stochastic.empty())
                run.stochastic = run_stochastic_rows(context, texture, config, kind, scene, truth_box[0], truth_gaussian[0]);
        }
        // sat's cost against footprint size: the same four corners per box whatever the footprint.
        for (const BenchFilter& filter : config.filters) {
            if (filter.options.filter != Filter::sat && filter.options.filter != Filter::sat_assembly)
                continue;
            RenderOptions render = render_options_for(SceneKind::minify, config.stage);
            render.lookups = config.lookups_per_pixel; // timed only
            SatSweep sweep{filter.label, {}, {}};
            for (double factor : {2.0, 64.0}) {
                SceneParams scene = make_minified_scene(config.width, config.height, texture_width, factor);
                auto renderer = create_renderer(context, texture, scene, filter.options, render);
                (factor == 2.0 ? sweep.at_2x : sweep.at_64x) =
                    summarize_times(time_frames(*renderer, config.warmup, config.frames, config.timer));
            }
            std::printf("minify    %-13s %8.3f ms at 2x, %8.3f ms at 64x\n", filter.label.c_str(), sweep.at_2x.median,
                        sweep.at_64x.median);
            run.sat_sweep.push_back(sweep);
        }
        // ewa's two tap forms against footprint size, when both run.
        auto ran = [&](const char* label) {
            for (const BenchFilter& f : config.filters)
                if (f.label == label) return true;
            return false;
        };
        if (ran("ewa") && ran("ewa-hw")) {
            run.ewa_sweep = run_ewa_sweep(context, texture, chain, config);
            for (const EwaSweepPoint& p : run.ewa_sweep)
                std::printf("minify    ewa %4.0f texels/px: PSNR gauss manual %6.2f, hardware %6.2f (%+.2f dB)\n",
                            p.texels_per_pixel, p.psnr_manual, p.psnr_hardware, p.psnr_hardware - p.psnr_manual);
        }
        return 0;
    });
    run.goals = judge_goals(run);
    return run;
}

} // namespace tf
