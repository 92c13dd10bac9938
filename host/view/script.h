#pragma once
// `texfilter view --script FILE`: the viewer's scripted mode, a contract that scripts outside the project
// use. One action a line, words split on spaces and tabs (no quoting: paths cannot hold spaces); a line
// whose first word starts with '#' is a comment, as is the rest of a line from a word starting with '#';
// blank lines are skipped. The whole file is checked before the window opens: the first bad line is a
// tf::Error "FILE:LINE: what is wrong". Filter flags are checked by the code `texfilter render` uses.
//
// Actions:
//   scene S                          texture T|PATH [--texture-size N] [--linear]
//   filter F [render's filter flags] compare F [flags] | compare off
//   resize WxH (even sides, 2..8192) wait N (frames, 0..100000)       hold MS (0..60000: present, no change)
//   screenshot PATH.png              screenshot-ui PATH.png            quit (the last action)
//   camera reset | camera set X,Y,Z,YAW,PITCH | camera fly DX DY DZ | camera turn YAW PITCH | camera orbit YAW PITCH
//   animate on|off  frame N (0..2^30)  view color|lod|anisotropy|fetches|error  truth on|off  divider F (0..1)
//   loupe X Y ZOOM (pixels >= 0, zoom 1..64) | loupe off   cursor X Y   minimize   restore
//   close (as the window's close button; the last action)   ui on|off (the panels)
//   stage fragment|compute           derivatives fine|coarse|ray
//   texture-animate on|off (the dynamic texture's frames)   texture-frame N (0..1000000, the dynamic texture)
//
// Use:     for (const ScriptAction& a : read_script(path)) if (a.verb == "filter") set_a(script_sampler(a)); ...
// Cost:    reads the file once; the typed helpers re-parse one action's words (microseconds). They are for
//          actions parse_script accepted and throw tf::Error (naming the line) when called on another verb.
#include "core/filter.h"
#include "io/texture_source.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tf {

struct ScriptAction {
    int line = 0;                   // 1-based, in the script
    std::string verb;               // the first word: "filter", "camera", ...
    std::vector<std::string> words; // the words after it
};

// Parses and checks a whole script; `name` stands for the file in messages.
std::vector<ScriptAction> parse_script(const std::string& text, const std::string& name);
// parse_script of a file (read_text_file: a regular file of at most 16 MiB); one that cannot be read is an
// error naming it.
std::vector<ScriptAction> read_script(const std::string& path);

// Typed values of one checked action.
SceneKind script_scene(const ScriptAction& action);                 // scene
TextureSource script_texture(const ScriptAction& action);           // texture
SamplerOptions script_sampler(const ScriptAction& action);          // filter, compare F
bool script_off(const ScriptAction& action);                        // compare/loupe/animate/texture-animate/truth/ui: "off"
std::pair<int, int> script_size(const ScriptAction& action);        // resize
int script_count(const ScriptAction& action);                       // wait, hold, frame, texture-frame
std::string script_path(const ScriptAction& action);                // screenshot, screenshot-ui
std::string script_word(const ScriptAction& action);                // view, stage, derivatives, camera's sub-verb
Stage script_stage(const ScriptAction& action);                     // stage
Gradients script_gradients(const ScriptAction& action);             // derivatives
double script_divider(const ScriptAction& action);                  // divider
Camera script_camera_pose(const ScriptAction& action);              // camera set X,Y,Z,YAW,PITCH (parse_camera)
std::vector<double> script_camera_motion(const ScriptAction& action); // camera fly (3), turn and orbit (2)
std::array<int, 3> script_loupe(const ScriptAction& action);        // loupe X Y ZOOM (not off)
std::array<int, 2> script_cursor(const ScriptAction& action);       // cursor X Y

} // namespace tf
