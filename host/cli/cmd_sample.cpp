#include "flags/cli_common.h"
#include "cli/commands.h"
#include "cli/sample_oiio.h"
#include "cli/sample_resource.h"
#include "core/texel_sources.h"
#include "vulkan/backend.h"
#include "vulkan/sample.h"
#include "vulkan/pipelines.h"
#include "vulkan/device.h"
#include "io/lookups_csv.h"
#include "io/output_path.h"
#include "io/text_file.h"
#include "reference/render.h"
#include "texture/error.h"
#include <algorithm>
#include <cstdint>
#include <cstdio>

namespace tf {

namespace {

void print_stats(const std::vector<LookupStats>& stats)
{
    if (stats.empty())
        return;
    auto summary = [&](const char* what, auto field) {
        double sum = 0;
        uint32_t low = UINT32_MAX, high = 0;
        for (const LookupStats& s : stats) {
            uint32_t v = s.*field;
            sum += v;
            low = std::min(low, v);
            high = std::max(high, v);
        }
        std::printf("%s per lookup: mean %.2f, min %u, max %u\n", what, sum / double(stats.size()), low, high);
    };
    summary("texel fetches", &LookupStats::texel_fetches);
    summary("hardware lookups", &LookupStats::hardware_lookups);
}

// --spirv FILE: the lookup shader read and checked (vulkan/pipelines.h) before any work; empty without it.
std::vector<uint32_t> sample_spirv_from(const Args& args, Backend backend, const ResourceOptions& resource,
                                        const TextureSource& source)
{
    if (!args.has("--spirv"))
        return {};
    const std::string path = args.get("--spirv", "");
    if (backend != Backend::vulkan)
        throw Error("--spirv is the device's lookup shader: it needs --backend vulkan");
    // The kinds whose harness variant Slang's GLSL mode compiles and tests/test_slang.cpp runs (docs/API.md
    // "Slang"); each is checked against its own pass's bindings.
    if (resource.resource != Resource::combined && resource.resource != Resource::separate &&
        resource.resource != Resource::separate_array)
        throw Error("--spirv replaces the shader of --resource combined, separate or separate-array, not " +
                    to_string(resource.resource));
    if (format_info(source.format).integer)
        throw Error("--spirv replaces the float formats' shader; --format " + to_string(source.format) +
                    " is read through the integer build");
    constexpr uint64_t max_bytes = 64ull << 20; // the harness module is ~0.5 MB
    return check_sample_spirv(read_text_file(path, max_bytes, "the SPIR-V file"), path, resource.resource);
}

std::vector<FlagSpec> sample_flag_specs()
{
    return join({texture_flags(),
                 sampler_flags(SamplerFlags::lookups),
                 {{"--lookups", "IN.csv", "header u,v,dudx,dvdx,dudy,dvdy; one lookup a row"},
                  {"-o", "OUT.csv", "r,g,b,a in linear light, one row per lookup"},
                  {"--stats", "", "vulkan: add columns fetches,hw_lookups (counted in the "
                                  "shader) and print their mean, min and max"},
                  {"--spirv", "FILE.spv",
                   "vulkan, --resource combined, separate or separate-array: run the lookups "
                   "through FILE.spv instead of the built-in shader (shaders/harness/"
                   "sample.comp.glsl compiled with -DHARNESS_RESOURCE=<the kind's id> by another "
                   "compiler, e.g. Slang's; checked first: valid SPIR-V, the kind's sample pass's "
                   "bindings)"},
                  oiio_interp_flag()},
                 resource_flags(),
                 device_flags()});
}

// What the flags select, every check that needs no lookups made in the command's order; `out` (the
// command's -o, null for sample_lookups) checked in its place among them. With --backend oiio only the
// options and the backend are filled in (run_sample_oiio checks the rest).
struct SampleSetup {
    SamplerOptions options;
    Backend backend = Backend::vulkan;
    ResourceOptions resource;
    TextureSource source;
    std::vector<uint32_t> spirv;
};

SampleSetup sample_setup(const Args& args, std::string* out)
{
    SampleSetup setup;
    setup.options = sampler_options_from(args);
    check_env_flag(args, {}, "sample, whose lookups are 2D uv");
    if (setup.options.filter == Filter::ground_truth)
        throw Error("bad value for --filter: ground-truth integrates over a scene's pixels, not around a lookup "
                    "(use render)");
    setup.backend = backend_from(args, true);
    if (setup.backend == Backend::oiio)
        return setup;
    check_oiio_interp_unused(args);
    setup.resource = resource_options_from(args);
    check_resource_options(setup.options, setup.resource); // what the kind cannot run, before any work
    setup.source = texture_source_from(args);
    const TextureSource& source = setup.source;
    check_format_filter(source.format, setup.options); // integer data and hardware filtering, before any work
    // The other resource kinds upload their images as RGBA32F (layers, bindless elements) or D32_SFLOAT
    // (shadow): a rounded format would reach the shader through the wrong descriptor type.
    if (setup.resource.resource != Resource::combined && source.build == TextureBuild::gpu)
        throw Error("--build gpu is for --resource combined; --resource " + to_string(setup.resource.resource) +
                    " builds its layers and depth maps on the host");
    if (setup.resource.resource != Resource::combined && source.format != TextureFormat::rgba32f)
        throw Error("--format " + to_string(source.format) + " is for --resource combined; --resource " +
                    to_string(setup.resource.resource) + " uploads RGBA32F (shadow: D32_SFLOAT)");
    if (out)
        *out = checked_output_path(args.require("-o"), {".csv"}, {args.require("--lookups"), source.name_or_path});
    if (args.has("--stats") && setup.backend != Backend::vulkan)
        throw Error("--stats counts the shader's fetches: it needs --backend vulkan");
    setup.spirv = sample_spirv_from(args, setup.backend, setup.resource, source);
    return setup;
}

// The lookups filtered as set up: the device opened, the texture checked against its memory and loaded.
SampleOutput sample_with(const Args& args, const SampleSetup& setup, const std::vector<Lookup>& lookups)
{
    const SamplerOptions& options = setup.options;
    const ResourceOptions& resource = setup.resource;
    const TextureSource& source = setup.source;
    const ShaderCode shader = {setup.spirv.empty() ? nullptr : setup.spirv.data(), setup.spirv.size() * sizeof(uint32_t)};
    CommandDevice device = open_command_device(setup.backend, args);
    if (device.gpu)
        check_format_support(device.gpu->context, source.format, options);
    TextureUse use = device.texture_use(needs_sat(options.filter));
    use.level0_only = source.build == TextureBuild::gpu;
    use.other_bytes = uint64_t(lookups.size()) * sample_lookup_bytes(!device.gpu);
    use.other_what = std::to_string(lookups.size()) + " lookups";
    if (is_texel_source(resource.resource)) {
        // The atlas or physical texture is built from the texture: its size, from the header, is checked
        // against the device's largest image and its bytes join the budget's, before anything is decoded.
        TextureSource header = source; // the size alone: the budget is checked below, the source's bytes in it
        header.memory_budget = UINT64_MAX;
        const TextureSize size = check_texture(header, use);
        if (device.gpu)
            check_source_device(device.gpu->context, resource.resource, size.width, size.height);
        else
            check_source_size(resource.resource, size.width, size.height, max_source_side);
        use.other_bytes += source_host_bytes(resource.resource, size.width, size.height, !device.gpu,
                                             device.gpu && device.limits.host_memory);
        use.other_what += " and the " + std::string(resource.resource == Resource::atlas ? "atlas" : "virtual texture");
    }
    MipChain chain = load_texture(source, use);
    GpuSession* gpu = device.gpu.get();

    SampleOutput output;
    if (resource.resource != Resource::combined) {
        output.colors = sample_resource(gpu, chain, lookups, options, resource, &output.stats, shader);
        if (gpu)
            gpu->finish();
    } else if (!gpu) {
        output.colors = reference_sample_all(chain, lookups, options);
    } else {
        std::vector<glm::vec4> results = with_texture(gpu->context, chain, needs_sat(options.filter), source.format,
                                                      source.build, [&](auto& t) {
            if (shader.words)
                return gpu_sample_with_shader(gpu->context, t, lookups, options, shader, &output.stats);
            return gpu_sample(gpu->context, t, lookups, options, &output.stats);
        });
        gpu->finish();
        output.colors.assign(results.begin(), results.end());
    }
    return output;
}

} // namespace

SampleOutput sample_lookups(const std::vector<std::string>& flags, const std::vector<Lookup>& lookups)
{
    const Args args = parse_args("sample", flags, sample_flag_specs(), 0);
    for (const char* file_flag : {"--lookups", "-o", "--help"})
        if (args.has(file_flag))
            throw Error(std::string("sample_lookups takes the lookups themselves: no ") + file_flag);
    const SampleSetup setup = sample_setup(args, nullptr);
    if (setup.backend == Backend::oiio)
        throw Error("sample_lookups: --backend oiio is the command's alone (texfilter sample)");
    SampleOutput output = sample_with(args, setup, lookups);
    if (!args.has("--stats"))
        output.stats.clear();
    return output;
}

int run_sample(const std::vector<std::string>& argv)
{
    const std::vector<FlagSpec> specs = sample_flag_specs();
    Args args = parse_args("sample", argv, specs, 0);
    if (args.has("--help")) {
        std::fputs(format_help("texfilter sample --texture T|PATH --filter F --lookups IN.csv "
                               "[--resource K] [--stochastic white|blue [--accumulate N]] [--backend vulkan|reference|oiio] [--stats] "
                               "[--spirv FILE.spv] [--oiio-interp I] "
                               "-o OUT.csv",
                               specs)
                       .c_str(),
                   stdout);
        return 0;
    }
    std::string out;
    const SampleSetup setup = sample_setup(args, &out);
    if (setup.backend == Backend::oiio)
        return run_sample_oiio(args, setup.options);
    const std::vector<Lookup> lookups = read_lookups_csv(args.require("--lookups"));
    const SampleOutput output = sample_with(args, setup, lookups);
    const bool with_stats = args.has("--stats");
    write_colors_csv(out, output.colors, with_stats ? &output.stats : nullptr);
    std::printf("%s: %zu lookups\n", out.c_str(), output.colors.size());
    if (with_stats)
        print_stats(output.stats);
    return 0;
}

} // namespace tf
