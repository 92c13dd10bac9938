// Image files through the image I/O module (io/oiio_abi.h): OpenImageIO is loaded on the first file read or
// written (oiio_loader.h), so this file, and the rest of the project, never sees its headers.
#include "io/image_io.h"
#include "io/oiio_loader.h"
#include "io/output_path.h"
#include "io/pfm.h"
#include "io/pfm_image.h"

#include "texture/error.h"

#include <cctype>
#include <filesystem>
#include <string>
#include <system_error>

namespace tf {
namespace {

namespace fs = std::filesystem;

static_assert(int(ColorSpace::automatic) == TF_OIIO_AUTOMATIC && int(ColorSpace::srgb) == TF_OIIO_SRGB &&
              int(ColorSpace::linear) == TF_OIIO_LINEAR);
static_assert(sizeof(glm::vec4) == 4 * sizeof(float));

// read_rgba into a new Image.
Image read_rgba_image(const std::string& path, int max_dimension, bool raw, ColorSpace space) {
    const tf_oiio_api& api = image_io_module();
    Image image;
    ModuleCall call;
    call.destination = [&](int width, int height) {
        image = make_image(width, height);
        return image.texels.data();
    };
    call.check(api.read_rgba(path.c_str(), max_dimension, raw, int(space), &call.c));
    return image;
}

std::string lower_extension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

} // namespace

bool image_io_available() { return true; }

void load_image_io() { image_io_module(); }

ImageHeader read_image_header(const std::string& path, int max_dimension) {
    if (is_pfm_file(path)) return read_pfm_image_header(path, max_dimension); // built in: io/pfm_image.h
    const tf_oiio_api& api = image_io_module();
    ModuleCall call;
    tf_oiio_header header{};
    call.check(api.read_header(path.c_str(), max_dimension, &header, &call.c));
    return {header.width, header.height, header.channels};
}

Image read_image(const std::string& path, ColorSpace space, int max_dimension) {
    if (is_pfm_file(path)) return read_pfm_image(path, max_dimension, true);
    return read_rgba_image(path, max_dimension, false, space);
}

void read_image_into(const std::string& path, ColorSpace space, int max_dimension, int width, int height,
                     glm::vec4* texels) {
    if (is_pfm_file(path)) return read_pfm_image_into(path, max_dimension, width, height, texels);
    const tf_oiio_api& api = image_io_module();
    ModuleCall call;
    call.destination = [&](int w, int h) {
        if (w != width || h != height) // the file changed since its header was read
            throw Error(path + ": now " + std::to_string(w) + "x" + std::to_string(h) + ", was " +
                        std::to_string(width) + "x" + std::to_string(height) + " when its header was read");
        return texels;
    };
    call.check(api.read_rgba(path.c_str(), max_dimension, 0, int(space), &call.c));
}

Image read_image_raw(const std::string& path) {
    if (is_pfm_file(path)) return read_pfm_image(path, raw_image_max_dimension, false);
    return read_rgba_image(path, raw_image_max_dimension, true, ColorSpace::automatic);
}

void write_image(const std::string& path, const Image& image) {
    if (is_pfm_path(path)) return write_pfm(path, image); // built in: no OpenImageIO needed
    const std::string ext = lower_extension(path);
    const bool png = ext == ".png";
    if (!png && ext != ".exr")
        throw Error(path + ": unsupported output format '" + ext + "' (use .png, .exr or .pfm)");
    if (image.width <= 0 || image.height <= 0 ||
        image.texels.size() != size_t(image.width) * size_t(image.height))
        throw Error(path + ": cannot write an empty or inconsistent " + std::to_string(image.width) + "x" +
                    std::to_string(image.height) + " image");
    const tf_oiio_api& api = image_io_module();

    write_output(path, [&](int fd) {
        ModuleCall call;
        call.check(api.write_rgba(path.c_str(), fd, png, image.width, image.height,
                                  reinterpret_cast<const float*>(image.texels.data()), &call.c));
    });
}

} // namespace tf
