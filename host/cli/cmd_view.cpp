#include "cli/commands.h"
#include "flags/cli_common.h"
#include "io/output_path.h"
#include "texture/error.h"
#include <cstdio>
#include <filesystem>

#if TEXFILTER_VIEWER
#include "view/screenshot_files.h"
#include "view/script.h"
#include "view/viewer.h"
#endif

namespace tf {

#if TEXFILTER_VIEWER
namespace {

std::string parent_directory(const std::string& path)
{
    const std::string parent = std::filesystem::path(path).parent_path().string();
    return parent.empty() ? "." : parent;
}

} // namespace
#endif

int run_view(const std::vector<std::string>& argv)
{
    std::vector<FlagSpec> specs = join(
        {{{"--scene", "S", scene_names() + " (default plane)"}},
         texture_flags(),
         sampler_flags(SamplerFlags::scenes),
         {{"--compare", "F", "filter B, shown right of a draggable divider (its options: set them in the UI or the "
                             "script's `compare F [flags]`)"},
          {"--size", "WxH", "window and scene size (default 1280x720)"},
          {"--stage", "S", "fragment (default) or compute"},
          {"--derivatives", "D", "fine (default), coarse, ray or cone"},
          {"--script", "FILE", "run the actions in FILE in the window, one a line (docs/VIEWER.md), then exit"},
          {"--state", "FILE", "start from a state a screenshot wrote (its .json)"},
          {"--frame-log", "FILE", "write every frame's times as CSV when the viewer ends (the viewer benchmark)"},
          {"--no-preview", "", "render every frame at full size, also while the camera moves (the benchmark's baseline)"}},
         device_flags()});
    Args args = parse_args("view", argv, specs, 0);
    if (args.has("--help")) {
        std::fputs(format_help("texfilter view [--scene S] [--texture T|PATH] [--filter F] [--compare F2] "
                               "[--size WxH] [--device D] [--script FILE] [--state FILE]",
                               specs)
                       .c_str(),
                   stdout);
        return 0;
    }
#if !TEXFILTER_VIEWER
    throw Error("the viewer was left out of this build (configure with -DTEXFILTER_VIEWER=ON; it needs GLFW and "
                "Dear ImGui: tools/setup.sh)");
#else
    check_env_flag(args, {}, "view, which shows the 2D scenes only");
    ViewOptions options;
    ViewState& s = options.state;
    if (args.has("--state")) {
        s = read_state_file(args.get("--state", ""));
        options.inputs.push_back(args.get("--state", ""));
    }
    if (args.has("--scene") || !args.has("--state"))
        s.scene = parse_flag(args, "--scene", "plane", parse_viewer_scene);
    if (args.has("--texture") || !args.has("--state")) {
        std::vector<std::string> texture_argv = {"--texture", args.get("--texture", "checker")};
        s.texture = texture_source_from(args.has("--texture") ? args : parse_args("view", texture_argv, texture_flags(), 0));
        if (!args.has("--texture"))
            s.texture.procedural_size = args.get_int("--texture-size", 256, 1, max_texture_dimension);
    }
    if (args.has("--filter") || !args.has("--state")) {
        Args filter_args = args;
        if (!args.has("--filter"))
            filter_args = parse_args("view", {"--filter", "trilinear"}, sampler_flags(SamplerFlags::scenes), 0);
        // Every filter's flags are kept: the keys and the compare half change the filter at run time.
        s.a.options = sampler_options_from(filter_args, {.keep_unread = true});
        check_viewer_sampler(s.a.options);
    }
    if (args.has("--compare")) {
        SamplerOptions b = s.a.options;
        b.filter = parse_flag(args, "--compare", "", parse_filter);
        s.b = ViewHalf{b};
    }
    if (args.has("--size") || !args.has("--state")) {
        auto [width, height] = parse_size("--size", args.get("--size", "1280x720"), 2, 8192);
        s.width = width;
        s.height = height;
    }
    if (args.has("--stage") || args.has("--derivatives") || !args.has("--state"))
        s.render = make_render_options(s.scene, parse_flag(args, "--stage", to_string(s.render.stage), parse_stage),
                                       parse_flag(args, "--derivatives", to_string(s.render.gradients), parse_gradients));
    options.device = context_options_from(args);
    if (args.has("--script")) {
        options.script_name = args.get("--script", "");
        options.script = read_script(options.script_name); // every line checked before the window opens
        options.inputs.push_back(options.script_name);
        std::vector<std::string> inputs = options.inputs;
        inputs.push_back(s.texture.name_or_path);
        for (const ScriptAction& action : options.script) // and where its screenshots go: none onto an input
            if (action.verb == "screenshot" || action.verb == "screenshot-ui") {
                const std::string where = options.script_name + ":" + std::to_string(action.line) + ": " + action.verb;
                check_writable_directory(parent_directory(script_path(action)), where);
                try {
                    checked_screenshot_paths(script_path(action), action.verb == "screenshot-ui", inputs);
                } catch (const Error& e) {
                    throw Error(where + ": " + e.what());
                }
            }
    }
    options.preview = !args.has("--no-preview");
    if (args.has("--frame-log"))
        options.frame_log = checked_output_path(args.get("--frame-log", ""), {".csv"}, options.inputs);
    return run_viewer(options);
#endif
}

} // namespace tf
