#pragma once
// OpenImageIO's TextureSystem as a peer: the lookups texfilter's filters answer, answered by the library a
// renderer built on OIIO would use, on the same level-0 texels. It runs in the image I/O module
// (io/oiio_abi.h's texture_lookups), so a build without OpenImageIO (TEXFILTER_IMAGE_IO=OFF) has no peer and
// says so.
//
// What OIIO is given: level 0 as linear RGBA floats, turned into a tiled MIP-mapped file by
// ImageBufAlgo::make_texture with maketx's defaults (box-filtered levels, each side halved and rounded down,
// float texels, 64x64 tiles; only the file is left uncompressed, which changes no texel) in a private temporary
// directory (mode 0700, an unpredictable name in $TMPDIR or /tmp, created exclusively), which is removed when
// the call returns or throws, and by the process's cleanup on a signal (io/temporary_files.h). TextureOpt: the
// wrap in s and t, the mip and interpolation modes below, the rest OIIO's defaults (anisotropic 32,
// conservative_filter on). OIIO's texel centres and axes are texfilter's: s = u, t = v, texel i centred at
// (i + 1/2) / size, t = 0 the first row; it takes floats, so u, v and the gradients are rounded to float.
//
// Modes (to_string / parse_oiio_texture_mode): "<mip>" with bilinear interpolation, or "<mip>-<interp>":
//   mip     trilinear (MipModeTrilinear: the LOD from the largest single gradient component times
//           min(width, height), levels blended linearly in footprint size) or aniso (MipModeAniso, OIIO's
//           default: Gaussian-weighted probes along the ellipse's major axis, on the levels where its minor
//           axis is about a texel)
//   interp  closest, bilinear, bicubic (B-spline) or smartbicubic (bicubic when magnifying, else bilinear; OIIO's
//           default; in trilinear OIIO reads it as bilinear)
// e.g. trilinear, aniso, aniso-smartbicubic (TextureOpt's defaults), trilinear-closest.
//
// Cost: one make_texture of level 0 and the module's load (0.3 s at 512², 2.1 s at 4096²), then OIIO's
// per-lookup cost on all cores.
// Example: oiio_texture_lookups(level0, lookups, Wrap::repeat, parse_oiio_texture_mode("aniso"))
#include "core/filter.h"
#include "core/lookup.h"
#include "texture/image.h"

#include <glm/vec4.hpp>

#include <string>
#include <vector>

namespace tf {

enum class OiioMip { trilinear, aniso };
enum class OiioInterp { closest, bilinear, bicubic, smartbicubic };

struct OiioTextureMode {
    OiioMip mip = OiioMip::aniso;
    OiioInterp interp = OiioInterp::bilinear;
    bool operator==(const OiioTextureMode&) const = default;
};

std::string to_string(OiioMip mip);
std::string to_string(OiioInterp interp);
std::string to_string(OiioTextureMode mode);
// Throw tf::Error naming the text and listing the names.
OiioInterp parse_oiio_interp(const std::string& name);
OiioTextureMode parse_oiio_texture_mode(const std::string& name);
// Every mode (mip x interp), trilinear first, each mip's bilinear first.
const std::vector<OiioTextureMode>& all_oiio_texture_modes();

// Whether this build has the peer (TEXFILTER_IMAGE_IO=ON).
bool oiio_texture_available();
// Loads the module, so a command finds it missing (or left out of this build) before any work. Throws tf::Error.
void load_oiio_texture();

// RGBA per lookup from OIIO's TextureSystem on level0's texels. Throws tf::Error for an empty or inconsistent
// image, a temporary directory that cannot be made, or OIIO's own failure (its message); nothing is left behind.
std::vector<glm::vec4> oiio_texture_lookups(const Image& level0, const std::vector<Lookup>& lookups, Wrap wrap,
                                            OiioTextureMode mode);

} // namespace tf
