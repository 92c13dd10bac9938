#pragma once
// What the viewer shows, as plain data: scene, texture, render options, window size, filter A and the
// optional filter B of split view, the camera and the debug view. It is saved beside a screenshot (JSON,
// `texfilter view --state FILE` loads it back) and turned into the `texfilter render` command lines that
// reproduce the frame offscreen.
//
// Use:     ViewState s; s.texture.name_or_path = "checker"; s.a.options.filter = Filter::ewa;
//          for (const std::string& line : render_command_lines(s, "shot.png")) ...; // shot.png, shot-b.png
//          ViewState back = state_from_json(state_to_json(s), "shot.json");
// Options: a flag goes on the command line when the half's filter reads it (core/filter.h's table; its exact
//          value, floats %.9g so they round-trip), and no other (render refuses a flag its filter does not
//          read); with the LOD view, --lod-* as well (it shows them); the ground truth's sample range
//          (truth_first, truth_count) is the viewer's progressive state and never written: the line renders
//          the whole grid, what the accumulation converges to. The dynamic texture's line always names its
//          frame (--texture-frame N, JSON texture.frame): the viewer animates it.
// Cost:    string building; no device, no files.
#include "core/filter.h"
#include "io/texture_source.h"
#include "scene/scene.h"
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace tf {

struct ViewHalf {
    SamplerOptions options; // filter A or B
};

struct ViewState {
    SceneKind scene = SceneKind::plane;
    TextureSource texture;
    RenderOptions render;
    int width = 1280, height = 720;
    ViewHalf a;
    std::optional<ViewHalf> b; // split view
    float divider = 0.5f;      // where A ends, 0..1 of the width
    std::string camera;        // "" = the scene's own; else to_string(tf::Camera), "X,Y,Z,YAW,PITCH"
    int frame = 0;             // the benchmark camera path's frame
    std::string view = "color"; // another engineer adds DebugView; kept a string here
};

// `texfilter render --scene ... -o PNG` for A, and with B a second line writing PNG's stem + "-b" (shot.png ->
// shot-b.png), each word shell-quoted where it needs it. The error view adds the ground truth it measures A
// against (truth_half, PNG's stem + "-truth"); its heat map itself has no render of its own.
std::vector<std::string> render_command_lines(const ViewState& state, const std::string& png_path);

// The ground truth the error view (and truth mode) measures `a` against: a's wrap, samples (--spp) and pixel
// filter.
ViewHalf truth_half(const ViewHalf& a);

// The render flags (without "texfilter render" and -o) of one half, as separate words, unquoted.
std::vector<std::string> render_flag_words(const ViewState& state, const ViewHalf& half);

// The sampler flags of `options` as words ("--filter", "ewa", "--alpha", "2", ...): see Options above.
// lod_view: the line renders --view lod.
std::vector<std::string> sampler_flag_words(const SamplerOptions& options, bool lod_view);

// One word for a POSIX shell: as it is when it holds only safe characters, else in single quotes.
std::string shell_quote(const std::string& word);

// The debug views by name (color, lod, anisotropy, fetches, error); check_debug_view returns `name` or
// throws tf::Error listing them.
// parse_scene for the viewer: the 2D scenes only (the environment scenes, skybox and reflect, render with
// `texfilter render`); throws tf::Error naming the scene.
SceneKind parse_viewer_scene(const std::string& name);

const std::vector<std::string>& debug_view_names();
std::string check_debug_view(const std::string& name);


// JSON through nlohmann-json. state_from_json checks every field (the sampler options with the CLI's own
// parser) and throws tf::Error naming `name` and the field ("shot.json: a.band: ...").
std::string state_to_json(const ViewState& state);
ViewState state_from_json(const std::string& text, const std::string& name);
// state_from_json of a file (`texfilter view --state FILE`; read_text_file: a regular file of at most 1 MiB); a
// file that cannot be read is an error naming it.
ViewState read_state_file(const std::string& path);

} // namespace tf
