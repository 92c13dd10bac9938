#include "flags/cli_common.h"
#include "core/analytic_texture.h"
#include "core/environment.h"
#include "vulkan/device.h"
#include "texture/error.h"
#include "core/memory_budget.h"
#include "core/numbers.h"
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <optional>

namespace tf {

std::vector<FlagSpec> texture_flags(BuildDefault default_build)
{
    const bool gpu_default = default_build == BuildDefault::gpu;
    return {{"--texture", "T|PATH", "procedural texture (checker, zoneplate, grid, noise, mipcolors, dynamic) or an image file"},
            {"--texture-size", "N", "side of a procedural texture in texels (default 256)"},
            {"--texture-frame", "N", "--texture dynamic: its frame, 0..1000000 (default 0; the viewer animates it "
                                     "with --build gpu)"},
            {"--linear", "", "the image file holds data/linear values: no sRGB decode"},
            {"--format", "F", "what the texture is uploaded as: " + texture_format_names() +
                                  " (default rgba32f; every level rounded to it, on both backends)"},
            {"--build", "B", std::string("where the MIP chain and summed-area table are built: cpu (the host") +
                                 (gpu_default ? ")" : ", default)") +
                                 " or gpu (level 0 uploaded, the rest built by the device" +
                                 (gpu_default ? ", default)" : "; --backend vulkan)")},
            {"--memory-budget", "SIZE", "most host memory a texture may take (512M, 8G; default: half of physical "
                                        "memory); checked from the file's header before decoding"},
            {"--env", "E", "environment scenes (skybox, reflect): cube (default; a procedural name makes six faces of it, "
                           "each tinted, or cube-labels, cube-hash, cube-smooth; a file is a 4:3 horizontal cross) or "
                           "latlong (a 2:1 equirectangular image; a procedural name: the same cube, resampled)"}};
}

std::vector<FlagSpec> sampler_flags(SamplerFlags which)
{
    const bool scenes = which == SamplerFlags::scenes;
    std::vector<FlagSpec> flags = {
        {"--filter", "F",
         std::string("nearest, bilinear, bspline, catmull-rom, trilinear, nearest-mip, bilinear-mip, brilinear, aniso, "
                     "ewa, ewa-fast, sat, sat-assembly, hw-nearest, hw-bilinear, hw-trilinear, hw-aniso") +
             (scenes ? ", ground-truth (supersampled) or none (no texture: the benchmark's baseline)" : "")},
        {"--wrap", "W", "repeat (default), clamp or mirror"},
        {"--aniso", "N", "hw-aniso: maximum anisotropy, 1..16 (default 16)"},
        {"--band", "B", "brilinear: trilinear band around each level transition, 0..1 (default 0.25)"},
        {"--probes", "N", "aniso: most probes along the major axis, 1..16 (default 16)"},
        {"--aniso-shape", "S", "aniso: gpu (Vulkan's model, default) or feline (ellipse axis, Gaussian weights)"},
        {"--taps", "T", "aniso, ewa, bspline, catmull-rom: manual (texelFetch, default) or hardware (bilinear/trilinear "
                        "lookups)"},
        {"--magnify", "R", "trilinear, aniso, ewa: level 0's reconstruction, bilinear (default), bspline or catmull-rom"},
        {"--alpha", "A", "ewa: Gaussian exp(-A r^2), 0.05..16 (default 2)"},
        {"--max-aniso", "E", "ewa: largest major/minor axis ratio, 1..64 (default 16)"},
        {"--boxes", "K", "sat-assembly: boxes along the major axis, 1..16 (default 4)"}};
    if (scenes) {
        flags.push_back({"--pixel-filter", "P", "ground-truth: box (over the pixel, default) or gaussian (sigma 0.5 px)"});
        flags.push_back({"--spp", "N", "ground-truth: samples a pixel, a square number 1..4096 (default 256)"});
        flags.push_back({"--truth", "T", "ground-truth: what it integrates, texels (level 0 reconstructed bilinearly, "
                                         "default) or analytic (the function of checker, zoneplate or grid)"});
    }
    // sample: row r takes the random numbers of pixel (0, 0), lookup r (render: its pixel, lookup 0).
    flags.push_back({"--stochastic", "NOISE", std::string("bilinear, trilinear, aniso, ewa: one texel (or, with --taps "
                                              "hardware, one tap) a lookup, chosen by its weight from white or blue "
                                              "noise") + (scenes ? "" : " (row r: the numbers of pixel 0,0, lookup r)")});
    flags.push_back({"--accumulate", "N", std::string("--stochastic: the mean of N frames, each with its own random "
                                          "numbers, 1..4096 (default 1: one noisy ") + (scenes ? "frame)" : "value a row)")});
    flags.insert(flags.end(), {{"--lod-bias", "B", "added to the LOD (default 0)"},
                               {"--lod-min", "L", "lowest LOD used (default 0)"},
                               {"--lod-max", "L", "highest LOD used (default: the last level)"},
                               {"--backend", "B", scenes ? "vulkan (default) or reference (the CPU reference)"
                                                         : "vulkan (default), reference (the CPU reference) or oiio "
                                                           "(OpenImageIO's TextureSystem: --filter trilinear or aniso)"}});
    return flags;
}

std::string scene_names()
{
    std::string names;
    const std::vector<SceneKind>& scenes = all_scenes();
    for (size_t i = 0; i < scenes.size(); ++i)
        names += (i == 0 ? "" : i + 1 == scenes.size() ? " or " : ", ") + to_string(scenes[i]);
    return names;
}

std::vector<FlagSpec> device_flags()
{
    return {{"--device", "NAME|INDEX", "Vulkan device by index or part of its name (default: lavapipe)"},
            {"--validate", "", "enable the Vulkan validation layers; any message is an error"},
            {"--help", "", "show this help"}};
}

std::vector<FlagSpec> join(std::vector<std::vector<FlagSpec>> groups)
{
    std::vector<FlagSpec> out;
    for (auto& g : groups)
        out.insert(out.end(), g.begin(), g.end());
    return out;
}

namespace {

bool has_extension(const std::string& path, std::initializer_list<const char*> extensions)
{
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return std::find(extensions.begin(), extensions.end(), ext) != extensions.end();
}

} // namespace

void check_texture_size_flag(const Args& args, const std::string& name)
{
    if (args.has("--texture-size") && !is_procedural_texture(name))
        throw Error("--texture-size is not read by --texture " + name + " (it applies to the procedural textures: " +
                    procedural_texture_names() + "; a file has its own size)");
}

TextureSource texture_source_from(const Args& args) { return texture_source_from(args, TextureCheck::now); }

TextureSource texture_source_from(const Args& args, TextureCheck when)
{
    TextureSource source;
    source.name_or_path = args.require("--texture");
    const std::string& name = source.name_or_path;
    const bool procedural = is_procedural_texture(name);
    if (when == TextureCheck::now)
        check_texture_name(name);
    source.procedural_size = args.get_int("--texture-size", 256, 1, max_texture_dimension);
    check_texture_size_flag(args, name);
    source.color = args.has("--linear") ? ColorSpace::linear : ColorSpace::automatic;
    if (args.has("--linear") && procedural)
        throw Error("--linear is not read by --texture " + name + " (it applies to image files: a procedural "
                    "texture is made in linear values)");
    if (args.has("--linear") && has_extension(name, {".exr", ".pfm", ".hdr"}))
        throw Error("--linear is not read by --texture " + name + " (it applies to 8- and 16-bit image files: "
                    "floats are read as linear values already)");
    source.format = parse_flag(args, "--format", "rgba32f", parse_texture_format);
    source.build = parse_flag(args, "--build", "cpu", parse_texture_build);
    if (args.has("--texture-frame")) {
        source.texture_frame = args.get_int("--texture-frame", 0, 0, max_texture_frame);
        if (!is_dynamic_texture(source))
            throw Error("--texture-frame applies to --texture dynamic only (the animated procedural texture), not to '" +
                        source.name_or_path + "'");
    }
    if (source.build == TextureBuild::gpu) {
        check_gpu_build(source.format, source.name_or_path);
        if (args.get("--backend", "vulkan") == "reference")
            throw Error("--build gpu builds on the Vulkan device: it needs --backend vulkan (the reference builds on the host)");
    }
    if (args.has("--memory-budget"))
        source.memory_budget = parse_flag(args, "--memory-budget", "", parse_byte_size);
    source.env = parse_flag(args, "--env", "cube", parse_env_map);
    return source;
}

void check_env_flag(const Args& args, const std::vector<SceneKind>& scenes, const std::string& where)
{
    if (!args.has("--env"))
        return;
    for (SceneKind kind : scenes)
        if (is_environment_scene(kind))
            return;
    throw Error("--env is not read by " + where + " (it applies to the environment scenes, skybox and reflect)");
}

SamplerOptions sampler_options_from(const Args& args, const SamplerFlagUse& use)
{
    SamplerOptions options;
    options.filter = parse_flag(args, "--filter", "", parse_filter);
    options.wrap = parse_flag(args, "--wrap", "repeat", parse_wrap);
    options.aniso = args.get_int("--aniso", 16, 1, 16);
    options.band = float(args.get_double("--band", options.band, 0.0, 1.0));
    options.probes = args.get_int("--probes", options.probes, 1, 16);
    options.aniso_shape = parse_flag(args, "--aniso-shape", "gpu", parse_aniso_shape);
    options.taps = parse_flag(args, "--taps", "manual", parse_taps);
    options.magnify = parse_flag(args, "--magnify", "bilinear", parse_reconstruction);
    options.alpha = float(args.get_double("--alpha", options.alpha, 0.05, 16.0));
    options.max_aniso = float(args.get_double("--max-aniso", options.max_aniso, 1.0, 64.0));
    options.boxes = args.get_int("--boxes", options.boxes, 1, 16);
    options.pixel_filter = parse_flag(args, "--pixel-filter", "box", parse_pixel_filter);
    options.truth_side = parse_flag(args, "--spp", "256", parse_spp_side);
    options.truth = parse_flag(args, "--truth", "texels", parse_truth); // its texture: resolve_analytic_truth
    if (args.has("--stochastic")) {
        options.stochastic = true;
        options.noise = parse_flag(args, "--stochastic", "", parse_noise);
    }
    if (args.has("--accumulate")) {
        const std::string n = args.get("--accumulate", "");
        const std::optional<long long> value = parse_whole_number(n);
        if (!value)
            throw Error("bad value for --accumulate: '" + n + "' (expected a whole number of frames, 1..4096)");
        if (*value < 1 || *value > HARNESS_MAX_ACCUMULATE) // named as given: 99999999999 must not read as 4097
            throw Error("bad value for --accumulate: " + n + " (expected 1.." + std::to_string(HARNESS_MAX_ACCUMULATE) +
                        " frames)");
        options.accumulate = int(*value);
    }
    options.lod_bias = float(args.get_double("--lod-bias", 0.0, -16.0, 16.0));
    options.lod_min = float(args.get_double("--lod-min", 0.0, 0.0, 1000.0));
    options.lod_max = float(args.get_double("--lod-max", 1000.0, 0.0, 1000.0));
    // Every value is well formed; now whether the filter reads it, before the combinations of what it reads.
    if (!use.keep_unread)
        for (const std::string& flag : sampler_flag_names()) {
            if (!args.has(flag) || filter_reads(options.filter, flag, options.stochastic))
                continue;
            if (use.lod_view && is_lod_flag(flag) && !is_scene_level(options.filter))
                continue;
            if (use.truth_view && (flag == "--spp" || flag == "--pixel-filter"))
                continue;
            throw Error(flag + " is not read by --filter " + to_string(options.filter) + " (it applies to " +
                        filters_reading(flag) + ")");
        }
    if (use.environment && args.has("--wrap") && !use.keep_unread)
        throw Error("--wrap is not read on the environment scenes (skybox, reflect: a cube or lat-long map has no "
                    "edge to wrap)");
    check_magnify(options);
    check_stochastic(options); // --accumulate's range, the filter, --magnify
    if (options.lod_min > options.lod_max)
        throw Error("bad values: --lod-min " + args.get("--lod-min", "0") + " is above --lod-max " +
                    args.get("--lod-max", "1000"));
    return options;
}

void check_viewer_sampler(const SamplerOptions& options)
{
    if (options.truth == Truth::analytic)
        throw Error("--truth analytic is not available in the viewer (its ground truth integrates the texels): render "
                    "it with texfilter render --filter ground-truth --truth analytic");
    if (options.stochastic)
        throw Error("--stochastic is not available in the viewer (it shows one deterministic frame a change): render "
                    "it with texfilter render --stochastic " + to_string(options.noise) + " --accumulate N");
}

int parse_spp_side(const std::string& text)
{
    const int largest = max_ground_truth_side * max_ground_truth_side;
    const std::optional<long long> spp = parse_whole_number(text);
    if (!spp || *spp < 1 || *spp > largest)
        throw Error("'" + text + "' is not a whole number in 1.." + std::to_string(largest));
    int side = 1;
    while ((side + 1) * (side + 1) <= *spp)
        ++side;
    if (side * side != *spp)
        throw Error("'" + text + "' is not a square number (the samples form a side x side grid: 64, 256, 1024, ...)");
    return side;
}

namespace {
// An empty --device would be a substring of every device's name and pick the first one silently.
std::string device_flag(const Args& args)
{
    if (args.has("--device") && args.get("--device", "").empty())
        throw Error("bad value for --device: '' (expected a device index or part of its name; texfilter info lists "
                    "them)");
    return args.get("--device", "");
}
} // namespace

bool validate_from_environment()
{
    const char* env = std::getenv("TEXFILTER_VALIDATE");
    const std::string value = env ? env : "";
    if (value.empty() || value == "0")
        return false;
    if (value == "1")
        return true;
    throw Error("TEXFILTER_VALIDATE='" + value + "' is neither 1 (the Vulkan validation layers on, as --validate) nor "
                "0 or empty (off)");
}

ContextOptions context_options_from(const Args& args)
{
    ContextOptions options;
    options.device = device_flag(args);
    options.validate = args.has("--validate") || validate_from_environment();
    return options;
}

Backend backend_from(const Args& args, bool peer)
{
    std::string name = args.get("--backend", "vulkan");
    if (name == "vulkan")
        return Backend::vulkan;
    if (name == "reference")
        return Backend::reference;
    if (name == "oiio" && peer)
        return Backend::oiio;
    throw Error("bad value for --backend: '" + name + "' (expected vulkan" + (peer ? ", reference or oiio)" : " or reference)"));
}

CommandDevice open_command_device(Backend backend, const Args& args)
{
    CommandDevice device;
    device_flag(args); // checked on the reference backend too, which opens no device
    if (backend == Backend::vulkan) {
        device.gpu = std::make_unique<GpuSession>(context_options_from(args));
        device.limits = device_limits(device.gpu->context.info);
    }
    return device;
}

void check_validation_clean()
{
    if (int n = validation_message_count(); n > 0)
        throw Error(std::to_string(n) + " Vulkan validation message(s) reported (printed above); no output written");
}

GpuSession::GpuSession(const ContextOptions& options) : context(create_context(options)) {}

GpuSession::~GpuSession() { destroy_context(context); }

void GpuSession::finish()
{
    destroy_context(context);
    check_validation_clean();
}

} // namespace tf
