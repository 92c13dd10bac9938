#include "view/view_state.h"
#include "core/procedural.h"
#include "scene/camera.h"
#include "flags/args.h"
#include "flags/cli_common.h"
#include "texture/error.h"
#include "io/text_file.h"
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <sstream>
#include <nlohmann/json.hpp>

namespace tf {

SceneKind parse_viewer_scene(const std::string& name)
{
    const SceneKind kind = parse_scene(name);
    if (is_environment_scene(kind))
        throw Error("scene " + name + ": the viewer shows the 2D scenes; render the environment scenes with texfilter "
                    "render --scene " + name);
    return kind;
}

namespace {

using nlohmann::json;

std::string format_float(double value) // %.9g: every float comes back the same from strtod
{
    char text[32];
    std::snprintf(text, sizeof(text), "%.9g", value);
    return text;
}

// Every sampler flag of sampler_options_from but --filter (first, always) and --backend (the viewer's is
// Vulkan): its value written the way the flag reads it (which filters read it: core/filter.h's table).
struct SamplerFlag {
    const char* flag;
    std::string (*value)(const SamplerOptions&);
};

const SamplerFlag kSamplerFlags[] = {
    {"--wrap", [](const SamplerOptions& o) { return to_string(o.wrap); }},
    {"--aniso", [](const SamplerOptions& o) { return std::to_string(o.aniso); }},
    {"--band", [](const SamplerOptions& o) { return format_float(o.band); }},
    {"--probes", [](const SamplerOptions& o) { return std::to_string(o.probes); }},
    {"--aniso-shape", [](const SamplerOptions& o) { return to_string(o.aniso_shape); }},
    {"--taps", [](const SamplerOptions& o) { return to_string(o.taps); }},
    {"--magnify", [](const SamplerOptions& o) { return to_string(o.magnify); }},
    {"--alpha", [](const SamplerOptions& o) { return format_float(o.alpha); }},
    {"--max-aniso", [](const SamplerOptions& o) { return format_float(o.max_aniso); }},
    {"--boxes", [](const SamplerOptions& o) { return std::to_string(o.boxes); }},
    {"--pixel-filter", [](const SamplerOptions& o) { return to_string(o.pixel_filter); }},
    {"--spp", [](const SamplerOptions& o) { return std::to_string(o.truth_side * o.truth_side); }},
    {"--lod-bias", [](const SamplerOptions& o) { return format_float(o.lod_bias); }},
    {"--lod-min", [](const SamplerOptions& o) { return format_float(o.lod_min); }},
    {"--lod-max", [](const SamplerOptions& o) { return format_float(o.lod_max); }},
};

const char* const kDebugViews[] = {"color", "lod", "anisotropy", "fetches", "error"};

std::string png_suffixed_path(const std::string& png_path, const std::string& suffix) // shot.png -> shot-b.png
{
    const size_t slash = png_path.find_last_of('/');
    const size_t dot = png_path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return png_path + suffix;
    return png_path.substr(0, dot) + suffix + png_path.substr(dot);
}

std::string png_b_path(const std::string& png_path) { return png_suffixed_path(png_path, "-b"); }

// ---------------------------------------------------------------------------------------------------
// Reading: each field checked where it is, the message naming the file and the field.

struct Reader {
    const std::string& name;

