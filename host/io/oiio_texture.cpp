// io/oiio_texture.h through the image I/O module (io/oiio_abi.h's texture_lookups).
#include "io/oiio_texture.h"

#include "io/oiio_loader.h"
#include "io/temporary_files.h"
#include "texture/error.h"

#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <type_traits>

namespace tf {
namespace {

namespace fs = std::filesystem;

// tf::Lookup crosses the table as six doubles, RGBA results as four floats.
static_assert(std::is_standard_layout_v<Lookup> && sizeof(Lookup) == 6 * sizeof(double));
static_assert(offsetof(Lookup, u) == 0 && offsetof(Lookup, dvdy) == 5 * sizeof(double));
static_assert(sizeof(glm::vec4) == 4 * sizeof(float));

int module_wrap(Wrap wrap)
{
    switch (wrap) {
    case Wrap::repeat: return TF_OIIO_WRAP_PERIODIC;
    case Wrap::clamp: return TF_OIIO_WRAP_CLAMP;
    case Wrap::mirror: return TF_OIIO_WRAP_MIRROR;
    }
    throw Error("invalid wrap mode " + std::to_string(int(wrap)));
}

int module_mip(OiioMip mip) { return mip == OiioMip::trilinear ? TF_OIIO_MIP_TRILINEAR : TF_OIIO_MIP_ANISO; }

int module_interp(OiioInterp interp)
{
    switch (interp) {
    case OiioInterp::closest: return TF_OIIO_INTERP_CLOSEST;
    case OiioInterp::bilinear: return TF_OIIO_INTERP_BILINEAR;
    case OiioInterp::bicubic: return TF_OIIO_INTERP_BICUBIC;
    case OiioInterp::smartbicubic: return TF_OIIO_INTERP_SMARTBICUBIC;
    }
    throw Error("invalid OpenImageIO interpolation " + std::to_string(int(interp)));
}

// The private directory the module writes its texture file into, removed however the call ends.
class TextureDirectory {
public:
    TextureDirectory()
    {
        std::error_code ec;
        const fs::path base = fs::temp_directory_path(ec); // $TMPDIR, else /tmp
        if (ec) {
            const char* tmpdir = std::getenv("TMPDIR");
            throw Error("OpenImageIO's TextureSystem reads its texture from a file, and there is no temporary "
                        "directory" + (tmpdir ? std::string(": TMPDIR=") + tmpdir : std::string()) + " (" +
                        ec.message() + ")");
        }
        path_ = create_temporary_directory((base / "texfilter-oiio").string());
    }
    TextureDirectory(const TextureDirectory&) = delete;
    TextureDirectory& operator=(const TextureDirectory&) = delete;
    ~TextureDirectory() { remove_temporary(path_); }
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

} // namespace

bool oiio_texture_available() { return true; }

void load_oiio_texture() { image_io_module(); }

std::vector<glm::vec4> oiio_texture_lookups(const Image& level0, const std::vector<Lookup>& lookups, Wrap wrap,
                                            OiioTextureMode mode)
{
    if (level0.width <= 0 || level0.height <= 0 ||
        level0.texels.size() != size_t(level0.width) * size_t(level0.height))
        throw Error("OpenImageIO's TextureSystem: an empty or inconsistent " + std::to_string(level0.width) + "x" +
                    std::to_string(level0.height) + " texture");
    const tf_oiio_api& api = image_io_module();
    std::vector<glm::vec4> colors(lookups.size());
    const TextureDirectory directory;
    tf_oiio_texture_job job{};
    job.directory = directory.path().c_str();
    job.width = level0.width;
    job.height = level0.height;
    job.rgba = reinterpret_cast<const float*>(level0.texels.data());
    job.wrap = module_wrap(wrap);
    job.mip = module_mip(mode.mip);
    job.interp = module_interp(mode.interp);
    job.lookups = reinterpret_cast<const double*>(lookups.data());
    job.count = int64_t(lookups.size());
    job.colors = reinterpret_cast<float*>(colors.data());
    ModuleCall call;
    call.check(api.texture_lookups(&job, &call.c));
    return colors;
}

} // namespace tf
