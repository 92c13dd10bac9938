#include "texture/image.h"

#include "texture/error.h"

#include <algorithm>
#include <array>
#include <cstdint>
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

const std::array<float, 256>& srgb8_decode_table()
{
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int code = 0; code < 256; ++code) t[size_t(code)] = float(srgb_to_linear(code / 255.0));
        return t;
    }();
    return table;
}

Image decode_srgb8(const uint8_t* pixels, int width, int height, int channels)
{
    if (channels < 1 || channels > 4)
        throw Error("decode_srgb8: " + std::to_string(channels) + " channels (1 grey, 2 grey + alpha, 3 RGB, 4 RGBA)");
    Image image = make_image(width, height);
    const std::array<float, 256>& table = srgb8_decode_table();
    const size_t n = size_t(channels);
    for (size_t i = 0; i < image.texels.size(); ++i) {
        const uint8_t* p = pixels + i * n;
        const float alpha = channels == 2 || channels == 4 ? p[n - 1] / 255.0f : 1.0f;
        image.texels[i] = channels < 3 ? glm::vec4(table[p[0]], table[p[0]], table[p[0]], alpha)
                                       : glm::vec4(table[p[0]], table[p[1]], table[p[2]], alpha);
    }
    return image;
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