    [[noreturn]] void fail(const std::string& field, const std::string& what) const
    {
        throw Error(name + ": " + field + ": " + what);
    }
    const json& member(const json& object, const std::string& field, const std::string& key) const
    {
        auto it = object.find(key);
        if (it == object.end())
            fail(field, "missing");
        return *it;
    }
    std::string string(const json& value, const std::string& field) const
    {
        if (!value.is_string())
            fail(field, "expected a string, got " + value.dump());
        return value.get<std::string>();
    }
    double number(const json& value, const std::string& field) const
    {
        if (!value.is_number())
            fail(field, "expected a number, got " + value.dump());
        return value.get<double>();
    }
    int integer(const json& value, const std::string& field, int min, int max) const
    {
        if (!value.is_number_integer() || value.get<long long>() < min || value.get<long long>() > max)
            fail(field, "expected a whole number in " + std::to_string(min) + ".." + std::to_string(max) + ", got " +
                            value.dump());
        return int(value.get<long long>());
    }
    void only(const json& object, const std::string& field, std::initializer_list<const char*> keys) const
    {
        if (!object.is_object())
            fail(field, "expected an object, got " + object.dump());
        for (auto it = object.begin(); it != object.end(); ++it) {
            bool known = false;
            for (const char* k : keys)
                known = known || it.key() == k;
            if (!known)
                fail(field.empty() ? it.key() : field + "." + it.key(), "unknown field");
        }
    }
    // `parse` run on `value`, its tf::Error put under the field's name.
    template <typename Parse>
    auto parsed(const std::string& field, Parse parse) const
    {
        try {
            return parse();
        } catch (const Error& e) {
            fail(field, e.what());
        }
    }
};

// A flag's value from JSON: strings as they are, whole numbers in decimal, other numbers to the last digit.
std::string flag_text(const Reader& reader, const json& value, const std::string& field)
{
    if (value.is_string())
        return value.get<std::string>();
    if (value.is_number_integer())
        return std::to_string(value.get<long long>());
    if (value.is_number()) {
        char text[40];
        std::snprintf(text, sizeof(text), "%.17g", value.get<double>());
        return text;
    }
    reader.fail(field, "expected a string or a number, got " + value.dump());
}

std::string json_key(const char* flag) { return std::string(flag).substr(2); } // "--lod-bias" -> "lod-bias"

SamplerOptions read_half(const Reader& reader, const json& object, const std::string& field)
{
    if (!object.is_object())
        reader.fail(field, "expected an object, got " + object.dump());
    // The CLI's own parser checks every value: first the filter alone, then each flag with it (so that a
    // message names its field), then all together (--lod-min above --lod-max). A half keeps every filter's
    // options (the keys change the filter), so none is refused for being unread by this one.
    const SamplerFlagUse kept{.keep_unread = true};
    Args args;
    args.command = field;
    args.values["--filter"] = reader.string(reader.member(object, field + ".filter", "filter"), field + ".filter");
    reader.parsed(field + ".filter", [&] { return sampler_options_from(args, kept); });
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (it.key() == "filter")
            continue;
        const SamplerFlag* spec = nullptr;
        for (const SamplerFlag& f : kSamplerFlags)
            if (json_key(f.flag) == it.key())
                spec = &f;
        const std::string key = field + "." + it.key();
        if (!spec)
            reader.fail(key, "unknown field");
        Args one;
        one.command = key;
        one.values["--filter"] = args.values["--filter"];
        one.values[spec->flag] = flag_text(reader, it.value(), key);
        reader.parsed(key, [&] { return sampler_options_from(one, kept); });
        args.values[spec->flag] = one.values[spec->flag];
    }
    return reader.parsed(field, [&] { return sampler_options_from(args, kept); });
}

json write_half(const SamplerOptions& o)
{
    json half = {{"filter", to_string(o.filter)},
                 {"wrap", to_string(o.wrap)},
                 {"aniso", o.aniso},
                 {"band", double(o.band)},
                 {"probes", o.probes},
                 {"aniso-shape", to_string(o.aniso_shape)},
                 {"taps", to_string(o.taps)},
                 {"alpha", double(o.alpha)},
                 {"max-aniso", double(o.max_aniso)},
                 {"boxes", o.boxes},
                 {"pixel-filter", to_string(o.pixel_filter)},
                 {"spp", o.truth_side * o.truth_side},
                 {"lod-bias", double(o.lod_bias)},
                 {"lod-min", double(o.lod_min)},
                 {"lod-max", double(o.lod_max)}};
    return half;
}

} // namespace

const std::vector<std::string>& debug_view_names()
{
    static const std::vector<std::string> names(std::begin(kDebugViews), std::end(kDebugViews));
    return names;
}

std::string check_debug_view(const std::string& name)
{
    for (const char* v : kDebugViews)
        if (name == v)
            return name;
    throw Error("unknown view '" + name + "' (expected color, lod, anisotropy, fetches or error)");
}

std::string shell_quote(const std::string& word)
{
    bool safe = !word.empty();
    for (char c : word)
        safe = safe && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                        std::string("_-+=./:,@%").find(c) != std::string::npos);
    if (safe)
        return word;
    std::string quoted = "'";
    for (char c : word)
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

std::vector<std::string> sampler_flag_words(const SamplerOptions& options, bool lod_view)
{
    // The flags the filter reads, each with its value, and no other: render refuses a flag its filter does not
    // read. The LOD view shows --lod-* on every filter that makes a lookup (render --view lod takes them).
    std::vector<std::string> words = {"--filter", to_string(options.filter)};
    for (const SamplerFlag& f : kSamplerFlags)
        if (filter_reads(options.filter, f.flag, options.stochastic) ||
            (lod_view && is_lod_flag(f.flag) && !is_scene_level(options.filter)))
            words.insert(words.end(), {f.flag, f.value(options)});
    return words;
}

