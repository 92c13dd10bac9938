// texfilter view --script: the actions of host/view/script.h applied to the viewer between frames.
#include "view/viewer.h"
#include "flags/args.h"
#include "flags/cli_common.h"
#include "texture/error.h"
#include <thread>

namespace tf {

namespace {

double number(const std::string& word) { return std::stod(word); } // the script parser checked every word

// "filter F --flag value ...": the render command's own flag parser, so the script means what the CLI means.
SamplerOptions filter_options(const ScriptAction& action)
{
    std::vector<std::string> argv = {"--filter", action.words.at(0)};
    argv.insert(argv.end(), action.words.begin() + 1, action.words.end());
    Args args = parse_args("view script", argv, sampler_flags(SamplerFlags::scenes), 0);
    return sampler_options_from(args);
}

void run_action(Viewer& v, const ScriptAction& a, ScriptRun& run)
{
    const std::string& verb = a.verb;
    const std::vector<std::string>& w = a.words;
    ViewState next = v.state;
    auto apply = [&] {
        std::string problem = apply_state(v, next);
        if (!problem.empty()) { // shown in the UI, as a dropped file's would be; the script goes on
            v.controls.message = problem;
            std::fprintf(stderr, "texfilter view: %s:%d: %s (the previous texture is kept)\n",
                         v.options.script_name.c_str(), a.line, problem.c_str());
        }
    };
    if (verb == "scene") {
        next.scene = parse_scene(w[0]);
        v.controls.camera_set = false;
        apply();
    } else if (verb == "texture") {
        next.texture.name_or_path = w[0];
        for (size_t i = 1; i < w.size(); ++i) {
            if (w[i] == "--texture-size")
                next.texture.procedural_size = std::stoi(w[++i]);
            else if (w[i] == "--linear")
                next.texture.color = ColorSpace::linear;
        }
        apply();
    } else if (verb == "filter") {
        next.a.options = filter_options(a);
        apply();
    } else if (verb == "compare") {
        if (w[0] == "off")
            next.b.reset();
        else
            next.b = ViewHalf{filter_options(a)};
        v.controls.truth = false;
        apply();
    } else if (verb == "truth") {
        v.controls.truth = w[0] == "on";
        if (!v.controls.truth)
            next.b.reset();
        apply();
    } else if (verb == "view") {
        next.view = w[0];
        apply();
    } else if (verb == "stage") {
        next.render.stage = parse_stage(w[0]);
        apply();
    } else if (verb == "derivatives") {
        next.render.gradients = parse_gradients(w[0]);
        apply();
    } else if (verb == "resize") {
        auto [width, height] = parse_size("resize", w[0], 2, 8192);
        set_window_size(*v.window, width, height);
        run.wait_frames = 2; // the window system answers between frames
    } else if (verb == "wait") {
        run.wait_frames = std::stoi(w[0]);
    } else if (verb == "hold") {
        run.hold_until = std::chrono::steady_clock::now() + std::chrono::milliseconds(std::stoi(w[0]));
    } else if (verb == "screenshot" || verb == "screenshot-ui") {
        screenshot(v, w[0], verb == "screenshot-ui");
    } else if (verb == "quit") {
        v.quit = true;
    } else if (verb == "close") {
        request_close(*v.window);
        run.wait_frames = 1;
    } else if (verb == "camera") {
        const SceneParams scene = current_scene(v);
        Camera c = v.controls.camera_set ? v.controls.camera : camera_of(scene);
        if (w[0] == "reset") {
            v.controls.camera_set = false;
        } else {
            if (w[0] == "set")
                c = parse_camera(w[1]);
            else if (w[0] == "fly")
                c = fly(c, scene, {number(w[1]), number(w[2]), number(w[3])});
            else if (w[0] == "turn")
                c = turn(c, number(w[1]), number(w[2]));
            else if (w[0] == "orbit")
                c = orbit(c, scene, look_target(scene), number(w[1]), number(w[2]));
            v.controls.camera = c;
            v.controls.camera_set = true;
        }
        scene_changed(v);
    } else if (verb == "animate") {
        v.controls.animate = w[0] == "on";
    } else if (verb == "frame") {
        next.frame = std::stoi(w[0]);
        apply();
    } else if (verb == "divider") {
        v.state.divider = float(number(w[0]));
    } else if (verb == "loupe") {
        v.controls.loupe = w[0] != "off";
        if (v.controls.loupe) {
            v.controls.loupe_center = {std::stoi(w[0]), std::stoi(w[1])};
            v.controls.loupe_zoom = std::stoi(w[2]);
        }
    } else if (verb == "cursor") {
        v.controls.cursor = {std::stoi(w[0]), std::stoi(w[1])};
    } else if (verb == "ui") {
        v.controls.ui = w[0] == "on";
    } else if (verb == "minimize") {
        iconify(*v.window);
        run.wait_frames = 2;
    } else if (verb == "restore") {
        restore(*v.window);
        run.wait_frames = 2;
    } else {
        throw Error(v.options.script_name + ":" + std::to_string(a.line) + ": unknown action '" + verb + "'");
    }
}

} // namespace

bool run_script_step(Viewer& v, ScriptRun& run)
{
    if (std::chrono::steady_clock::now() < run.hold_until)
        return true;
    // `wait N`: the frame drawn right after the action is the first of the N.
    if (run.wait_frames > 0 && --run.wait_frames > 0)
        return true;
    while (run.next < v.options.script.size() && run.wait_frames == 0 && !v.quit &&
           std::chrono::steady_clock::now() >= run.hold_until) {
        const ScriptAction& action = v.options.script[run.next++];
        try {
            run_action(v, action, run);
        } catch (const Error& e) {
            throw Error(v.options.script_name + ":" + std::to_string(action.line) + ": " + e.what());
        }
    }
    return run.next < v.options.script.size() || run.wait_frames > 0 || v.quit ||
           std::chrono::steady_clock::now() < run.hold_until;
}

} // namespace tf
