#include "flags/cli_common.h"
#include "cli/commands.h"
#include "vulkan/device.h"
#include "texture/error.h"
#include "cli/golden.h"
#include "vulkan/backend.h"
#include "vulkan/render.h"
#include "io/image_io.h"
#include "io/output_dir.h"
#include "io/output_path.h"
#include "reference/render.h"
#include "reference/env_render.h"
#include "io/environment_source.h"
#include "vulkan/environment.h"
#include "io/report.h"
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>

#ifndef TEXFILTER_SOURCE_DIR
#define TEXFILTER_SOURCE_DIR ""
#endif
#ifndef TEXFILTER_BUILD_DIR
#define TEXFILTER_BUILD_DIR ""
#endif

namespace tf {

namespace {

namespace fs = std::filesystem;

// The source tree's golden/, but only for the binary the build tree made: an installed (or copied) texfilter
// must be told --golden-dir, or `golden --update` would rewrite whatever checkout it was built from.
std::string default_golden_dir()
{
    std::error_code ec;
    fs::path exe = fs::canonical("/proc/self/exe", ec);
    fs::path build = std::string(TEXFILTER_BUILD_DIR).empty() ? fs::path() : fs::weakly_canonical(TEXFILTER_BUILD_DIR, ec);
    if (ec || build.empty() || exe.parent_path() != build || std::string(TEXFILTER_SOURCE_DIR).empty())
        throw Error("golden: missing required flag --golden-dir (this texfilter is not the build tree's, so it has "
                    "no source tree's golden/ to default to)");
    return (fs::path(TEXFILTER_SOURCE_DIR) / "golden").string();
}

struct GoldenRun {
    std::string golden_dir, out_dir;
    std::vector<TextureBuild> builds = {TextureBuild::cpu}; // --build: where each case's chain is built, in turn
    std::vector<GoldenCase> cases;
};

std::string golden_path(const GoldenRun& run, const GoldenCase& c) { return run.golden_dir + "/" + c.name + ".png"; }

// The golden a case is compared with, whole (a truncated file fails here) and of the case's size.
Image read_golden(const GoldenRun& run, const GoldenCase& c)
{
    const std::string path = golden_path(run, c);
    Image golden = read_image_raw(path);
    if (golden.width != c.width || golden.height != c.height)
        throw Error(path + ": is " + std::to_string(golden.width) + "x" + std::to_string(golden.height) +
                    ", the case renders " + std::to_string(c.width) + "x" + std::to_string(c.height) +
                    " (run texfilter golden --update)");
    return golden;
}

void update_goldens(const GoldenRun& run)
{
    // Every golden checked before any render, as render -o checks its output: a read-only one is kept.
    std::vector<std::string> paths;
    for (const GoldenCase& c : run.cases)
        paths.push_back(checked_output_path(golden_path(run, c), {".png"}, {c.texture.name_or_path}));
    for (size_t i = 0; i < run.cases.size(); ++i) {
        const GoldenCase& c = run.cases[i];
        const std::string& path = paths[i];
        if (is_environment_scene(c.scene)) {
            const EnvironmentMap env = load_environment(c.texture);
            SceneParams scene = make_scene(c.scene, c.width, c.height, environment_size(env));
            write_image(path, reference_render_environment(scene, env, c.sampler, c.render));
            std::printf("updated %s (CPU reference)\n", path.c_str());
            continue;
        }
        MipChain chain = load_texture(c.texture, {needs_sat(c.sampler.filter), nullptr});
        SceneParams scene = make_scene(c.scene, c.width, c.height, chain.levels[0].width);
        write_image(path, reference_render(scene, chain, c.sampler, c.render));
        std::printf("updated %s (CPU reference)\n", path.c_str());
    }
}

// An environment case (skybox, reflect) on the device: its map uploaded, rendered, destroyed.
Image render_environment_case(const VulkanContext& context, const GoldenCase& c, const DeviceLimits& limits,
                              EnvironmentPipelineCache& pipelines)
{
    const EnvironmentMap env = load_environment(c.texture, {false, &limits});
    SceneParams scene = make_scene(c.scene, c.width, c.height, environment_size(env));
    GpuEnvironment gpu = upload_environment(context, env);
    Cleanup cleanup;
    cleanup.add([&] { destroy_environment(context, gpu); });
    return gpu_render_environment(context, gpu, scene, c.sampler, c.render, &pipelines);
}

// A golden's bytes, copied beside the failure images as they are.
std::string file_bytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in.is_open())
        throw Error(path + ": cannot read the golden again");
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// "cpu", "gpu" or "cpu,gpu".
std::vector<std::string> split_list_of_builds(const std::string& text)
{
    if (text == "cpu,gpu")
        return {"cpu", "gpu"};
    return {text};
}

int check_goldens(const GoldenRun& run, const ContextOptions& context_options)
{
    // Every golden read before the device opens and --out is claimed, so that a missing, truncated or
    // wrong-sized one leaves nothing behind; each is read again when compared (all at once would hold a
    // MiB of floats per 256x256 case).
    for (const GoldenCase& c : run.cases)
        read_golden(run, c);
    GpuSession gpu(context_options);
    // Claimed before any case runs (and after the device opened, so that a machine without one is left as it was).
    OwnedDirectory out = claim_directory(run.out_dir, "golden");
    const DeviceLimits limits = device_limits(gpu.context.info);
    std::vector<ReportCase> report;
    int failures = 0;
    int skipped = 0;
    // The cases share ~30 pipelines: each compiled once (most of a case's time on lavapipe). Declared after
    // the session, so destroyed before it; every render has completed by then (gpu_render waits).
    auto pipelines = std::make_unique<RenderPipelineCache>();
    auto environment_pipelines = std::make_unique<EnvironmentPipelineCache>();
    // --build cpu,gpu renders every case once a build in this one process: the second build's pipelines are
    // the first's. Its lines and images are named gpu-build/NAME.
    for (TextureBuild build : run.builds)
    for (GoldenCase c : run.cases) {
        const std::string label = std::string(run.builds.size() > 1 && build == TextureBuild::gpu ? "gpu-build/" : "") + c.name;
        if (build == TextureBuild::gpu) {
            // mipcolors' levels are not a downsample, integer formats round codes on the host: cpu builds only.
            try {
                if (is_environment_scene(c.scene))
                    throw Error("environment maps are built on the host");
                check_gpu_build(c.texture.format, c.texture.name_or_path);
            } catch (const Error& e) {
                std::printf("%-40s SKIP  %s\n", label.c_str(), e.what());
                ++skipped;
                continue;
            }
            c.texture.build = TextureBuild::gpu;
        }
        Image actual;
        if (is_environment_scene(c.scene)) {
            actual = render_environment_case(gpu.context, c, limits, *environment_pipelines);
        } else {
            check_format_support(gpu.context, c.texture.format, c.sampler);
            TextureUse use{needs_sat(c.sampler.filter), &limits};
            use.level0_only = c.texture.build == TextureBuild::gpu;
            MipChain chain = load_texture(c.texture, use);
            SceneParams scene = make_scene(c.scene, c.width, c.height, chain.levels[0].width);
            actual = with_texture(gpu.context, chain, needs_sat(c.sampler.filter), c.texture.format, c.texture.build,
                                  [&](auto& t) { return gpu_render(gpu.context, t, scene, c.sampler, c.render, pipelines.get()); });
        }

        Image golden = read_golden(run, c);
        Image encoded = encode_srgb(actual);
        DiffResult result = diff_images(encoded, golden, c.thresholds);
        ReportCase entry{label, result.pass, describe(result, c.thresholds), "", "", ""};
        if (!result.pass) {
            ++failures;
            entry.actual_png = "actual/" + label + ".png";
            entry.golden_png = "golden/" + label + ".png";
            entry.diff_png = "diff/" + label + ".png";
            for (const std::string* file : {&entry.actual_png, &entry.golden_png, &entry.diff_png}) {
                record_file(out, *file);
                fs::create_directories(fs::path(out.path) / fs::path(*file).parent_path());
            }
            write_image(out.path + "/" + entry.actual_png, actual);
            write_file_atomic(out.path + "/" + entry.golden_png, file_bytes(golden_path(run, c)));
            // Amplified so that one 8-bit step shows; the diff is of sRGB-encoded values.
            write_image(out.path + "/" + entry.diff_png, diff_image(encoded, golden, 32.0));
        }
        std::printf("%-40s %s  max %.5f  over %.3f%%\n", label.c_str(), result.pass ? "PASS" : "FAIL",
                    result.max_error, result.fail_percent);
        std::fflush(stdout);
        report.push_back(entry);
    }
    std::string device_name = gpu.context.info.name;
    pipelines.reset(); // before the device goes
    environment_pipelines.reset();
    gpu.finish();
    record_file(out, "report.html");
    std::string report_path = out.path + "/report.html";
    write_html_report(report_path, "texfilter golden regression on " + device_name, report);
    if (skipped)
        std::printf("%zu cases, %d failed, %d skipped (--build gpu cannot build them); report: %s\n", run.cases.size(),
                    failures, skipped, report_path.c_str());
    else
        std::printf("%zu cases, %d failed; report: %s\n", run.cases.size(), failures, report_path.c_str());
    return failures == 0 ? 0 : 1;
}

} // namespace

