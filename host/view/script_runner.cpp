// texfilter view --script: the actions of host/view/script.h applied to the viewer between frames.
#include "view/viewer.h"
#include "texture/error.h"
#include <thread>

namespace tf {

namespace {

// A problem the script goes on after: shown in the UI, as a dropped file's would be, and on stderr.
void report(Viewer& v, const ScriptAction& a, const std::string& problem, const char* kept)
{
    if (problem.empty())
        return;
    v.controls.message = problem;
    std::fprintf(stderr, "texfilter view: %s:%d: %s (%s)\n", v.options.script_name.c_str(), a.line, problem.c_str(),
                 kept);
}

// The actions that change the ViewState, applied as the UI applies them. False: not one of them.
bool run_state_action(Viewer& v, const ScriptAction& a)
{
    const std::string& verb = a.verb;
    ViewState next = v.state;
    if (verb == "scene") {
        next.scene = script_scene(a);
        v.controls.camera_set = false;
    } else if (verb == "texture") {
        next.texture = script_texture(a);
        next.texture.build = v.state.texture.build; // built where the viewer's --build says
        next.texture.memory_budget = v.state.texture.memory_budget;
    } else if (verb == "filter") {
        next.a.options = script_sampler(a);
    } else if (verb == "compare") {
        if (script_off(a))
            next.b.reset();
        else
            next.b = ViewHalf{script_sampler(a)};
        v.controls.truth = false;
    } else if (verb == "truth") {
        v.controls.truth = !script_off(a);
        if (!v.controls.truth)
            next.b.reset();
    } else if (verb == "view") {
        next.view = script_word(a);
    } else if (verb == "stage") {
        next.render.stage = script_stage(a);
    } else if (verb == "derivatives") {
        next.render.gradients = script_gradients(a);
    } else if (verb == "frame") {
        next.frame = script_count(a);
    } else {
        return false;
    }
    report(v, a, problem_of([&] { apply_state(v, next); }), "the previous texture is kept");
    return true;
}

// The window's actions and the script's own pacing. False: not one of them.
bool run_window_action(Viewer& v, const ScriptAction& a, ScriptRun& run)
{
    const std::string& verb = a.verb;
    if (verb == "resize") {
        auto [width, height] = script_size(a);
        set_window_size(*v.window, width, height);
        run.wait_frames = 2; // the window system answers between frames
    } else if (verb == "wait") {
        run.wait_frames = script_count(a);
    } else if (verb == "hold") {
        run.hold_until = std::chrono::steady_clock::now() + std::chrono::milliseconds(script_count(a));
    } else if (verb == "screenshot" || verb == "screenshot-ui") {
        screenshot(v, script_path(a), verb == "screenshot-ui");
    } else if (verb == "quit") {
        v.quit = true;
    } else if (verb == "close") {
        request_close(*v.window);
        run.wait_frames = 1;
    } else if (verb == "minimize") {
        iconify(*v.window);
        run.wait_frames = 2;
    } else if (verb == "restore") {
        restore(*v.window);
        run.wait_frames = 2;
    } else {
        return false;
    }
    return true;
}

void run_camera_action(Viewer& v, const ScriptAction& a)
{
    const SceneParams scene = current_scene(v);
    const Camera c = v.controls.camera_set ? v.controls.camera : camera_of(scene);
    const std::string how = script_word(a);
    if (how == "reset") {
        v.controls.camera_set = false;
    } else {
        if (how == "set") {
            v.controls.camera = script_camera_pose(a);
        } else {
            const std::vector<double> m = script_camera_motion(a);
            v.controls.camera = how == "fly"  ? fly(c, scene, {m[0], m[1], m[2]})
                                : how == "turn" ? turn(c, m[0], m[1])
                                                : orbit(c, scene, look_target(scene), m[0], m[1]);
        }
        v.controls.camera_set = true;
    }
    scene_changed(v);
}

// What is shown and how it moves: the camera, the animations, the divider, the loupe, the cursor, the UI.
// False: not one of them.
bool run_display_action(Viewer& v, const ScriptAction& a)
{
    const std::string& verb = a.verb;
    if (verb == "camera") {
        run_camera_action(v, a);
    } else if (verb == "animate") {
        v.controls.animate = !script_off(a);
    } else if (verb == "texture-animate") {
        v.controls.texture_animate = !script_off(a);
        if (v.controls.texture_animate && !rebuilt_on_device(v.state.texture))
            report(v, a,
                   "texture-animate: only the dynamic texture with --build gpu animates (the texture is " +
                       v.state.texture.name_or_path + ", built on the " + to_string(v.state.texture.build) + ")",
                   "it stays as it is");
    } else if (verb == "texture-frame") {
        report(v, a, problem_of([&] { set_viewer_texture_frame(v, script_count(a)); }), "the frame is unchanged");
    } else if (verb == "divider") {
        v.state.divider = float(script_divider(a));
    } else if (verb == "loupe") {
        v.controls.loupe = !script_off(a);
        if (v.controls.loupe) {
            const std::array<int, 3> l = script_loupe(a);
            v.controls.loupe_center = {l[0], l[1]};
            v.controls.loupe_zoom = l[2];
        }
    } else if (verb == "cursor") {
        const std::array<int, 2> c = script_cursor(a);
        v.controls.cursor = {c[0], c[1]};
    } else if (verb == "ui") {
        v.controls.ui = !script_off(a);
    } else {
        return false;
    }
    return true;
}

// The words were checked when the script was read; the typed getters of view/script.h read them.
void run_action(Viewer& v, const ScriptAction& a, ScriptRun& run)
{
    if (!run_state_action(v, a) && !run_window_action(v, a, run) && !run_display_action(v, a))
        throw Error("unknown action '" + a.verb + "'");
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
