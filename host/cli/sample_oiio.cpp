#include "cli/sample_oiio.h"

#include "core/memory_budget.h"
#include "flags/cli_common.h"
#include "io/lookups_csv.h"
#include "io/oiio_texture.h"
#include "io/output_path.h"
#include "texture/error.h"

#include <cstdio>
#include <set>

namespace tf {

FlagSpec oiio_interp_flag()
{
    return {"--oiio-interp", "I",
            "--backend oiio: OpenImageIO's interpolation within a level, closest, bilinear (default), bicubic or "
            "smartbicubic (bicubic when magnifying; OIIO's own default)"};
}

void check_oiio_interp_unused(const Args& args)
{
    if (args.has("--oiio-interp"))
        throw Error("--oiio-interp is not read by --backend " + args.get("--backend", "vulkan") +
                    " (it applies to --backend oiio)");
}

int run_sample_oiio(const Args& args, const SamplerOptions& options)
{
    if (options.filter != Filter::trilinear && options.filter != Filter::aniso)
        throw Error("--backend oiio runs OpenImageIO's TextureSystem, whose modes are --filter trilinear and aniso, "
                    "not --filter " + to_string(options.filter));
    // What OIIO is given: the texture's level 0, the lookups, the wrap and its two modes. Every other flag would
    // be silently ignored, so it is refused.
    static const std::set<std::string> read = {"--texture", "--texture-size", "--texture-frame", "--linear",
                                               "--memory-budget", "--filter", "--wrap", "--backend",
                                               "--oiio-interp", "--lookups", "-o"};
    for (const auto& [flag, value] : args.values)
        if (!read.count(flag))
            throw Error(flag + " is not read by --backend oiio (OpenImageIO's TextureSystem reads the texture's "
                        "level 0, --filter trilinear or aniso, --wrap and --oiio-interp)");
    OiioTextureMode mode;
    mode.mip = options.filter == Filter::trilinear ? OiioMip::trilinear : OiioMip::aniso;
    mode.interp = parse_flag(args, "--oiio-interp", "bilinear", parse_oiio_interp);
    load_oiio_texture(); // a build without it, or a missing module, says so before any work
    TextureSource source = texture_source_from(args);
    const std::string out =
        checked_output_path(args.require("-o"), {".csv"}, {args.require("--lookups"), source.name_or_path});
    const std::vector<Lookup> lookups = read_lookups_csv(args.require("--lookups"));
    TextureUse use;
    use.level0_only = true; // OIIO builds its own levels from level 0 (maketx)
    // Beside level 0 OIIO holds make_texture's float copy of it and of the levels it builds (16 bytes a texel,
    // a third more for the levels); its ImageCache then reads tiles of that file within its own limit.
    const TextureSize size = check_texture(source, {});
    const uint64_t oiio_copy = uint64_t(size.width) * uint64_t(size.height) * 16 * 4 / 3;
    use.other_bytes = uint64_t(lookups.size()) * sample_lookup_bytes(true) + oiio_copy;
    use.other_what = std::to_string(lookups.size()) + " lookups and OpenImageIO's MIP-mapped copy";
    const MipChain chain = load_texture(source, use);
    const std::vector<glm::vec4> results = oiio_texture_lookups(chain.levels[0], lookups, options.wrap, mode);
    write_colors_csv(out, std::vector<glm::dvec4>(results.begin(), results.end()));
    std::printf("%s: %zu lookups (OpenImageIO %s)\n", out.c_str(), results.size(), to_string(mode).c_str());
    return 0;
}

} // namespace tf