std::vector<std::string> render_flag_words(const ViewState& state, const ViewHalf& half)
{
    const TextureSource defaults;
    std::vector<std::string> words = {"--scene", to_string(state.scene), "--texture", state.texture.name_or_path};
    if (is_procedural(state.texture.name_or_path) || state.texture.procedural_size != defaults.procedural_size)
        words.insert(words.end(), {"--texture-size", std::to_string(state.texture.procedural_size)});
    if (state.texture.color == ColorSpace::linear)
        words.push_back("--linear");
    if (state.texture.memory_budget != 0)
        words.insert(words.end(), {"--memory-budget", std::to_string(state.texture.memory_budget)});
    if (state.texture.build == TextureBuild::gpu)
        words.insert(words.end(), {"--build", "gpu"});
    if (is_dynamic_texture(state.texture)) // the frame shown: the viewer animates it
        words.insert(words.end(), {"--texture-frame", std::to_string(state.texture.texture_frame)});
    const Filter f = half.options.filter;
    const bool view_written = state.view != "color" && state.view != "error" && f != Filter::ground_truth &&
                              f != Filter::none;
    const std::vector<std::string> sampler = sampler_flag_words(half.options, view_written && state.view == "lod");
    words.insert(words.end(), sampler.begin(), sampler.end());
    words.insert(words.end(), {"--size", std::to_string(state.width) + "x" + std::to_string(state.height), "--stage",
                               to_string(state.render.stage), "--derivatives", to_string(state.render.gradients)});
    if (!state.camera.empty())
        words.insert(words.end(), {"--camera", state.camera});
    if (state.frame != 0)
        words.insert(words.end(), {"--frame", std::to_string(state.frame)});
    // The debug views are the harness's; the error view is the viewer's own (A against the truth, below), and
    // the ground truth and none have no view but colour.
    if (view_written)
        words.insert(words.end(), {"--view", state.view});
    return words;
}

ViewHalf truth_half(const ViewHalf& a)
{
    ViewHalf t;
    t.options.filter = Filter::ground_truth;
    t.options.wrap = a.options.wrap;
    t.options.truth_side = a.options.truth_side; // A's --spp and --pixel-filter choose the truth's
    t.options.pixel_filter = a.options.pixel_filter;
    return t;
}

std::vector<std::string> render_command_lines(const ViewState& state, const std::string& png_path)
{
    auto line = [&](const ViewHalf& half, const std::string& out) {
        std::string text = "texfilter render";
        for (const std::string& word : render_flag_words(state, half))
            text += " " + shell_quote(word);
        return text + " -o " + shell_quote(out);
    };
    std::vector<std::string> lines = {line(state.a, png_path)};
    if (state.b)
        lines.push_back(line(*state.b, png_b_path(png_path)));
    if (state.view == "error") // the heat map's other input: the ground truth it measures A against
        lines.push_back(line(truth_half(state.a), png_suffixed_path(png_path, "-truth")));
    return lines;
}

std::string state_to_json(const ViewState& state)
{
    json j = {{"scene", to_string(state.scene)},
              {"texture",
               {{"name", state.texture.name_or_path},
                {"size", state.texture.procedural_size},
                {"linear", state.texture.color == ColorSpace::linear},
                {"memory-budget", state.texture.memory_budget},
                {"build", to_string(state.texture.build)},
                {"frame", state.texture.texture_frame}}},
              {"render", {{"stage", to_string(state.render.stage)}, {"derivatives", to_string(state.render.gradients)}}},
              {"width", state.width},
              {"height", state.height},
              {"a", write_half(state.a.options)},
              {"b", state.b ? write_half(state.b->options) : json(nullptr)},
              {"divider", double(state.divider)},
              {"camera", state.camera},
              {"frame", state.frame},
              {"view", state.view}};
    return j.dump(2) + "\n";
}

