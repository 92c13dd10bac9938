// The names of io/oiio_texture.h's modes: in every build, so that a lean build parses them and then says that
// the peer was left out.
#include "io/oiio_texture.h"

#include "texture/error.h"

#include <utility>

namespace tf {
namespace {

const std::pair<OiioMip, const char*> kMipNames[] = {{OiioMip::trilinear, "trilinear"}, {OiioMip::aniso, "aniso"}};
const std::pair<OiioInterp, const char*> kInterpNames[] = {{OiioInterp::closest, "closest"},
                                                            {OiioInterp::bilinear, "bilinear"},
                                                            {OiioInterp::bicubic, "bicubic"},
                                                            {OiioInterp::smartbicubic, "smartbicubic"}};

} // namespace

std::string to_string(OiioMip mip)
{
    for (const auto& [value, name] : kMipNames)
        if (value == mip)
            return name;
    throw Error("invalid OpenImageIO MIP mode " + std::to_string(int(mip)));
}

std::string to_string(OiioInterp interp)
{
    for (const auto& [value, name] : kInterpNames)
        if (value == interp)
            return name;
    throw Error("invalid OpenImageIO interpolation " + std::to_string(int(interp)));
}

std::string to_string(OiioTextureMode mode)
{
    return to_string(mode.mip) + (mode.interp == OiioInterp::bilinear ? "" : "-" + to_string(mode.interp));
}

OiioInterp parse_oiio_interp(const std::string& name)
{
    std::string names;
    for (const auto& [value, text] : kInterpNames) {
        if (name == text)
            return value;
        names += (names.empty() ? "" : ", ") + std::string(text);
    }
    throw Error("unknown OpenImageIO interpolation '" + name + "' (expected one of: " + names + ")");
}

const std::vector<OiioTextureMode>& all_oiio_texture_modes()
{
    static const std::vector<OiioTextureMode> modes = [] {
        std::vector<OiioTextureMode> list;
        for (const auto& mip : kMipNames) {
            list.push_back({mip.first, OiioInterp::bilinear});
            for (const auto& interp : kInterpNames)
                if (interp.first != OiioInterp::bilinear)
                    list.push_back({mip.first, interp.first});
        }
        return list;
    }();
    return modes;
}

OiioTextureMode parse_oiio_texture_mode(const std::string& name)
{
    std::string names;
    for (const OiioTextureMode& mode : all_oiio_texture_modes()) {
        if (name == to_string(mode))
            return mode;
        names += (names.empty() ? "" : ", ") + to_string(mode);
    }
    throw Error("unknown OpenImageIO texture mode '" + name + "' (expected one of: " + names + ")");
}

} // namespace tf
