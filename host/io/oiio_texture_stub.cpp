// io/oiio_texture.h for builds configured with TEXFILTER_IMAGE_IO=OFF: no OpenImageIO, so no peer.
#include "io/oiio_texture.h"

#include "texture/error.h"

namespace tf {
namespace {

[[noreturn]] void left_out()
{
    throw Error("OpenImageIO's TextureSystem (--backend oiio) was left out of this build (configure with "
                "-DTEXFILTER_IMAGE_IO=ON)");
}

} // namespace

bool oiio_texture_available() { return false; }

void load_oiio_texture() { left_out(); }

std::vector<glm::vec4> oiio_texture_lookups(const Image&, const std::vector<Lookup>&, Wrap, OiioTextureMode)
{
    left_out();
}

} // namespace tf
