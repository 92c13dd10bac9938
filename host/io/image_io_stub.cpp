// Image I/O for builds configured with TEXFILTER_IMAGE_IO=OFF: no OpenImageIO, so the CLI links
// only libvulkan and the C++ runtime. Procedural textures and renders still work; files say why not.
#include "io/image_io.h"

#include "texture/error.h"
#include "io/pfm.h"
#include "io/pfm_image.h"

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

// PFM files are read by the built-in reader (io/pfm_image.h), as in a build with image I/O.
Image read_image(const std::string& path, ColorSpace, int max_dimension)
{
    if (!is_pfm_file(path))
        left_out(path);
    return read_pfm_image(path, max_dimension, true);
}

void read_image_into(const std::string& path, ColorSpace, int max_dimension, int width, int height, glm::vec4* texels)
{
    if (!is_pfm_file(path))
        left_out(path);
    read_pfm_image_into(path, max_dimension, width, height, texels);
}

ImageHeader read_image_header(const std::string& path, int max_dimension)
{
    if (!is_pfm_file(path))
        left_out(path);
    return read_pfm_image_header(path, max_dimension);
}

void write_image(const std::string& path, const Image& image)
{
    if (!is_pfm_path(path))
        left_out(path);
    write_pfm(path, image);
}

Image read_image_raw(const std::string& path)
{
    if (!is_pfm_file(path))
        left_out(path);
    return read_pfm_image(path, raw_image_max_dimension, false);
}

} // namespace tf
