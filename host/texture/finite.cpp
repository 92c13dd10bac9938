#include "texture/finite.h"

#include "texture/error.h"

#include <cmath>
#include <string>

namespace tf {

namespace {

const char* channel_name(int c) { return c == 0 ? "R" : c == 1 ? "G" : c == 2 ? "B" : "A"; }

std::string value_name(float v) { return std::isnan(v) ? "NaN" : v > 0 ? "+Inf" : "-Inf"; }

} // namespace

void NonFiniteTexels::scan(const glm::vec4* texels, size_t first, size_t n, int width)
{
    for (size_t i = 0; i < n; ++i) {
        const glm::vec4& t = texels[i];
        // One test for the common case: a finite texel's channels sum to a finite value or to an Inf that
        // x - x turns into NaN; NaN/Inf anywhere makes the sum's x - x NaN too.
        const float sum = t.r + t.g + t.b + t.a;
        if (sum - sum == 0.0f)
            continue;
        int c = 0;
        while (c < 4 && std::isfinite(t[c]))
            ++c;
        if (c == 4)
            continue;
        const size_t index = first + i;
        if (count++ == 0 || index < first_index) {
            first_index = index;
            x = int(index % size_t(width));
            y = int(index / size_t(width));
            channel = c;
            value = t[c];
        }
    }
}

void check_finite_texels(const NonFiniteTexels& found, const std::string& what, int width, int height)
{
    if (found.count == 0)
        return;
    const uint64_t texels = uint64_t(width) * uint64_t(height);
    throw Error(what + ": texel (" + std::to_string(found.x) + ", " + std::to_string(found.y) + ") is " +
                value_name(found.value) + " (channel " + channel_name(found.channel) + "; " +
                std::to_string(found.count) + " of " + std::to_string(texels) +
                " texels hold NaN or Inf): every filter needs finite texels");
}

void check_finite_texels(const Image& image, const std::string& what)
{
    NonFiniteTexels found;
    found.scan(image.texels.data(), 0, image.texels.size(), image.width);
    check_finite_texels(found, what, image.width, image.height);
}

} // namespace tf
