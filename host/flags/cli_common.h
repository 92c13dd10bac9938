#pragma once
// Flags and helpers shared by the CLI commands (render, sample, golden, info) and the viewer's script.
#include "flags/args.h"
#include "texture/error.h"
#include "core/filter.h"
#include "scene/scene.h"
#include "io/texture_source.h"
#include "vulkan/device.h"
#include <memory>
#include <vector>

namespace tf {

// oiio: OpenImageIO's TextureSystem as a peer (io/oiio_texture.h), `sample` only.
enum class Backend { vulkan, reference, oiio };

// The texture flags; `default_build` is what --build's help names as the command's default (only `build`
// defaults to the device's).
enum class BuildDefault { cpu, gpu };
std::vector<FlagSpec> texture_flags(BuildDefault default_build = BuildDefault::cpu);
// The filter flags: for one lookup (sample) or, with the ground-truth and none filters and their flags, for
// a scene's pixels (render, golden).
enum class SamplerFlags { lookups, scenes };
std::vector<FlagSpec> sampler_flags(SamplerFlags which);
// "plane, tunnel, ... or mesh": every scene, for --scene's help.
std::string scene_names();
std::vector<FlagSpec> device_flags();
std::vector<FlagSpec> join(std::vector<std::vector<FlagSpec>> groups);

// The texture flags. Refused before any device is opened: a --texture that is neither a procedural name nor a
// readable file (the message lists the names), --texture-size on a file, --linear on a procedural texture or a
// float file (.exr, .pfm, .hdr: linear already).
TextureSource texture_source_from(const Args& args);
// when = later: the file is checked when the texture loads (the viewer's script, whose screenshots may write
// the file a later line loads). For a command with texture flags of its own (bench): check_texture_name
// (io/texture_source.h), and --texture-size on a procedural texture only. Throw tf::Error.
enum class TextureCheck { now, later };
TextureSource texture_source_from(const Args& args, TextureCheck when);
void check_texture_size_flag(const Args& args, const std::string& name_or_path);

// Who reads the sampler flags besides the filter (core/filter.h's table): a flag that nothing reads is refused,
// naming the flag and the filters that read it (docs/CLI.md, "Flags a filter does not read").
struct SamplerFlagUse {
    // The viewer's command line and state files: its keys and its compare half change the filter at run time,
    // so every filter's flags are kept for later.
    bool keep_unread = false;
    bool lod_view = false;    // render --view lod|data, the viewer's script: the view shows the LOD --lod-* make
    bool truth_view = false;  // the viewer's script: the error view's ground truth reads --spp, --pixel-filter
    bool environment = false; // skybox, reflect: directions have no edges, so --wrap is read by nothing
};
SamplerOptions sampler_options_from(const Args& args, const SamplerFlagUse& use = {});
// What the viewer cannot show, pointing at render: --truth analytic (its ground truth integrates the texels,
// and its texture can change under it) and --stochastic (one deterministic frame a change). Throws tf::Error.
void check_viewer_sampler(const SamplerOptions& options);
// --spp: a square number of samples a pixel, 1..4096; returns the grid side. Throws naming what is wrong.
int parse_spp_side(const std::string& text);
// TEXFILTER_VALIDATE: unset, empty or 0 off, 1 on (as --validate); anything else is refused (tf::Error).
bool validate_from_environment();
ContextOptions context_options_from(const Args& args);
// --env is read on the environment scenes only: throws naming `where` ("--scene plane") when none of `scenes`
// is one.
void check_env_flag(const Args& args, const std::vector<SceneKind>& scenes, const std::string& where);
// --backend; oiio only where `peer` (sample), else refused as an unknown value.
Backend backend_from(const Args& args, bool peer = false);

// parse(value of flag), with the flag's name put in front of any error ("bad value for --filter: ...").
template <typename Parse>
auto parse_flag(const Args& args, const std::string& flag, const std::string& fallback, Parse parse)
{
    std::string value = fallback.empty() ? args.require(flag) : args.get(flag, fallback);
    try {
        return parse(value);
    } catch (const Error& e) {
        throw Error("bad value for " + flag + ": " + e.what());
    }
}

// A Vulkan context for one command. finish() destroys it and turns any validation message into an
// error, so a command can check before it writes its output file.
struct GpuSession {
    VulkanContext context;
    explicit GpuSession(const ContextOptions& options);
    ~GpuSession();
    void finish();
    GpuSession(const GpuSession&) = delete;
    GpuSession& operator=(const GpuSession&) = delete;
};

// The device of a command that can run on either backend: opened (with --backend vulkan) before the texture
// is loaded, so that load_texture checks the texture against the device's memory before decoding it.
struct CommandDevice {
    std::unique_ptr<GpuSession> gpu; // null with --backend reference
    DeviceLimits limits;
    TextureUse texture_use(bool sat) const
    {
        TextureUse use;
        use.sat = sat;
        use.device = gpu ? &limits : nullptr;
        return use;
    }
};
CommandDevice open_command_device(Backend backend, const Args& args);

// Throws tf::Error if the validation layers reported anything so far.
void check_validation_clean();

} // namespace tf
