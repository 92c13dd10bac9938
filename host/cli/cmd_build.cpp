// `texfilter build`: the MIP chain (and the summed-area table) of a texture as the filters read it, built
// by the device (--build gpu, the default here) or the host (--build cpu), written to a new directory for
// inspection: each level as a PFM or EXR file, the table as sat.bin, and build.txt saying what was built.
#include "flags/cli_common.h"
#include "cli/commands.h"
#include "core/texture_format.h"
#include "io/image_io.h"
#include "io/output_dir.h"
#include "io/output_path.h"
#include "io/pfm.h"
#include "texture/error.h"
#include "texture/sat.h"
#include "vulkan/device.h"
#include "vulkan/render.h"
#include "vulkan/textures.h"
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace tf {

namespace {

// sat.bin: "TFSAT001", int32 width, height, float offset[4], scale[4], then uint32 low[(w+1)(h+1)·4] and
// high[(w+1)(h+1)], row 0 first, little-endian (docs/API.md, "texfilter build").
std::string sat_file_bytes(const SatTable& sat)
{
    std::string bytes = "TFSAT001";
    auto put = [&](const void* data, size_t size) { bytes.append(static_cast<const char*>(data), size); };
    const int32_t size[2] = {sat.width, sat.height};
    put(size, sizeof size);
    put(&sat.offset.x, 4 * sizeof(float));
    put(&sat.scale.x, 4 * sizeof(float));
    put(sat.low.data(), sat.low.size() * sizeof(uint32_t));
    put(sat.high.data(), sat.high.size() * sizeof(uint32_t));
    return bytes;
}

struct Built {
    MipChain chain; // every level as the shader reads it (decoded from the format)
    SatTable sat;   // width 0: none
};

Built build_on_host(const TextureSource& source, bool with_sat)
{
    Built b;
    b.chain = load_texture(source, {with_sat, nullptr});
    if (with_sat)
        b.sat = build_sat(b.chain.levels[0]);
    return b;
}

Built build_on_device(const VulkanContext& context, const TextureSource& source, bool with_sat)
{
    const DeviceLimits limits = device_limits(context.info);
    TextureUse use{with_sat, &limits};
    use.level0_only = true;
    const MipChain level0 = load_texture(source, use);
    Built b;
    with_texture(context, level0, with_sat, source.format, TextureBuild::gpu, [&](const GpuTexture& t) {
        const size_t bytes = texel_bytes(t.format);
        for (int l = 0; l < t.levels; ++l) {
            const int w = std::max(1, t.width >> l), h = std::max(1, t.height >> l);
            const std::vector<unsigned char> stored = read_image_level(
                context, t.chain.image, uint32_t(l), uint32_t(w), uint32_t(h), bytes, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
            Image level = make_image(w, h);
            unpack_texels(stored.data(), level.texels.size(), t.format, level.texels.data());
            b.chain.levels.push_back(std::move(level));
        }
        if (with_sat) {
            b.sat.width = t.width;
            b.sat.height = t.height;
            b.sat.offset = t.sat_offset;
            b.sat.scale = t.sat_scale;
            const uint32_t tw = uint32_t(t.width) + 1, th = uint32_t(t.height) + 1;
            const std::vector<unsigned char> low = read_image_level(context, t.sat_low.image, 0, tw, th, 16,
                                                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
            const std::vector<unsigned char> high = read_image_level(context, t.sat_high.image, 0, tw, th, 4,
                                                                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
            b.sat.low.resize(low.size() / 4);
            b.sat.high.resize(high.size() / 4);
            std::memcpy(b.sat.low.data(), low.data(), low.size());
            std::memcpy(b.sat.high.data(), high.data(), high.size());
        }
        return 0;
    });
    return b;
}

} // namespace

int run_build(const std::vector<std::string>& argv)
{
    std::vector<FlagSpec> specs = join(
        {texture_flags(BuildDefault::gpu),
         {{"--out", "DIR", "a new (or empty) directory: level-NN.pfm|exr, sat.bin with --sat, build.txt (required)"},
          {"--sat", "", "also the summed-area table (sat.bin; sides up to 4096)"},
          {"--level-format", "F", "pfm (linear float RGB, any build; default) or exr (RGBA half, needs image I/O)"}},
         device_flags()});
    Args args = parse_args("build", argv, specs, 0);
    if (args.has("--help")) {
        std::fputs(format_help("texfilter build --texture T|PATH --out DIR [--build gpu|cpu] [--format F] [--sat]", specs)
                       .c_str(),
                   stdout);
        return 0;
    }
    std::vector<std::string> source_argv = argv;
    if (!args.has("--build")) // this command's default: the device's build (the host's is --build cpu)
        source_argv.insert(source_argv.end(), {"--build", "gpu"});
    check_env_flag(args, {}, "build, which builds 2D textures");
    const TextureSource source = texture_source_from(parse_args("build", source_argv, specs, 0));
    const bool with_sat = args.has("--sat");
    const std::string level_format = args.get("--level-format", "pfm");
    if (level_format != "pfm" && level_format != "exr")
        throw Error("bad value for --level-format: '" + level_format + "' (expected pfm or exr)");
    if (level_format == "exr") {
        if (!image_io_available())
            throw Error("--level-format exr: image I/O was left out of this build (pfm is built in)");
        load_image_io();
    }
    const std::string out = args.require("--out");
    check_new_directory(out, "build --out");
    StagingDirectory staging(out); // made before any work: the real test that --out can be written
    if (with_sat)
        check_texture(source, {true, nullptr}); // a texture too big for the table fails here, before any work

    Built built;
    std::string device = "the host";
    if (source.build == TextureBuild::gpu) {
        GpuSession gpu(context_options_from(args));
        check_format_support(gpu.context, source.format, SamplerOptions{});
        built = build_on_device(gpu.context, source, with_sat);
        device = gpu.context.info.name + " (" + gpu.context.info.driver_name + " " + gpu.context.info.driver_info + ")";
        gpu.finish();
    } else {
        built = build_on_host(source, with_sat);
    }

    std::ostringstream summary;
    const Image& base = built.chain.levels[0];
    summary << "texture " << source.name_or_path << " " << base.width << "x" << base.height << ", format "
            << to_string(source.format) << ", built by " << device << " (--build " << to_string(source.build) << ")\n";
    if (source.build == TextureBuild::gpu) {
        const std::vector<MipBuildPass> plan = plan_mip_build(base.width, base.height);
        summary << "MIP build: " << plan.size() << " dispatch(es)";
        for (const MipBuildPass& p : plan)
            summary << "; levels " << p.source_level + 1 << ".." << p.source_level + p.levels << " from " << p.source_level
                    << " in " << p.groups_x << "x" << p.groups_y << " groups" << (p.tail ? ", the last group the rest" : "");
        summary << "\n";
    }
    for (size_t l = 0; l < built.chain.levels.size(); ++l) {
        char name[32];
        std::snprintf(name, sizeof name, "level-%02zu.%s", l, level_format.c_str());
        const Image& level = built.chain.levels[l];
        write_image(staging.path + "/" + name, level);
        summary << name << " " << level.width << "x" << level.height << "\n";
    }
    if (with_sat) {
        write_file_atomic(staging.path + "/sat.bin", sat_file_bytes(built.sat));
        char line[256];
        std::snprintf(line, sizeof line, "sat.bin %dx%d entries, offset %.9g %.9g %.9g %.9g, scale %.9g %.9g %.9g %.9g\n",
                      built.sat.width + 1, built.sat.height + 1, built.sat.offset.x, built.sat.offset.y,
                      built.sat.offset.z, built.sat.offset.w, built.sat.scale.x, built.sat.scale.y, built.sat.scale.z,
                      built.sat.scale.w);
        summary << line;
    }
    write_file_atomic(staging.path + "/build.txt", summary.str());
    staging.publish();
    std::fputs(summary.str().c_str(), stdout);
    std::printf("%s\n", out.c_str());
    return 0;
}

} // namespace tf
