#include "texture/mip.h"

#include "texture/error.h"

#include <algorithm>
#include <glm/ext/vector_double4.hpp>

namespace tf {

int mip_level_count(int width, int height) {
    if (width < 1 || height < 1) return 0;
    int size = std::max(width, height);
    int levels = 1;
    while (size > 1) {
        size >>= 1;
        ++levels;
    }
    return levels;
}

namespace {

// One source texel's contribution to a destination texel along one axis.
struct Tap {
    int index;
    double weight;
};

// Destination texel i covers source [i*W/W', (i+1)*W/W'); each source texel weighs overlap / (W/W').
// For W' = W >> 1 this is 2 taps (even W) or 3 taps (odd W); W = 1 maps to itself.
std::vector<std::vector<Tap>> axis_taps(int src, int dst) {
    const double scale = double(src) / double(dst);
    std::vector<std::vector<Tap>> taps(static_cast<size_t>(dst));
    for (int i = 0; i < dst; ++i) {
        const double lo = i * scale, hi = (i + 1) * scale;
        const int first = int(lo), last = std::min(src - 1, int(hi));
        for (int k = first; k <= last; ++k) {
            const double overlap = std::min(hi, double(k + 1)) - std::max(lo, double(k));
            if (overlap > 0.0) taps[size_t(i)].push_back({k, overlap / scale});
        }
    }
    return taps;
}

} // namespace

Image downsample(const Image& source) {
    if (source.width < 1 || source.height < 1) throw Error("downsample of an empty image");
    const int w = std::max(1, source.width >> 1), h = std::max(1, source.height >> 1);
    const auto xtaps = axis_taps(source.width, w);
    const auto ytaps = axis_taps(source.height, h);

    // Horizontal pass into a double buffer (source rows x w), then vertical, so rounding happens once.
    std::vector<glm::dvec4> rows(size_t(source.height) * size_t(w));
    for (int y = 0; y < source.height; ++y)
        for (int x = 0; x < w; ++x) {
            glm::dvec4 sum(0.0);
            for (const Tap& t : xtaps[size_t(x)]) sum += t.weight * glm::dvec4(source.at(t.index, y));
            rows[size_t(y) * size_t(w) + size_t(x)] = sum;
        }

    Image result = make_image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            glm::dvec4 sum(0.0);
            for (const Tap& t : ytaps[size_t(y)]) sum += t.weight * rows[size_t(t.index) * size_t(w) + size_t(x)];
            result.at(x, y) = glm::vec4(sum);
        }
    return result;
}

MipChain build_mip_chain(Image level0) {
    if (level0.width < 1 || level0.height < 1) throw Error("MIP chain of an empty image");
    MipChain chain;
    const int count = mip_level_count(level0.width, level0.height);
    chain.levels.reserve(size_t(count));
    chain.levels.push_back(std::move(level0));
    while (int(chain.levels.size()) < count) chain.levels.push_back(downsample(chain.levels.back()));
    return chain;
}

} // namespace tf
