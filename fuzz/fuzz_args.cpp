// libFuzzer target: the command-line parser (host/flags/args.cpp) and the option helpers the commands share
// (host/flags/cli_common.cpp: texture, sampler, backend, device), with `render`'s flags. The input is argv:
// tokens separated by NUL bytes, after one byte giving how many positional arguments are allowed.
// Asserts: only tf::Error escapes; accepted flags are declared ones, each once; values parsed from them
// are in the ranges the commands document; sizes are within their bounds.
#include "flags/args.h"
#include "flags/cli_common.h"
#include "texture/error.h"
#include "fuzz_common.h"

#include <cstdint>

namespace {

const std::vector<tf::FlagSpec>& specs()
{
    static const std::vector<tf::FlagSpec> all =
        tf::join({{{"--scene", "S", ""}, {"--size", "WxH", ""}, {"-o", "OUT", ""}, {"--stats", "", ""}},
                  tf::texture_flags(), tf::sampler_flags(tf::SamplerFlags::scenes), tf::device_flags()});
    return all;
}

template <typename F>
void parse_or_error(F parse)
{
    try {
        parse();
    } catch (const tf::Error& e) {
        FUZZ_CHECK(*e.what() != '\0');
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    if (size == 0)
        return 0;
    const size_t max_positional = data[0] % 4;
    std::vector<std::string> argv;
    std::string token;
    for (size_t i = 1; i < size; ++i) {
        if (data[i] == '\0') {
            argv.push_back(token);
            token.clear();
        } else {
            token += char(data[i]);
        }
    }
    if (size > 1)
        argv.push_back(token);

    tf::Args args;
    try {
        args = tf::parse_args("render", argv, specs(), max_positional);
    } catch (const tf::Error& e) {
        FUZZ_CHECK(std::string(e.what()).rfind("render: ", 0) == 0, e.what());
        return 0;
    }
    FUZZ_CHECK(args.positional.size() <= max_positional);
    for (const auto& [flag, value] : args.values) {
        bool declared = false;
        for (const tf::FlagSpec& s : specs())
            if (s.name == flag) {
                declared = true;
                FUZZ_CHECK(!s.value.empty() || value.empty(), flag + " is a switch");
            }
        FUZZ_CHECK(declared, flag);
    }

    parse_or_error([&] {
        const tf::TextureSource t = tf::texture_source_from(args);
        FUZZ_CHECK(t.name_or_path == args.values.at("--texture"));
        FUZZ_CHECK(t.procedural_size >= 1 && t.procedural_size <= tf::max_texture_dimension);
    });
    parse_or_error([&] { tf::fuzz::check_sampler_options(tf::sampler_options_from(args)); });
    parse_or_error([&] { (void)tf::backend_from(args); });
    parse_or_error([&] { (void)tf::context_options_from(args); });
    parse_or_error([&] {
        const auto [w, h] = tf::parse_size("--size", args.get("--size", "256x256"), 2, 4096);
        FUZZ_CHECK(w >= 2 && w <= 4096 && h >= 2 && h <= 4096);
    });
    parse_or_error([&] { (void)args.get_int("--aniso", 1, -5, 5); });
    parse_or_error([&] { (void)args.get_double("--lod-bias", 0.0, -1e300, 1e300); });
    parse_or_error([&] { (void)tf::parse_spp_side(args.get("--spp", "256")); });
    (void)tf::format_help("render ...", specs());
    return 0;
}
