// The viewer's state (host/view/view_state.h): the `texfilter render` command lines of a frame parse back,
// through the CLI's own sampler_options_from, to the very options the viewer had (every filter, every
// option, floats to the last bit); the words survive a real shell; a line runs `texfilter render`; the
// JSON state round-trips and every bad field is an error naming the file and the field.
#include "support.h"
#include "flags/args.h"
#include "flags/cli_common.h"
#include "core/procedural.h"
#include "view/view_state.h"
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>

using namespace tf;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// What `texfilter render` accepts, plus the flags other engineers add for the viewer (--camera, --frame,
// --view): the words after "texfilter render" must all be among them.
Args parse_render_line(const std::string& line)
{
    std::vector<std::string> words = test::shell_words(line);
    if (words.size() < 2 || words[0] != "texfilter" || words[1] != "render")
        throw Error("not a texfilter render line: " + line);
    words.erase(words.begin(), words.begin() + 2);
    const std::vector<FlagSpec> specs = join({{{"--scene", "S", ""}},
                                              texture_flags(),
                                              sampler_flags(SamplerFlags::scenes),
                                              {{"--size", "WxH", ""},
                                               {"--stage", "S", ""},
                                               {"--derivatives", "D", ""},
                                               {"--camera", "C", ""},
                                               {"--frame", "N", ""},
                                               {"--view", "V", ""},
                                               {"-o", "OUT", ""}}});
    return parse_args("render", words, specs, 0);
}

// "" when every field the command line carries is equal (bit for bit for floats), else the first that is not.
std::string option_difference(const SamplerOptions& a, const SamplerOptions& b)
{
    auto bits = [](float f) { return std::bit_cast<uint32_t>(f); };
    if (a.filter != b.filter) return "filter";
    if (a.wrap != b.wrap) return "wrap";
    if (bits(a.lod_bias) != bits(b.lod_bias)) return "lod_bias";
    if (bits(a.lod_min) != bits(b.lod_min)) return "lod_min";
    if (bits(a.lod_max) != bits(b.lod_max)) return "lod_max";
    if (a.aniso != b.aniso) return "aniso";
    if (bits(a.band) != bits(b.band)) return "band";
    if (a.probes != b.probes) return "probes";
    if (a.aniso_shape != b.aniso_shape) return "aniso_shape";
    if (a.taps != b.taps) return "taps";
    if (bits(a.alpha) != bits(b.alpha)) return "alpha";
    if (bits(a.max_aniso) != bits(b.max_aniso)) return "max_aniso";
    if (a.boxes != b.boxes) return "boxes";
    if (a.pixel_filter != b.pixel_filter) return "pixel_filter";
    if (a.truth_side != b.truth_side) return "truth_side";
    return "";
}

// Floats that need all 9 digits (%g would print them as the float next door).
float odd(float f) { return std::nextafter(f, 1000.0f); }

// One change to every option, each away from its default, inside the CLI's bounds.
// Each option changed, with the flag that carries it.
struct Change {
    const char* what;
    const char* flag;
    std::function<void(SamplerOptions&)> apply;
};
const std::vector<Change> kChanges = {
    {"wrap", "--wrap", [](SamplerOptions& o) { o.wrap = Wrap::mirror; }},
    {"lod_bias", "--lod-bias", [](SamplerOptions& o) { o.lod_bias = odd(-1.3f); }},
    {"lod_min", "--lod-min", [](SamplerOptions& o) { o.lod_min = odd(0.3f); }},
    {"lod_max", "--lod-max", [](SamplerOptions& o) { o.lod_max = odd(7.7f); }},
    {"aniso", "--aniso", [](SamplerOptions& o) { o.aniso = 7; }},
    {"band", "--band", [](SamplerOptions& o) { o.band = odd(0.3f); }},
    {"probes", "--probes", [](SamplerOptions& o) { o.probes = 5; }},
    {"aniso_shape", "--aniso-shape", [](SamplerOptions& o) { o.aniso_shape = AnisoShape::feline; }},
    {"taps", "--taps", [](SamplerOptions& o) { o.taps = Taps::hardware; }},
    {"alpha", "--alpha", [](SamplerOptions& o) { o.alpha = odd(2.5f); }},
    {"max_aniso", "--max-aniso", [](SamplerOptions& o) { o.max_aniso = odd(9.9f); }},
    {"boxes", "--boxes", [](SamplerOptions& o) { o.boxes = 3; }},
    {"pixel_filter", "--pixel-filter", [](SamplerOptions& o) { o.pixel_filter = PixelFilter::gaussian; }},
    {"truth_side", "--spp", [](SamplerOptions& o) { o.truth_side = 7; }},
};

