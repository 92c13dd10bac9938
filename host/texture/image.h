#pragma once
// Linear-light RGBA float images: the one pixel container shared by textures, renders and goldens.
#include <glm/vec4.hpp>
#include <vector>

namespace tf {

// Row-major, row 0 first. Texel (x, y) covers texture space [x, x+1) x [y, y+1) in texel units,
// so v = 0 is row 0 (Vulkan convention: the first row in memory is t = 0).
struct Image {
    int width = 0;
    int height = 0;
    std::vector<glm::vec4> texels;

    glm::vec4& at(int x, int y) { return texels[size_t(y) * size_t(width) + size_t(x)]; }
    const glm::vec4& at(int x, int y) const { return texels[size_t(y) * size_t(width) + size_t(x)]; }
};

Image make_image(int width, int height, glm::vec4 fill = glm::vec4(0.0f));

// IEC 61966-2-1 transfer functions, exact piecewise form (not a gamma approximation).
double srgb_to_linear(double encoded);
double linear_to_srgb(double linear);

// Linear image -> sRGB-encoded values in float (clamped to [0,1] first, no quantisation), alpha unchanged:
// the display values goldens and benchmark errors are measured in.
Image encode_srgb(const Image& linear);

} // namespace tf
