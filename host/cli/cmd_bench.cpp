#include "bench/bench.h"
#include "bench/footprint_bench.h"
#include "io/oiio_texture.h"
#include "bench/gpu_build_bench.h"
#include "bench/mip_build_bench.h"
#include "flags/cli_common.h"
#include "core/environment.h"
#include "cli/commands.h"
#include "vulkan/device.h"
#include "texture/error.h"
#include "vulkan/timing.h"
#include "core/memory_budget.h"
#include "io/output_dir.h"
#include "io/output_path.h"
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <unistd.h>

namespace tf {

namespace {

namespace fs = std::filesystem;

std::vector<std::string> split_list(const std::string& text)
{
    std::vector<std::string> items;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');)
        items.push_back(item);
    return items;
}

// A list flag as given, or the fallback where it is absent. An empty value or item ('', ',', 'a,,b') is
// refused: it used to run the default, or nothing, without a word.
std::vector<std::string> list_flag(const Args& args, const std::string& flag, const std::string& fallback,
                                   const std::string& what)
{
    if (!args.has(flag))
        return split_list(fallback);
    const std::string text = args.get(flag, "");
    const std::vector<std::string> items = split_list(text);
    if (text.empty() || text.back() == ',' || std::find(items.begin(), items.end(), "") != items.end())
        throw Error("bad value for " + flag + ": '" + text + "' (" + (text.empty() ? "empty" : "an empty item") +
                    "; expected " + what + " separated by commas)");
    return items;
}

// --memory-budget, or half of physical memory.
uint64_t memory_budget_from(const Args& args)
{
    return args.has("--memory-budget") ? parse_flag(args, "--memory-budget", "", parse_byte_size) : default_memory_budget();
}

// All filters where no label is given.
std::vector<BenchFilter> select_filters(const std::vector<std::string>& labels)
{
    std::vector<BenchFilter> all = bench_filters();
    if (labels.empty())
        return all;
    std::vector<BenchFilter> chosen;
    for (const std::string& label : labels) {
        bool found = false;
        for (const BenchFilter& f : all)
            if (f.label == label) {
                chosen.push_back(f);
                found = true;
            }
        if (!found) {
            std::string valid;
            for (const BenchFilter& f : all)
                valid += (valid.empty() ? "" : ", ") + f.label;
            throw Error("bad value for --filters: unknown label '" + label + "' (expected some of: " + valid + ")");
        }
    }
    return chosen;
}

// bench --mip-build and --gpu-build are other runs than the results run: a flag the chosen run does not
// read is refused, not ignored (--out most of all: nothing would appear there).
void check_mode_flags(const Args& args, const std::string& mode, const std::vector<std::string>& takes)
{
    std::string list;
    for (const std::string& flag : takes)
        list += (list.empty() ? "" : ", ") + flag;
    for (const auto& [flag, value] : args.values)
        if (flag != mode && std::find(takes.begin(), takes.end(), flag) == takes.end())
            throw Error("bench " + mode + " does not take " + flag + " (" +
                        (flag == "--out" ? "it prints its figures and writes no files; " : "") + "its flags: " + list +
                        ")");
}

// --out as given, a trailing '/' dropped (results/ names the directory results), checked new or empty.
std::string new_out_directory(const Args& args)
{
    std::string out = args.require("--out");
    while (out.size() > 1 && out.back() == '/')
        out.pop_back();
    check_new_directory(out, "bench --out");
    return out;
}

// bench --footprints: every flag checked, each texture's header read and the output directory made before any
// work; the files appear together at the end (a staging directory renamed into place).
int run_footprints(const Args& args, const std::vector<std::string>& argv)
{
    check_mode_flags(args, "--footprints",
                     {"--out", "--quick", "--textures", "--filters", "--texture-size", "--lookups", "--format",
                      "--device", "--validate"});
    FootprintConfig config;
    config.quick = args.has("--quick");
    config.textures = list_flag(args, "--textures", "checker,zoneplate", "procedural names or image paths");
    for (const std::string& name : config.textures)
        check_texture_name(name);
    if (args.has("--texture-size") &&
        std::none_of(config.textures.begin(), config.textures.end(), is_procedural_texture))
        throw Error("--texture-size is not read by --textures " + args.get("--textures", "") +
                    " (it applies to the procedural textures: " + procedural_texture_names() + ")");
    config.texture_size = args.get_int("--texture-size", config.quick ? 128 : 512, 1, 16384);
    config.sampling.lookups = args.get_int("--lookups", config.quick ? 900 : 9000, 1, 1000000);
    if (config.quick)
        config.sampling.max_side = 32;
    const std::vector<std::string> labels = args.has("--filters")
                                                ? list_flag(args, "--filters", "", "filter labels")
                                                : default_footprint_labels();
    config.filters = select_footprint_filters(labels);
    if (std::any_of(labels.begin(), labels.end(), [](const std::string& l) { return l.starts_with("oiio-"); }))
        load_oiio_texture(); // the image I/O module, found before any work
    config.format = parse_flag(args, "--format", "rgba32f", parse_texture_format);
    for (const FootprintFilter& f : config.filters) // integer data and hardware filtering, before any work
        if (f.device)
            check_format_filter(config.format, f.options);
    const bool device = std::any_of(config.filters.begin(), config.filters.end(),
                                    [](const FootprintFilter& f) { return f.device; });
    const fs::path out = new_out_directory(args);
    StagingDirectory staging(out.string()); // made before any work: the real test that --out can be written
    std::unique_ptr<GpuSession> gpu;
    if (device)
        gpu = std::make_unique<GpuSession>(context_options_from(args));
    for (const FootprintFilter& f : config.filters)
        if (gpu && f.device)
            check_format_support(gpu->context, config.format, f.options);
    const DeviceLimits limits = gpu ? device_limits(gpu->context.info) : DeviceLimits{};
    for (const std::string& name : config.textures) // sizes against the SAT's, the device's and memory limits
        check_texture(footprint_source(config, name), footprint_use(config, gpu ? &limits : nullptr));
    if (gpu)
        std::printf("bench --footprints on %s (%s %s)\n", gpu->context.info.name.c_str(),
                    gpu->context.info.driver_name.c_str(), gpu->context.info.driver_info.c_str());
    FootprintRun run = run_footprint_bench(gpu ? &gpu->context : nullptr, config);
    run.command = "texfilter bench";
    for (const std::string& word : argv)
        run.command += " " + word;
    if (gpu)
        gpu->finish(); // validation messages fail the run before anything appears at --out
    write_file_atomic(staging.path + "/bench.json", footprint_json(run));
    write_file_atomic(staging.path + "/bench.csv", footprint_csv(run));
    write_file_atomic(staging.path + "/tables.md", footprint_tables(run));
    staging.publish();
    std::printf("truths %.1f s, filters %.1f s\n%s\n", run.truth_seconds, run.filter_seconds, out.string().c_str());
    return 0;
}

// The results directory appears whole or not at all: everything is written into a sibling directory that is
// renamed into place at the end, and removed if anything fails.
} // namespace

int run_bench(const std::vector<std::string>& argv)
{
    std::vector<FlagSpec> specs = join(
        {{{"--out", "DIR", "results directory, new or empty: bench.json, bench.csv, images/ (required)"},
          {"--quick", "", "a CI-sized run: 128x128, 4 scenes, 64 spp, 5 timed frames, 3 path frames, no stochastic rows"},
          {"--scenes", "A,B", "scenes to run (default: all; quick: plane, tunnel, slanted, mesh)"},
          {"--filters", "A,B", "filter labels to run (default: all; see docs/BENCHMARKS.md)"},
          {"--size", "WxH", "image size, even sides (default 256x256)"},
          {"--texture", "T|PATH", "procedural texture (default checker) or an image file"},
          {"--texture-size", "N", "procedural textures: the side in texels (default 512)"},
          {"--memory-budget", "SIZE", "most host memory the texture may take (512M, 8G; default: half of physical memory)"},
          {"--format", "F", "what the texture is uploaded as: " + texture_format_names() +
                                " (default rgba32f; integer formats need --filters without hardware filtering)"},
          {"--build", "B", "cpu (default: the host builds the MIP chain and SAT) or gpu (the device builds them from level 0)"},
          {"--env", "E", "skybox, reflect: the environment map made of --texture, cube (default) or latlong"},
          {"--spp", "N", "ground truth samples a pixel, a square number (default 256)"},
          {"--truth-backend", "B", "vulkan (default: the device) or reference (the CPU, in double)"},
          {"--warmup", "N", "untimed frames before timing (default 5)"},
          {"--frames", "N", "timed frames; min, median and max are reported (default 20)"},
          {"--flicker-frames", "N", "frames of the camera path for flicker, 2..64 (default 8)"},
          {"--lookups-per-pixel", "N", "timed frames: each pixel the mean of N lookups over its footprint, 1..256 "
                                       "(default 1; a GPU's filters above the harness's own cost; images and errors: 1)"},
          {"--stage", "S", "fragment (default) or compute; the mesh scene always rasterizes"},
          {"--timer", "T", "timestamps (GPU timestamps; default on GPUs), wall-clock (default on CPU devices) or cpu-time (the process's CPU time a frame: a CPU device's work, whatever else runs)"},
          {"--mip-build", "", "instead: time the host's MIP build beside memcpy (--texture-size, default 8192; no --out)"},
          {"--repeat", "N", "--mip-build, --gpu-build: runs of each measure, the median reported (default 5, 3)"},
          {"--gpu-build", "", "instead: time the device's MIP and SAT builds beside the host's and beside a copy of "
                              "the same bytes on each, and the dynamic texture's frame (no --out)"},
          {"--sizes", "A,B", "--gpu-build: texture sides (default 1024,4096,8192)"},
          {"--dynamic-size", "N", "--gpu-build: the dynamic texture's side, 0 for none (default 1024)"},
          {"--footprints", "", "instead: each filter's error against footprint size and anisotropy, lookup by lookup, "
                               "against per-lookup truths (--out DIR: bench.json, bench.csv, tables.md)"},
          {"--textures", "A,B", "--footprints: procedural names or image paths (default checker,zoneplate)"},
          {"--lookups", "N", "--footprints: random lookups a texture (default 9000; quick: 900)"}},
         device_flags()});
    Args args = parse_args("bench", argv, specs, 0);
    if (args.has("--help")) {
        std::fputs(format_help("texfilter bench --out DIR [--quick] [--device NAME|INDEX]", specs).c_str(), stdout);
        return 0;
    }
    if (int(args.has("--mip-build")) + int(args.has("--gpu-build")) + int(args.has("--footprints")) > 1)
        throw Error("bench: --mip-build, --gpu-build and --footprints are different runs: give one of them");
    if (args.has("--footprints"))
        return run_footprints(args, argv);
    if (args.has("--mip-build")) {
        check_mode_flags(args, "--mip-build", {"--texture-size", "--repeat", "--memory-budget"});
        const int side = args.get_int("--texture-size", 8192, 1, 16384);
        const int repeats = args.get_int("--repeat", 5, 1, 100);
        check_mip_build_bench(side, memory_budget_from(args));
        std::fputs(format_mip_build_bench(run_mip_build_bench(side, repeats)).c_str(), stdout);
        return 0;
    }
    if (args.has("--gpu-build")) {
        check_mode_flags(args, "--gpu-build",
                         {"--sizes", "--repeat", "--dynamic-size", "--timer", "--device", "--validate", "--memory-budget"});
        std::vector<int> sides;
        for (const std::string& item : list_flag(args, "--sizes", "1024,4096,8192", "texture sides")) {
            Args one = parse_args("bench", {"--sizes", item}, {{"--sizes", "N", ""}}, 0);
            sides.push_back(one.get_int("--sizes", 0, 1, max_texture_dimension));
        }
        const int repeats = args.get_int("--repeat", 3, 1, 100);
        const int dynamic_side = args.get_int("--dynamic-size", 1024, 0, max_texture_dimension);
        GpuSession gpu(context_options_from(args));
        check_gpu_build_bench(sides, dynamic_side, device_limits(gpu.context.info), memory_budget_from(args));
        const bool cpu_device = gpu.context.info.type == "cpu";
        const FrameTimer timer = parse_flag(args, "--timer", cpu_device ? "wall-clock" : "timestamps", parse_frame_timer);
        const std::string text =
            format_gpu_build_bench(run_gpu_build_bench(gpu.context, sides, repeats, timer, dynamic_side));
        gpu.finish();
        std::fputs(text.c_str(), stdout);
        return 0;
    }
    using Owner = std::pair<std::string, std::string>; // a flag of the other runs, and which
    for (const auto& [flag, runs] : {Owner{"--repeat", "--mip-build and --gpu-build"}, Owner{"--sizes", "--gpu-build"},
                                     Owner{"--dynamic-size", "--gpu-build"}, Owner{"--textures", "--footprints"},
                                     Owner{"--lookups", "--footprints"}})
        if (args.has(flag))
            throw Error(flag + " is for bench " + runs + ", not for the results run (--out DIR)");
    BenchConfig config;
    config.quick = args.has("--quick");
    config.stochastic = !config.quick; // 64 frames a filter and noise: not in a CI-sized run
    auto [width, height] = parse_size("--size", args.get("--size", config.quick ? "128x128" : "256x256"), 2, 4096);
    if (width % 2 || height % 2)
        throw Error("bad value for --size: '" + args.get("--size", "") + "' (sides must be even: 2x2 quads)");
    config.width = width;
    config.height = height;
    config.stage = parse_flag(args, "--stage", "fragment", parse_stage);
    config.texture.name_or_path = args.get("--texture", "checker");
    check_texture_name(config.texture.name_or_path); // before the device is opened
    config.texture.procedural_size = args.get_int("--texture-size", config.quick ? 256 : 512, 1, 16384);
    check_texture_size_flag(args, config.texture.name_or_path);
    if (args.has("--memory-budget"))
        config.texture.memory_budget = parse_flag(args, "--memory-budget", "", parse_byte_size);
    config.texture.format = parse_flag(args, "--format", "rgba32f", parse_texture_format);
    config.texture.build = parse_flag(args, "--build", "cpu", parse_texture_build);
    config.texture.env = parse_flag(args, "--env", "cube", parse_env_map);
    if (config.texture.build == TextureBuild::gpu)
        check_gpu_build(config.texture.format, config.texture.name_or_path);
    config.truth_side = parse_flag(args, "--spp", config.quick ? "64" : "256", parse_spp_side);
    std::string truth = args.get("--truth-backend", "vulkan");
    if (truth != "vulkan" && truth != "reference")
        throw Error("bad value for --truth-backend: '" + truth + "' (expected vulkan or reference)");
    config.truth_on_cpu = truth == "reference";
    config.warmup = args.get_int("--warmup", config.quick ? 2 : 5, 0, 1000);
    config.frames = args.get_int("--frames", config.quick ? 5 : 20, 1, 1000);
    config.flicker_frames = args.get_int("--flicker-frames", config.quick ? 3 : 8, 2, 64);
    config.lookups_per_pixel = args.get_int("--lookups-per-pixel", 1, 1, 256);
    const std::vector<std::string> scenes =
        list_flag(args, "--scenes", config.quick ? "plane,tunnel,slanted,mesh" : "", "scene names");
    if (scenes.empty()) // the 2D scenes (skybox and reflect look up directions, not uv)
        for (SceneKind kind : all_scenes())
            if (!is_environment_scene(kind))
                config.scenes.push_back(kind);
    for (const std::string& name : scenes) {
        try {
            config.scenes.push_back(parse_scene(name));
        } catch (const Error& e) {
            throw Error(std::string("bad value for --scenes: ") + e.what());
        }
    }
    check_env_flag(args, config.scenes, "--scenes without skybox or reflect");
    for (SceneKind kind : config.scenes) // before any work: the environment maps' own limits
        if (is_environment_scene(kind) && (config.texture.format != TextureFormat::rgba32f || config.texture.build != TextureBuild::cpu))
            throw Error("--scenes " + to_string(kind) + ": environment maps are uploaded as rgba32f and built on the host "
                        "(drop --format and --build, or bench them in another run)");
    config.filters = select_filters(list_flag(args, "--filters", "", "filter labels"));
    for (const BenchFilter& f : config.filters) // integer data and hardware filtering, before any work
        check_format_filter(config.texture.format, f.options);

    const fs::path out = new_out_directory(args);
    StagingDirectory staging(out.string()); // made before any work: the real test that --out can be written
    GpuSession gpu(context_options_from(args));
    // Every filter runs, the SAT ones too: the texture must fit the table, the memory budget and the device.
    const DeviceLimits limits = device_limits(gpu.context.info);
    for (const BenchFilter& f : config.filters)
        check_format_support(gpu.context, config.texture.format, f.options);
    MipChain chain = load_texture(config.texture, {true, &limits});

    bool cpu_device = gpu.context.info.type == "cpu";
    config.timer = parse_flag(args, "--timer", cpu_device ? "wall-clock" : "timestamps", parse_frame_timer);
    std::printf("bench on %s (%s %s), %dx%d, %zu scenes x %zu filters, %s timer\n", gpu.context.info.name.c_str(),
                gpu.context.info.driver_name.c_str(), gpu.context.info.driver_info.c_str(), config.width, config.height,
                config.scenes.size(), config.filters.size(), to_string(config.timer).c_str());
    BenchRun run = run_bench(gpu.context, config, chain, staging.path);
    gpu.finish(); // validation messages fail the run before anything appears at --out
    write_file_atomic(staging.path + "/bench.json", bench_json(run));
    write_file_atomic(staging.path + "/bench.csv", bench_csv(run));
    staging.publish();
    for (const BenchGoal& g : run.goals)
        std::printf("goal %-14s %s: %s%s%s\n", ("[" + g.status + "]").c_str(), g.goal.c_str(), g.measured.c_str(),
                    g.note.empty() ? "" : " -- ", g.note.c_str());
    std::printf("%s\n", out.string().c_str());
    return 0;
}

} // namespace tf