std::vector<Filter> every_filter()
{
    std::vector<Filter> filters = all_filters();
    filters.push_back(Filter::ground_truth);
    filters.push_back(Filter::none);
    return filters;
}

ViewState example_state()
{
    ViewState s;
    s.scene = SceneKind::slanted;
    s.texture.name_or_path = "zoneplate";
    s.texture.procedural_size = 128;
    s.render = make_render_options(s.scene, Stage::compute, Gradients::ray);
    s.width = 640;
    s.height = 360;
    s.a.options.filter = Filter::ewa;
    s.a.options.alpha = odd(3.1f);
    s.b = ViewHalf{};
    s.b->options.filter = Filter::aniso;
    s.b->options.probes = 8;
    s.divider = odd(0.4f);
    s.camera = "1.5,-2,0.25,90,-10";
    s.frame = 17;
    s.view = "lod";
    return s;
}

// The tf::Error message of state_from_json(text), "" if it was accepted.
std::string json_error(const std::string& text)
{
    try {
        state_from_json(text, "saved.json");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

// example_state()'s JSON with `from` replaced by `to` (the first occurrence; it must be there).
std::string edited(const std::string& from, const std::string& to)
{
    std::string text = state_to_json(example_state());
    const size_t at = text.find(from);
    if (at == std::string::npos)
        throw Error("test: '" + from + "' is not in the state's JSON");
    return text.replace(at, from.size(), to);
}

// The JSON of example_state() after `change` (values the struct can hold but a saved state must not).
std::string changed(const std::function<void(ViewState&)>& change)
{
    ViewState s = example_state();
    change(s);
    return state_to_json(s);
}

} // namespace

TEST_SUITE_BEGIN("reference");

// 1. Every filter with every option at its default, all changed at once, and each changed alone: the
//    command line's flags, read back by sampler_options_from, give the options the filter reads bit for bit;
//    the others are left off the line (render refuses a flag its filter does not read) and read back as their
//    defaults.
TEST_CASE("command-line-round-trip")
{
    int lines = 0;
    for (Filter filter : every_filter()) {
        struct Variant {
            std::string what;
            SamplerOptions options, expected;
        };
        std::vector<Variant> variants;
        SamplerOptions base;
        base.filter = filter;
        variants.push_back({"defaults", base, base});
        Variant all{"every option changed", base, base};
        for (const Change& change : kChanges) {
            change.apply(all.options);
            if (filter_reads(filter, change.flag, false))
                change.apply(all.expected);
        }
        variants.push_back(all);
        for (const Change& change : kChanges) {
            Variant one{change.what, base, base};
            change.apply(one.options);
            if (filter_reads(filter, change.flag, false))
                change.apply(one.expected);
            variants.push_back(one);
        }
        for (const Variant& v : variants) {
            ViewState state;
            state.texture.name_or_path = "checker";
            state.a.options = v.options;
            state.a.options.truth_first = 3; // the viewer's progress: never on the line
            state.a.options.truth_count = 5;
            const std::vector<std::string> command = render_command_lines(state, "shot.png");
            CHECK_EQ(command.size(), 1);
            const Args args = parse_render_line(command.at(0));
            const SamplerOptions back = sampler_options_from(args);
            const std::string difference = option_difference(back, v.expected);
            CHECK(difference.empty(), to_string(filter) + ", " + v.what + ": " + difference + " differs in\n" + command[0]);
            CHECK(back.truth_first == 0 && back.truth_count == 0);
            ++lines;
        }
    }
    std::printf("  %d command lines parsed back to their options\n", lines);
    CHECK_EQ(lines, int(every_filter().size() * (kChanges.size() + 2)));
}

// 2. The rest of the line: scene, texture, size, stage, derivatives, camera, frame, view and the output;
//    split view gives B's line writing PATH's stem + "-b".
TEST_CASE("command-line-fields")
{
    const ViewState s = example_state();
    const std::vector<std::string> lines = render_command_lines(s, "out.d/shot.png");
    CHECK_EQ(lines.size(), 2);
    if (lines.size() != 2)
        return;
    const Args a = parse_render_line(lines[0]), b = parse_render_line(lines[1]);
    CHECK(a.get("--scene", "") == "slanted" && a.get("--texture", "") == "zoneplate" &&
              a.get("--texture-size", "") == "128" && a.get("--size", "") == "640x360" &&
              a.get("--stage", "") == "compute" && a.get("--derivatives", "") == "ray",
          lines[0]);
    CHECK(a.get("--camera", "") == s.camera && a.get("--frame", "") == "17" && a.get("--view", "") == "lod", lines[0]);
    CHECK(a.get("-o", "") == "out.d/shot.png" && b.get("-o", "") == "out.d/shot-b.png", lines[1]);
    CHECK(option_difference(sampler_options_from(b), s.b->options).empty(), lines[1]);
    CHECK(sampler_options_from(b).filter == Filter::aniso);
    CHECK(!a.has("--linear") && !a.has("--memory-budget"));

    // Defaults leave the optional flags out; a file texture has no --texture-size; --linear when linear.
    ViewState plain;
    plain.texture.name_or_path = "photos/brick wall.png";
    plain.texture.color = ColorSpace::linear;
    const std::string line = render_command_lines(plain, "shot")[0];
    const Args p = parse_render_line(line);
    CHECK(!p.has("--camera") && !p.has("--frame") && !p.has("--view") && !p.has("--texture-size"), line);
    CHECK(p.has("--linear") && p.get("--texture", "") == "photos/brick wall.png", line);
    CHECK_CONTAINS(line, "--texture 'photos/brick wall.png'", "--size 1280x720 --stage fragment --derivatives fine");
    plain.b = ViewHalf{};
    CHECK(parse_render_line(render_command_lines(plain, "shot")[1]).get("-o", "") == "shot-b");
}

// 3. shell_quote's words come back unchanged through /bin/sh (printf one a line).
TEST_CASE("shell-quoting")
{
    const std::vector<std::string> words = {"plain-word_1.png", "a b", "it's", "$HOME", "*", "", "x\"y",
                                            "back\\slash", "semi;colon", "tab\there", "~user", "a=b,c:d@e%f+g"};
    std::string command = "printf '%s\\n'";
    for (const std::string& w : words)
        command += " " + shell_quote(w);
    FILE* pipe = popen(command.c_str(), "r");
    CHECK(pipe != nullptr);
    if (!pipe)
        return;
    std::string output;
    char buffer[256];
    while (size_t n = std::fread(buffer, 1, sizeof(buffer), pipe))
        output.append(buffer, n);
    CHECK_EQ(pclose(pipe), 0);
    std::string expected;
    for (const std::string& w : words)
        expected += w + "\n";
    CHECK(output == expected, command + "\ngave\n" + output);
    CHECK(shell_quote("plain-word_1.png") == "plain-word_1.png"); // safe words stay unquoted
    CHECK(test::shell_words(shell_quote("it's a 'test'")) == std::vector<std::string>{"it's a 'test'"});
}

// 4. JSON: a state comes back field for field.
TEST_CASE("json-round-trip")
{
    for (bool split : {true, false}) {
        ViewState s = example_state();
        s.texture.color = ColorSpace::linear;
        s.texture.memory_budget = 123456789;
        for (const auto& change : kChanges)
            change.apply(s.a.options);
        if (!split)
            s.b.reset();
        const std::string text = state_to_json(s);
        const ViewState back = state_from_json(text, "round.json");
        CHECK(back.scene == s.scene && back.texture.name_or_path == s.texture.name_or_path &&
                  back.texture.procedural_size == s.texture.procedural_size && back.texture.color == s.texture.color &&
                  back.texture.memory_budget == s.texture.memory_budget,
              text);
        CHECK(back.render.stage == s.render.stage && back.render.gradients == s.render.gradients &&
                  back.render.rasterize == s.render.rasterize,
              text);
        CHECK(back.width == s.width && back.height == s.height && back.divider == s.divider, text);
        CHECK(back.camera == s.camera && back.frame == s.frame && back.view == s.view, text);
        CHECK(option_difference(back.a.options, s.a.options).empty(), option_difference(back.a.options, s.a.options));
        CHECK(back.b.has_value() == split);
        if (split && back.b)
            CHECK(option_difference(back.b->options, s.b->options).empty());
        // Written again, the same text: nothing is lost or reformatted on the way.
        CHECK(state_to_json(back) == text);
    }
    // The mesh scene is rasterized: its render options come back so.
    ViewState mesh;
    mesh.scene = SceneKind::mesh;
    mesh.texture.name_or_path = "checker";
    mesh.render = make_render_options(SceneKind::mesh, Stage::fragment, Gradients::fine);
    CHECK(state_from_json(state_to_json(mesh), "mesh.json").render.rasterize);
}

// 5. Bad JSON and bad values: each an error naming the file and the field.
TEST_CASE("json-errors")
{
    CHECK_CONTAINS(json_error("{\"scene\": "), "saved.json", "not valid JSON");
    CHECK_CONTAINS(json_error("[1, 2]"), "saved.json", "expected a JSON object");
    CHECK_CONTAINS(json_error(edited("\"scene\": \"slanted\"", "\"scene\": \"moon\"")), "saved.json",
                   "saved.json: scene: ");
    CHECK_CONTAINS(json_error(edited("\"scene\": \"slanted\"", "\"scene\": 3")), "saved.json",
                   "scene: expected a string");
    CHECK_CONTAINS(json_error(edited("\"scene\": \"slanted\",", "\"colour\": 1, \"scene\": \"slanted\",")),
                   "saved.json", "colour: unknown field");
    CHECK_CONTAINS(json_error(edited("\"name\": \"zoneplate\"", "\"name\": \"\"")), "saved.json",
                   "texture.name: empty");
    CHECK_CONTAINS(json_error(edited("\"size\": 128", "\"size\": 0")), "saved.json", "texture.size");
    CHECK_CONTAINS(json_error(edited("\"linear\": false", "\"linear\": \"no\"")), "saved.json", "texture.linear");
    CHECK_CONTAINS(json_error(edited("\"memory-budget\": 0", "\"memory-budget\": -5")), "saved.json",
                   "texture.memory-budget");
    CHECK_CONTAINS(json_error(edited("\"stage\": \"compute\"", "\"stage\": \"vertex\"")), "saved.json", "render.stage");
    CHECK_CONTAINS(json_error(edited("\"derivatives\": \"ray\"", "\"derivatives\": \"fast\"")), "saved.json",
                   "render.derivatives");
    CHECK_CONTAINS(json_error(edited("\"width\": 640", "\"width\": 641")), "saved.json", "width: must be even");
    CHECK_CONTAINS(json_error(edited("\"height\": 360", "\"height\": 9000")), "saved.json",
                   "height: expected a whole number in 2..8192");
    CHECK_CONTAINS(json_error(edited("\"height\": 360", "\"height\": 360.5")), "saved.json", "height");
    CHECK_CONTAINS(json_error(edited("\"filter\": \"ewa\"", "\"filter\": \"blurry\"")), "saved.json", "a.filter");
    CHECK_CONTAINS(json_error(changed([](ViewState& v) { v.a.options.alpha = 99.0f; })), "saved.json",
                   "a.alpha: bad value for --alpha");
    CHECK_CONTAINS(json_error(edited("\"band\": 0.25", "\"band\": \"wide\"")), "saved.json",
                   "a.band: bad value for --band");
    CHECK_CONTAINS(json_error(edited("\"band\": 0.25", "\"band\": true")), "saved.json",
                   "a.band: expected a string or a number");
    CHECK_CONTAINS(json_error(edited("\"spp\": 256", "\"spp\": 200")), "saved.json", "a.spp");
    CHECK_CONTAINS(json_error(edited("\"wrap\": \"repeat\"", "\"bogus\": 1, \"wrap\": \"repeat\"")), "saved.json",
                   "a.bogus: unknown field");
    CHECK_CONTAINS(json_error(changed([](ViewState& v) { v.a.options.lod_min = 5.0f, v.a.options.lod_max = 2.0f; })),
                   "saved.json", "saved.json: a: bad values: --lod-min 5 is above --lod-max 2");
    CHECK_CONTAINS(json_error(edited("\"filter\": \"aniso\"", "\"filter\": \"nope\"")), "saved.json", "b.filter");
    CHECK_CONTAINS(json_error(changed([](ViewState& v) { v.divider = 1.5f; })), "saved.json",
                   "divider: expected a number in 0..1");
    CHECK_CONTAINS(json_error(edited("\"camera\": \"1.5,-2,0.25,90,-10\"", "\"camera\": \"1,2\"")), "saved.json",
                   "camera: ");
    CHECK_CONTAINS(json_error(edited("\"frame\": 17", "\"frame\": -1")), "saved.json", "frame");
    CHECK_CONTAINS(json_error(edited("\"view\": \"lod\"", "\"view\": \"depth\"")), "saved.json",
                   "view: unknown view 'depth'");
    // Missing fields that have no default.
    CHECK_CONTAINS(json_error("{\"scene\": \"plane\"}"), "saved.json", "texture: missing");
    std::string no_a = state_to_json(example_state());
    no_a.replace(no_a.find("\"a\":"), 4, "\"z\":");
    CHECK_CONTAINS(json_error(no_a), "saved.json", "z: unknown field");
    // The mesh scene is rasterized in the fragment stage: compute is a conflict, named as render.
    CHECK_CONTAINS(json_error(edited("\"scene\": \"slanted\"", "\"scene\": \"mesh\"")), "saved.json", "render: ");
    // A file that cannot be read names its path.
    CHECK_THROWS_WITH(read_state_file("/nonexistent/state.json"), "/nonexistent/state.json: cannot open");
}

// 6. The dynamic texture: its frame is on the render line (--texture-frame, with --build gpu when the viewer
//    builds on the device), parses back through the CLI's texture_source_from, and round-trips through JSON;
//    any other texture has no frame, on the line, in the JSON and in texture_source_from.
TEST_CASE("dynamic-texture-frame")
{
    ViewState s = example_state();
    s.texture.name_or_path = "dynamic";
    s.texture.procedural_size = 512;
    s.texture.build = TextureBuild::gpu;
    s.texture.texture_frame = 12345;
    for (const std::string& line : render_command_lines(s, "shot.png")) { // A's and B's: the same texture
        const TextureSource back = texture_source_from(parse_render_line(line));
        CHECK(back.name_or_path == "dynamic" && back.texture_frame == 12345 && back.build == TextureBuild::gpu &&
                  back.procedural_size == 512,
              line);
    }
    s.texture.texture_frame = 0; // frame 0 too: the line says which frame it shows
    s.texture.build = TextureBuild::cpu;
    const std::string zero = render_command_lines(s, "shot.png")[0];
    CHECK(contains(zero, " --texture-frame 0 ") && !contains(zero, "--build"), zero);
    CHECK(!contains(render_command_lines(example_state(), "shot.png")[0], "--texture-frame"));

    s.texture.build = TextureBuild::gpu;
    s.texture.texture_frame = max_texture_frame;
    const std::string text = state_to_json(s);
    const ViewState back = state_from_json(text, "dynamic.json");
    CHECK(back.texture.texture_frame == max_texture_frame && back.texture.build == TextureBuild::gpu, text);
    CHECK(state_to_json(back) == text);
    auto json_refused = [&](const std::string& from, const std::string& to, const std::string& part) {
        std::string edited_text = text;
        const size_t at = edited_text.find(from);
        CHECK(at != std::string::npos, from);
        if (at == std::string::npos)
            return;
        const std::string message = json_error(edited_text.replace(at, from.size(), to));
        CHECK_CONTAINS(message, "saved.json: texture.frame: ", part);
    };
    json_refused("\"frame\": 1000000", "\"frame\": 1000001", "0..1000000");
    json_refused("\"frame\": 1000000", "\"frame\": -1", "0..1000000");
    json_refused("\"frame\": 1000000", "\"frame\": \"7\"", "expected a whole number");
    json_refused("\"name\": \"dynamic\"", "\"name\": \"grid\"", "only the dynamic texture has frames (the texture is grid)");

    auto source_error = [](std::vector<std::string> argv) {
        try {
            texture_source_from(parse_args("render", argv, texture_flags(), 0));
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    const std::string other = source_error({"--texture", "checker", "--texture-frame", "3"});
    CHECK_CONTAINS(other, "--texture-frame applies to --texture dynamic only", "'checker'");
    CHECK_CONTAINS(source_error({"--texture", "dynamic", "--texture-frame", "1000001"}), "--texture-frame");
    CHECK(source_error({"--texture", "dynamic", "--texture-frame", "1000000"}).empty());
}

// 7. What --texture-frame loads: dynamic_texture(size, N) as level 0, bit for bit, its host chain for a cpu
//    build and level 0 alone for a gpu build (the device builds the rest); frame 0 is make_procedural's. A
//    frame set on another texture (not through the CLI) is refused naming the texture.
TEST_CASE("dynamic-texture-load")
{
    TextureSource source;
    source.name_or_path = "dynamic";
    source.procedural_size = 24;
    source.texture_frame = 5;
    const Image expected = dynamic_texture(24, 5);
    auto same = [](const Image& a, const Image& b) {
        return a.width == b.width && a.height == b.height &&
               std::memcmp(a.texels.data(), b.texels.data(), a.texels.size() * sizeof(glm::vec4)) == 0;
    };
    const MipChain chain = load_texture(source);
    CHECK(chain.levels.size() == build_mip_chain(expected).levels.size());
    CHECK(same(chain.levels.at(0), expected));
    CHECK(same(chain.levels.back(), build_mip_chain(expected).levels.back()));
    TextureUse level0;
    level0.level0_only = true;
    const MipChain alone = load_texture(source, level0);
    CHECK(alone.levels.size() == 1);
    CHECK(same(alone.levels.at(0), expected));
    CHECK(!same(expected, dynamic_texture(24, 6))); // the frames differ, so the checks above can fail
    source.texture_frame = 0;
    CHECK(same(load_texture(source).levels.at(0), make_procedural("dynamic", 24).levels[0]));
    source.name_or_path = "noise";
    source.texture_frame = 2;
    CHECK_THROWS_WITH(load_texture(source), "texture noise: --texture-frame 2 applies to the dynamic procedural texture only");
}

TEST_SUITE_END();

TEST_SUITE_BEGIN("gpu");

// 8. A CLI test (the command lines the viewer prints are its contract): `texfilter render` accepts each
//    (A and B, an output path a shell must quote) and writes its PNG. Frames without --camera/--frame/--view,
//    which render does not take yet on its own.
TEST_CASE("command-lines-run")
{
    const std::filesystem::path work = test::make_work_dir("view-state");
    ViewState s;
    s.scene = SceneKind::zoom;
    s.texture.name_or_path = "checker";
    s.texture.procedural_size = 64;
    s.width = s.height = 64;
    s.a.options.filter = Filter::ewa;
    s.a.options.alpha = odd(2.5f);
    s.b = ViewHalf{};
    s.b->options.filter = Filter::brilinear;
    s.b->options.band = odd(0.3f);
    const std::string png = (work / "it's a shot.png").string();
    for (std::string line : render_command_lines(s, png)) {
        line.replace(0, std::string("texfilter").size(), shell_quote(test::texfilter_path()));
        const int status = std::system((line + " > /dev/null").c_str());
        CHECK_EQ(status, 0);
    }
    CHECK(std::filesystem::exists(png), png);
    CHECK(std::filesystem::exists(work / "it's a shot-b.png"));
}

TEST_SUITE_END();