int run_golden(const std::vector<std::string>& argv)
{
    std::vector<FlagSpec> specs = join({{{"--update", "", "regenerate the golden images from the CPU reference"},
                                         {"--case", "NAME", "only this case (repeat with commas: a,b)"},
                                         {"--golden-dir", "DIR", "where manifest.txt and the images are (default, for the build "
                                                                 "tree's binary only: the source tree's golden/; an "
                                                                 "installed texfilter requires it)"},
                                         {"--out", "DIR", "where failures and report.html go (default golden-out)"},
                                         {"--build", "B", "cpu (default) or gpu: where each case's MIP chain and "
                                                          "summed-area table are built before the GPU renders it; "
                                                          "cpu,gpu: both in turn, one process (gpu lines named gpu-build/NAME)"}},
                                        device_flags()});
    Args args = parse_args("golden", argv, specs, 0);
    if (args.has("--help")) {
        std::fputs(format_help("texfilter golden [--golden-dir DIR] [--update] [--case NAME] [--out DIR]", specs).c_str(), stdout);
        return 0;
    }
    GoldenRun run;
    run.golden_dir = args.has("--golden-dir") ? args.get("--golden-dir", "") : default_golden_dir();
    run.out_dir = args.get("--out", "golden-out");
    run.builds.clear();
    for (const std::string& name : split_list_of_builds(args.get("--build", "cpu")))
        try {
            run.builds.push_back(parse_texture_build(name));
        } catch (const Error& e) {
            throw Error(std::string("bad value for --build: ") + e.what());
        }
    if (run.builds != std::vector<TextureBuild>{TextureBuild::cpu} && args.has("--update"))
        throw Error("--update renders the goldens with the CPU reference, which builds on the host: drop --build gpu");
    std::vector<GoldenCase> all = read_manifest(run.golden_dir + "/manifest.txt");
    if (args.has("--case")) {
        std::string list = args.get("--case", "") + ",";
        for (size_t start = 0, comma; (comma = list.find(',', start)) != std::string::npos; start = comma + 1) {
            std::string name = list.substr(start, comma - start);
            bool found = false;
            for (const GoldenCase& c : all)
                if (c.name == name) {
                    run.cases.push_back(c);
                    found = true;
                }
            if (!found)
                throw Error("bad value for --case: no golden case named '" + name + "' in " + run.golden_dir +
                            "/manifest.txt");
        }
    } else {
        run.cases = all;
    }
    if (!image_io_available())
        throw Error("golden needs image I/O, which was left out of this build (configure with -DTEXFILTER_IMAGE_IO=ON)");
    load_image_io(); // a missing image I/O module fails here, before any render
    if (args.has("--update")) {
        check_writable_directory(run.golden_dir, "golden --update");
        update_goldens(run);
        return 0;
    }
    return check_goldens(run, context_options_from(args));
}

} // namespace tf
