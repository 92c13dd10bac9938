#include "io/pfm_image.h"

#include "io/pfm.h"
#include "texture/error.h"
#include "texture/finite.h"

#include <fstream>

namespace tf {

namespace {

std::ifstream open_pfm(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw Error(path + ": no such file or not readable");
    return in;
}

void read_checked(std::istream& in, const PfmHeader& header, const std::string& path, glm::vec4* texels, bool finite)
{
    NonFiniteTexels found;
    read_pfm_pixels(in, header, path, texels, finite ? &found : nullptr);
    check_finite_texels(found, path, header.width, header.height);
}

} // namespace

ImageHeader read_pfm_image_header(const std::string& path, int max_dimension)
{
    std::ifstream in = open_pfm(path);
    const PfmHeader header = read_pfm_header(in, path, max_dimension);
    return {header.width, header.height, 3};
}

Image read_pfm_image(const std::string& path, int max_dimension, bool finite)
{
    std::ifstream in = open_pfm(path);
    const PfmHeader header = read_pfm_header(in, path, max_dimension);
    Image image = make_image(header.width, header.height);
    read_checked(in, header, path, image.texels.data(), finite);
    return image;
}

void read_pfm_image_into(const std::string& path, int max_dimension, int width, int height, glm::vec4* texels)
{
    std::ifstream in = open_pfm(path);
    const PfmHeader header = read_pfm_header(in, path, max_dimension);
    if (header.width != width || header.height != height) // the file changed since its header was read
        throw Error(path + ": now " + std::to_string(header.width) + "x" + std::to_string(header.height) + ", was " +
                    std::to_string(width) + "x" + std::to_string(height) + " when its header was read");
    read_checked(in, header, path, texels, true);
}

} // namespace tf
