#include "core/texture_build.h"
#include "texture/error.h"

namespace tf {

TextureBuild parse_texture_build(const std::string& name)
{
    if (name == "cpu")
        return TextureBuild::cpu;
    if (name == "gpu")
        return TextureBuild::gpu;
    throw Error("unknown build '" + name + "' (expected cpu or gpu)");
}

std::string to_string(TextureBuild build) { return build == TextureBuild::gpu ? "gpu" : "cpu"; }

void check_gpu_build(TextureFormat format, const std::string& texture_name)
{
    if (format_info(format).integer)
        throw Error("--build gpu: --format " + to_string(format) +
                    " is integer data, whose levels are rounded codes built on the host; use --build cpu");
    if (texture_name == "mipcolors")
        throw Error("--build gpu: texture mipcolors gives every level its own colour, not a downsample of "
                    "level 0, so the device cannot build it; use --build cpu");
}

} // namespace tf