namespace {

// The state's "texture" object.
TextureSource read_texture(const Reader& r, const json& texture)
{
    TextureSource t;
    r.only(texture, "texture", {"name", "size", "linear", "memory-budget", "build", "frame"});
    t.name_or_path = r.string(r.member(texture, "texture.name", "name"), "texture.name");
    if (t.name_or_path.empty())
        r.fail("texture.name", "empty (a procedural name or an image file)");
    if (texture.contains("size"))
        t.procedural_size = r.integer(texture["size"], "texture.size", 1, max_texture_dimension);
    if (texture.contains("linear")) {
        if (!texture["linear"].is_boolean())
            r.fail("texture.linear", "expected true or false, got " + texture["linear"].dump());
        t.color = texture["linear"].get<bool>() ? ColorSpace::linear : ColorSpace::automatic;
    }
    if (texture.contains("build"))
        t.build = r.parsed("texture.build",
                                   [&] { return parse_texture_build(r.string(texture["build"], "texture.build")); });
    if (texture.contains("frame")) {
        t.texture_frame = r.integer(texture["frame"], "texture.frame", 0, max_texture_frame);
        if (t.texture_frame != 0 && !is_dynamic_texture(t))
            r.fail("texture.frame", "only the dynamic texture has frames (the texture is " + t.name_or_path + ")");
    }
    if (texture.contains("memory-budget")) {
        const json& budget = texture["memory-budget"];
        if (!budget.is_number_unsigned() && !(budget.is_number_integer() && budget.get<long long>() >= 0))
            r.fail("texture.memory-budget", "expected a whole number of bytes (0: the default), got " + budget.dump());
        t.memory_budget = budget.get<uint64_t>();
    }
    return t;
}

// The state's "render" object: the stage and derivatives `scene` allows.
RenderOptions read_render(const Reader& r, const json& render, SceneKind scene)
{
    r.only(render, "render", {"stage", "derivatives"});
    const Stage stage = r.parsed("render.stage", [&] {
        return parse_stage(render.contains("stage") ? r.string(render["stage"], "render.stage") : "fragment");
    });
    const Gradients gradients = r.parsed("render.derivatives", [&] {
        return parse_gradients(render.contains("derivatives") ? r.string(render["derivatives"], "render.derivatives")
                                                              : "fine");
    });
    return r.parsed("render", [&] { return make_render_options(scene, stage, gradients); });
}

} // namespace

ViewState state_from_json(const std::string& text, const std::string& name)
{
    json j;
    try {
        j = json::parse(text);
    } catch (const json::parse_error& e) {
        throw Error(name + ": not valid JSON: " + e.what());
    }
    const Reader r{name};
    if (!j.is_object())
        throw Error(name + ": expected a JSON object (a saved viewer state), got " + j.dump().substr(0, 40));
    r.only(j, "", {"scene", "texture", "render", "width", "height", "a", "b", "divider", "camera", "frame", "view"});

    ViewState s;
    s.scene = r.parsed("scene", [&] { return parse_viewer_scene(r.string(r.member(j, "scene", "scene"), "scene")); });

    const json& texture = r.member(j, "texture", "texture");
    s.texture = read_texture(r, texture);

    const json& render = r.member(j, "render", "render");
    s.render = read_render(r, render, s.scene);

    // Sides as `texfilter render --size` takes them, so that the saved frame can be rendered again.
    s.width = r.integer(r.member(j, "width", "width"), "width", 2, 8192);
    s.height = r.integer(r.member(j, "height", "height"), "height", 2, 8192);
    if (s.width % 2 || s.height % 2)
        r.fail(s.width % 2 ? "width" : "height", "must be even (derivatives come from 2x2 quads)");

    s.a.options = read_half(r, r.member(j, "a", "a"), "a");
    if (j.contains("b") && !j["b"].is_null())
        s.b = ViewHalf{read_half(r, j["b"], "b")};
    if (j.contains("divider")) {
        const double divider = r.number(j["divider"], "divider");
        if (!(divider >= 0.0 && divider <= 1.0))
            r.fail("divider", "expected a number in 0..1, got " + j["divider"].dump());
        s.divider = float(divider);
    }
    if (j.contains("camera")) {
        s.camera = r.string(j["camera"], "camera");
        if (!s.camera.empty())
            r.parsed("camera", [&] { return parse_camera(s.camera); });
    }
    if (j.contains("frame"))
        s.frame = r.integer(j["frame"], "frame", 0, 1 << 30);
    if (j.contains("view"))
        s.view = r.parsed("view", [&] { return check_debug_view(r.string(j["view"], "view")); });
    return s;
}

ViewState read_state_file(const std::string& path)
{
    constexpr uint64_t max_state_bytes = 1u << 20; // a screenshot's state is about a kilobyte
    return state_from_json(read_text_file(path, max_state_bytes, "the viewer state"), path);
}

} // namespace tf
