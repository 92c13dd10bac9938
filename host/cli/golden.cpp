#include "cli/golden.h"
#include "core/analytic_texture.h"
#include "flags/cli_common.h"
#include "io/text_file.h"
#include "texture/error.h"
#include <cctype>
#include <cstdlib>
#include <sstream>

namespace tf {

namespace {

// A case's name is a file name (--golden-dir/NAME.png, --out's actual/NAME.png), never a path: letters, digits
// and . _ + - (the manifest's names use all of them), starting with a letter or digit, so never hidden or "..".
bool plain_case_name(const std::string& name)
{
    if (name.empty() || name.size() > max_case_name || !std::isalnum(static_cast<unsigned char>(name[0])))
        return false;
    for (unsigned char ch : name)
        if (!std::isalnum(ch) && ch != '.' && ch != '_' && ch != '+' && ch != '-')
            return false;
    return true;
}

} // namespace

std::vector<GoldenCase> read_manifest(const std::string& path)
{
    constexpr uint64_t max_manifest_bytes = 16u << 20; // the project's is 18 KiB for about 200 cases
    std::istringstream in(read_text_file(path, max_manifest_bytes, "the golden manifest"));
    return parse_manifest(in, path);
}

std::vector<GoldenCase> parse_manifest(std::istream& in, const std::string& path)
{
    // A case's options are the render command's flags written key=value, so both share one parser.
    const std::vector<FlagSpec> specs = join({{{"--scene", "S", ""}, {"--size", "WxH", ""}, {"--fail", "X", ""},
                                               {"--stage", "S", ""}, {"--derivatives", "D", ""},
                                               {"--failpercent", "P", ""}, {"--hardfail", "H", ""}},
                                              texture_flags(),
                                              sampler_flags(SamplerFlags::scenes)});
    std::vector<GoldenCase> cases;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (size_t hash = line.find('#'); hash != std::string::npos)
            line.resize(hash);
        std::stringstream tokens(line);
        std::vector<std::string> words;
        for (std::string w; tokens >> w;)
            words.push_back(w);
        if (words.empty())
            continue;
        std::string where = path + ":" + std::to_string(number);
        if (words.size() < 4)
            throw Error(where + ": expected NAME SCENE TEXTURE FILTER [key=value ...]");
        std::vector<std::string> argv = {"--scene", words[1], "--texture", words[2], "--filter", words[3]};
        for (size_t i = 4; i < words.size(); ++i) {
            if (words[i].find('=') == std::string::npos)
                throw Error(where + ": expected key=value, got '" + words[i] + "'");
            argv.push_back("--" + words[i]);
        }
        if (!plain_case_name(words[0]))
            throw Error(where + ": case name '" + words[0] + "' is not a plain file name (up to " +
                        std::to_string(max_case_name) + " letters, digits and . _ + -, starting with a letter or digit)");
        GoldenCase c;
        c.name = words[0];
        try {
            Args args = parse_args("manifest", argv, specs, 0);
            c.scene = parse_flag(args, "--scene", "", parse_scene);
            c.texture = texture_source_from(args);
            SamplerFlagUse use;
            use.environment = is_environment_scene(c.scene);
            c.sampler = sampler_options_from(args, use);
            check_env_flag(args, {c.scene}, "scene " + to_string(c.scene));
            if (is_environment_scene(c.scene))
                check_environment_truth(c.sampler);
            resolve_analytic_truth(c.sampler, c.texture.name_or_path); // truth=analytic: the texture's function
            check_format_filter(c.texture.format, c.sampler);
            c.render = make_render_options(c.scene, parse_flag(args, "--stage", "fragment", parse_stage),
                                           parse_flag(args, "--derivatives", "fine", parse_gradients));
            std::tie(c.width, c.height) = parse_size("size", args.get("--size", "256x256"), 2, 4096);
            c.thresholds.fail = args.get_double("--fail", c.thresholds.fail, 0.0, 1.0);
            c.thresholds.fail_percent = args.get_double("--failpercent", c.thresholds.fail_percent, 0.0, 100.0);
            c.thresholds.hard_fail = args.get_double("--hardfail", c.thresholds.hard_fail, 0.0, 1.0);
        } catch (const Error& e) {
            throw Error(where + ": " + e.what());
        }
        for (const GoldenCase& other : cases)
            if (other.name == c.name)
                throw Error(where + ": case name '" + c.name + "' used twice");
        cases.push_back(c);
    }
    return cases;
}


} // namespace tf
