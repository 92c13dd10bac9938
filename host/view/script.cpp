#include "view/script.h"
#include "scene/camera.h"
#include "core/numbers.h"
#include "flags/args.h"
#include "flags/cli_common.h"
#include "texture/error.h"
#include "io/text_file.h"
#include "view/view_state.h"
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>

namespace tf {

namespace {

// ---------------------------------------------------------------------------------------------------
// Word parsers: each throws tf::Error saying what is wrong (parse_script adds FILE:LINE and the verb).

void expect_words(const ScriptAction& a, size_t count, const char* form)
{
    if (a.words.size() != count)
        throw Error("expected '" + std::string(form) + "', got " + std::to_string(a.words.size()) + " word(s) after '" +
                    a.verb + "'");
}

// Numbers in core/numbers.h's grammar, as every flag writes them.
long whole(const std::string& text, long min, long max, const char* what)
{
    const std::optional<long long> value = parse_whole_number(text);
    if (!value || *value < min || *value > max)
        throw Error(std::string(what) + " '" + text + "' is not a whole number in " + std::to_string(min) + ".." +
                    std::to_string(max));
    return long(*value);
}

double number(const std::string& text, const char* what)
{
    const std::optional<double> value = parse_real_number(text);
    if (!value)
        throw Error(std::string(what) + " '" + text + "' is not a finite number");
    return *value;
}

bool on_off(const ScriptAction& a)
{
    expect_words(a, 1, "on|off");
    if (a.words[0] != "on" && a.words[0] != "off")
        throw Error("expected on or off, got '" + a.words[0] + "'");
    return a.words[0] == "on";
}

std::string png_path(const ScriptAction& a)
{
    expect_words(a, 1, "PATH.png");
    const std::string& path = a.words[0];
    if (path.size() < 5 || path.compare(path.size() - 4, 4, ".png") != 0)
        throw Error("'" + path + "' does not end in .png (screenshots are PNG files)");
    return path;
}

// `FLAG value` pairs and switches after the first word, with the flag prefixed by `first_flag`.
Args flag_args(const ScriptAction& a, const std::string& first_flag, const std::vector<FlagSpec>& specs)
{
    if (a.words.empty() || a.words[0].rfind("-", 0) == 0)
        throw Error("missing its first word before any flag (" + std::string(a.verb == "texture" ? "T|PATH" : "F") +
                    ")");
    std::vector<std::string> argv = {first_flag, a.words[0]};
    argv.insert(argv.end(), a.words.begin() + 1, a.words.end());
    return parse_args(a.verb, argv, specs, 0);
}

// render's filter flags, without --backend: the viewer draws with Vulkan.
std::vector<FlagSpec> script_sampler_flags()
{
    std::vector<FlagSpec> flags;
    for (const FlagSpec& f : sampler_flags(SamplerFlags::scenes))
        if (f.name != "--backend")
            flags.push_back(f);
    return flags;
}

SceneKind scene(const ScriptAction& a)
{
    expect_words(a, 1, "scene S");
    return parse_viewer_scene(a.words[0]);
}

std::string view_name(const ScriptAction& a)
{
    expect_words(a, 1, "view V");
    return check_debug_view(a.words[0]);
}

SamplerOptions sampler(const ScriptAction& a)
{
    // A line sets the whole half, so a flag its filter does not read is refused as render refuses it, but for
    // what the viewer's own views read: the LOD view (--lod-*) and the error view's truth (--spp, --pixel-filter).
    SamplerOptions options = sampler_options_from(flag_args(a, "--filter", script_sampler_flags()),
                                                  {.lod_view = true, .truth_view = true});
    check_viewer_sampler(options);
    return options;
}

TextureSource texture(const ScriptAction& a)
{
    std::vector<FlagSpec> specs;
    for (const FlagSpec& f : texture_flags())
        if (f.name == "--texture" || f.name == "--texture-size" || f.name == "--linear")
            specs.push_back(f);
    // The file is checked when the line runs: a screenshot line before it may write it.
    return texture_source_from(flag_args(a, "--texture", specs), TextureCheck::later);
}

std::pair<int, int> size(const ScriptAction& a)
{
    expect_words(a, 1, "resize WxH");
    auto [w, h] = parse_size("resize", a.words[0], 2, 8192);
    if (w % 2 || h % 2)
        throw Error("'" + a.words[0] + "': sides must be even (the frame's render command needs 2x2 quads)");
    return {w, h};
}

int count(const ScriptAction& a)
{
    if (a.verb == "wait") {
        expect_words(a, 1, "wait N");
        return int(whole(a.words[0], 0, 100000, "frames"));
    }
    if (a.verb == "hold") {
        expect_words(a, 1, "hold MS");
        return int(whole(a.words[0], 0, 60000, "milliseconds"));
    }
    if (a.verb == "texture-frame") {
        expect_words(a, 1, "texture-frame N");
        return int(whole(a.words[0], 0, max_texture_frame, "texture frame"));
    }
    expect_words(a, 1, "frame N");
    return int(whole(a.words[0], 0, 1L << 30, "frame"));
}

std::vector<double> numbers(const ScriptAction& a, size_t from, const char* what)
{
    std::vector<double> values;
    for (size_t i = from; i < a.words.size(); ++i)
        values.push_back(number(a.words[i], what));
    return values;
}

// camera reset | set X,Y,Z,YAW,PITCH | fly DX DY DZ | turn YAW PITCH | orbit YAW PITCH
void check_camera(const ScriptAction& a)
{
    if (a.words.empty())
        throw Error("expected reset, set, fly, turn or orbit after 'camera'");
    const std::string& how = a.words[0];
    auto arity = [&](size_t n, const char* form) {
        if (a.words.size() != n + 1)
            throw Error("expected '" + std::string(form) + "'");
    };
    if (how == "reset") {
        arity(0, "camera reset");
    } else if (how == "set") {
        arity(1, "camera set X,Y,Z,YAW,PITCH");
        parse_camera(a.words[1]);
    } else if (how == "fly") {
        arity(3, "camera fly DX DY DZ");
        numbers(a, 1, "distance");
    } else if (how == "turn" || how == "orbit") {
        arity(2, how == "turn" ? "camera turn YAW PITCH" : "camera orbit YAW PITCH");
        numbers(a, 1, "angle");
    } else {
        throw Error("unknown camera action '" + how + "' (expected reset, set, fly, turn or orbit)");
    }
}

std::array<int, 2> pixel(const ScriptAction& a, size_t from)
{
    return {int(whole(a.words[from], 0, 65535, "pixel x")), int(whole(a.words[from + 1], 0, 65535, "pixel y"))};
}

std::array<int, 3> loupe(const ScriptAction& a)
{
    expect_words(a, 3, "loupe X Y ZOOM");
    const std::array<int, 2> at = pixel(a, 0);
    return {at[0], at[1], int(whole(a.words[2], 1, 64, "zoom"))};
}

std::array<int, 2> cursor(const ScriptAction& a)
{
    expect_words(a, 2, "cursor X Y");
    return pixel(a, 0);
}

double divider(const ScriptAction& a)
{
    expect_words(a, 1, "divider F");
    const double f = number(a.words[0], "divider");
    if (f < 0.0 || f > 1.0)
        throw Error("'" + a.words[0] + "' is outside 0..1 (the divider's place across the window)");
    return f;
}

std::string one_of(const ScriptAction& a, std::initializer_list<const char*> names)
{
    std::string list;
    for (const char* n : names)
        list += std::string(list.empty() ? "" : "|") + n;
    expect_words(a, 1, (a.verb + " " + list).c_str());
    for (const char* n : names)
        if (a.words[0] == n)
            return n;
    throw Error("expected " + list + ", got '" + a.words[0] + "'");
}

// Every verb and the check of its words.
struct Verb {
    const char* name;
    void (*check)(const ScriptAction&);
};

const Verb kVerbs[] = {
    {"scene", [](const ScriptAction& a) { scene(a); }},
    {"texture", [](const ScriptAction& a) { texture(a); }},
    {"filter", [](const ScriptAction& a) { sampler(a); }},
    {"compare", [](const ScriptAction& a) { if (!(a.words.size() == 1 && a.words[0] == "off")) sampler(a); }},
    {"resize", [](const ScriptAction& a) { size(a); }},
    {"wait", [](const ScriptAction& a) { count(a); }},
    {"hold", [](const ScriptAction& a) { count(a); }},
    {"frame", [](const ScriptAction& a) { count(a); }},
    {"screenshot", [](const ScriptAction& a) { png_path(a); }},
    {"screenshot-ui", [](const ScriptAction& a) { png_path(a); }},
    {"quit", [](const ScriptAction& a) { expect_words(a, 0, "quit"); }},
    {"camera", check_camera},
    {"animate", [](const ScriptAction& a) { on_off(a); }},
    {"texture-animate", [](const ScriptAction& a) { on_off(a); }},
    {"texture-frame", [](const ScriptAction& a) { count(a); }},
    {"truth", [](const ScriptAction& a) { on_off(a); }},
    {"view", [](const ScriptAction& a) { view_name(a); }},
    {"divider", [](const ScriptAction& a) { divider(a); }},
    {"loupe", [](const ScriptAction& a) { if (!(a.words.size() == 1 && a.words[0] == "off")) loupe(a); }},
    {"cursor", [](const ScriptAction& a) { cursor(a); }},
    {"minimize", [](const ScriptAction& a) { expect_words(a, 0, "minimize"); }},
    {"restore", [](const ScriptAction& a) { expect_words(a, 0, "restore"); }},
    {"close", [](const ScriptAction& a) { expect_words(a, 0, "close"); }},
    {"ui", [](const ScriptAction& a) { on_off(a); }},
    {"stage", [](const ScriptAction& a) { parse_stage(one_of(a, {"fragment", "compute"})); }},
    {"derivatives", [](const ScriptAction& a) { parse_gradients(one_of(a, {"fine", "coarse", "ray"})); }},
};

std::string verb_list()
{
    std::string list;
    for (const Verb& v : kVerbs)
        list += std::string(list.empty() ? "" : ", ") + v.name;
    return list;
}

// A typed helper's value, or an error naming the line when the action is another verb.
void require_verb(const ScriptAction& a, std::initializer_list<const char*> verbs, const char* helper)
{
    for (const char* v : verbs)
        if (a.verb == v)
            return;
    throw Error("script line " + std::to_string(a.line) + ": " + helper + " does not apply to '" + a.verb + "'");
}

template <typename Parse>
auto at_line(const ScriptAction& a, Parse parse)
{
    try {
        return parse();
    } catch (const Error& e) {
        throw Error("script line " + std::to_string(a.line) + ": " + a.verb + ": " + e.what());
    }
}

} // namespace

std::vector<ScriptAction> parse_script(const std::string& text, const std::string& name)
{
    std::vector<ScriptAction> actions;
    std::istringstream in(text);
    std::string line;
    int quit_line = 0;
    std::string quit_verb;
    for (int number = 1; std::getline(in, line); ++number) {
        ScriptAction action;
        action.line = number;
        std::istringstream tokens(line); // spaces, tabs and a trailing '\r' all split words
        for (std::string word; tokens >> word;) {
            if (word[0] == '#')
                break;
            if (action.verb.empty())
                action.verb = word;
            else
                action.words.push_back(word);
        }
        if (action.verb.empty())
            continue;
        const std::string where = name + ":" + std::to_string(number) + ": ";
        if (quit_line)
            throw Error(where + "'" + action.verb + "' after " + quit_verb + " (line " + std::to_string(quit_line) +
                        ") would never run");
        const Verb* verb = nullptr;
        for (const Verb& v : kVerbs)
            if (action.verb == v.name)
                verb = &v;
        if (!verb)
            throw Error(where + "unknown action '" + action.verb + "' (expected " + verb_list() + ")");
        try {
            verb->check(action);
        } catch (const Error& e) {
            throw Error(where + action.verb + ": " + e.what());
        }
        if (action.verb == "quit" || action.verb == "close") {
            quit_line = number;
            quit_verb = action.verb;
        }
        actions.push_back(std::move(action));
    }
    return actions;
}

std::vector<ScriptAction> read_script(const std::string& path)
{
    constexpr uint64_t max_script_bytes = 16u << 20; // hundreds of thousands of lines
    return parse_script(read_text_file(path, max_script_bytes, "the script"), path);
}

SceneKind script_scene(const ScriptAction& a)
{
    require_verb(a, {"scene"}, "script_scene");
    return at_line(a, [&] { return scene(a); });
}

TextureSource script_texture(const ScriptAction& a)
{
    require_verb(a, {"texture"}, "script_texture");
    return at_line(a, [&] { return texture(a); });
}

SamplerOptions script_sampler(const ScriptAction& a)
{
    require_verb(a, {"filter", "compare"}, "script_sampler");
    return at_line(a, [&] { return sampler(a); });
}

bool script_off(const ScriptAction& a)
{
    require_verb(a, {"compare", "loupe", "animate", "texture-animate", "truth", "ui"}, "script_off");
    return a.words.size() == 1 && a.words[0] == "off";
}

std::pair<int, int> script_size(const ScriptAction& a)
{
    require_verb(a, {"resize"}, "script_size");
    return at_line(a, [&] { return size(a); });
}

int script_count(const ScriptAction& a)
{
    require_verb(a, {"wait", "hold", "frame", "texture-frame"}, "script_count");
    return at_line(a, [&] { return count(a); });
}

std::string script_path(const ScriptAction& a)
{
    require_verb(a, {"screenshot", "screenshot-ui"}, "script_path");
    return at_line(a, [&] { return png_path(a); });
}

std::string script_word(const ScriptAction& a)
{
    require_verb(a, {"view", "stage", "derivatives", "camera"}, "script_word");
    return at_line(a, [&] {
        if (a.words.empty())
            throw Error("no word after '" + a.verb + "'");
        return a.words[0];
    });
}

Stage script_stage(const ScriptAction& a)
{
    require_verb(a, {"stage"}, "script_stage");
    return at_line(a, [&] { return parse_stage(one_of(a, {"fragment", "compute"})); });
}

Gradients script_gradients(const ScriptAction& a)
{
    require_verb(a, {"derivatives"}, "script_gradients");
    return at_line(a, [&] { return parse_gradients(one_of(a, {"fine", "coarse", "ray"})); });
}

double script_divider(const ScriptAction& a)
{
    require_verb(a, {"divider"}, "script_divider");
    return at_line(a, [&] { return divider(a); });
}

Camera script_camera_pose(const ScriptAction& a)
{
    require_verb(a, {"camera"}, "script_camera_pose");
    return at_line(a, [&] {
        if (a.words.size() != 2 || a.words[0] != "set")
            throw Error("not 'camera set X,Y,Z,YAW,PITCH'");
        return parse_camera(a.words[1]);
    });
}

std::vector<double> script_camera_motion(const ScriptAction& a)
{
    require_verb(a, {"camera"}, "script_camera_motion");
    return at_line(a, [&] {
        check_camera(a);
        if (a.words[0] != "fly" && a.words[0] != "turn" && a.words[0] != "orbit")
            throw Error("not 'camera fly', 'camera turn' or 'camera orbit'");
        return numbers(a, 1, "value");
    });
}

std::array<int, 3> script_loupe(const ScriptAction& a)
{
    require_verb(a, {"loupe"}, "script_loupe");
    return at_line(a, [&] { return loupe(a); });
}

std::array<int, 2> script_cursor(const ScriptAction& a)
{
    require_verb(a, {"cursor"}, "script_cursor");
    return at_line(a, [&] { return cursor(a); });
}

} // namespace tf
