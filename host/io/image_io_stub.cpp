// Image I/O for builds configured with TEXFILTER_IMAGE_IO=OFF: no OpenImageIO, so the CLI links
// only libvulkan and the C++ runtime. Procedural textures and renders still work; files say why not.
#include "io/image_io.h"

#include "texture/error.h"
#include "io/pfm.h"

namespace tf {
namespace {

[[noreturn]] void left_out(const std::string& path) {
    throw Error(path + ": image I/O was left out of this build (configure with -DTEXFILTER_IMAGE_IO=ON)");
}

} // namespace

bool image_io_available() { return false; }

void load_image_io() {
    throw Error("image I/O was left out of this build (configure with -DTEXFILTER_IMAGE_IO=ON)");
}

Image read_image(const std::string& path, ColorSpace, int) { left_out(path); }
void read_image_into(const std::string& path, ColorSpace, int, int, int, glm::vec4*) { left_out(path); }

ImageHeader read_image_header(const std::string& path, int) { left_out(path); }

void write_image(const std::string& path, const Image& image)
{
    if (!is_pfm_path(path))
        left_out(path);
    write_pfm(path, image);
}

Image read_image_raw(const std::string& path) { left_out(path); }

} // namespace tf
