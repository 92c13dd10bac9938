#include "texture/image.h"

#include "texture/error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace tf {

Image make_image(int width, int height, glm::vec4 fill) {
    if (width < 0 || height < 0)
        throw Error("invalid image size " + std::to_string(width) + "x" + std::to_string(height));
    Image image;
    image.width = width;
    image.height = height;
    image.texels.assign(size_t(width) * size_t(height), fill);
    return image;
}

// IEC 61966-2-1: linear segment below the 0.04045 / 0.0031308 breakpoints, 2.4 power above.
double srgb_to_linear(double encoded) {
    if (encoded <= 0.04045) return encoded / 12.92;
    return std::pow((encoded + 0.055) / 1.055, 2.4);
}

double linear_to_srgb(double linear) {
    if (linear <= 0.0031308) return linear * 12.92;
    return 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

Image encode_srgb(const Image& linear)
{
    Image out = linear;
    for (glm::vec4& t : out.texels)
        for (int c = 0; c < 3; ++c)
            t[c] = float(linear_to_srgb(std::min(1.0, std::max(0.0, double(t[c])))));
    return out;
}

} // namespace tf
