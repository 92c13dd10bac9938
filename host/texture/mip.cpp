#include "texture/mip.h"

#include "texture/error.h"
#include "texture/threads.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <string>

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

// The source texels one destination texel takes along one axis, in increasing order, with their weights.
// 2 taps for even sizes, 3 for odd ones; room for a 4th that float rounding of i*W/W' could add.
struct Taps {
    int count = 0;
    int index[4] = {};
    double weight[4] = {};
};

// Destination texel i covers source [i*W/W', (i+1)*W/W'); each source texel weighs overlap / (W/W').
std::vector<Taps> axis_taps(int src, int dst) {
    const double scale = double(src) / double(dst);
    std::vector<Taps> taps(static_cast<size_t>(dst));
    for (int i = 0; i < dst; ++i) {
        const double lo = i * scale, hi = (i + 1) * scale;
        const int first = int(lo), last = std::min(src - 1, int(hi));
        Taps& t = taps[size_t(i)];
        for (int k = first; k <= last; ++k) {
            const double overlap = std::min(hi, double(k + 1)) - std::max(lo, double(k));
            if (overlap > 0.0 && t.count < 4) {
                t.index[t.count] = k;
                t.weight[t.count++] = overlap / scale;
            }
        }
    }
    return taps;
}

struct Double4 {
    double v[4];
};

// One source row filtered horizontally: row[x] = sum of weight * texel over x's taps (in tap order, from 0).
// Even widths (the common case) take two texels at weight 1/2 each: the same sums, without the tap loop.
void horizontal(const glm::vec4* source_row, const std::vector<Taps>& xtaps, bool pairs, Double4* row) {
    if (pairs) {
        for (size_t x = 0; x < xtaps.size(); ++x) {
            const glm::vec4& a = source_row[2 * x];
            const glm::vec4& b = source_row[2 * x + 1];
            for (int c = 0; c < 4; ++c) row[x].v[c] = 0.0 + 0.5 * double(a[c]) + 0.5 * double(b[c]);
        }
        return;
    }
    for (size_t x = 0; x < xtaps.size(); ++x) {
        const Taps& t = xtaps[x];
        double s[4] = {0.0, 0.0, 0.0, 0.0};
        for (int k = 0; k < t.count; ++k) {
            const glm::vec4& texel = source_row[t.index[k]];
            for (int c = 0; c < 4; ++c) s[c] += t.weight[k] * double(texel[c]);
        }
        for (int c = 0; c < 4; ++c) row[x].v[c] = s[c];
    }
}

// Destination row y from its (up to 4) horizontally filtered source rows; rounding to float happens here, once.
void vertical(const Taps& t, Double4* const* rows, size_t width, glm::vec4* out) {
    if (t.count == 2) {
        const Double4* a = rows[0];
        const Double4* b = rows[1];
        const double wa = t.weight[0], wb = t.weight[1];
        for (size_t x = 0; x < width; ++x) {
            double s[4];
            for (int c = 0; c < 4; ++c) s[c] = 0.0 + wa * a[x].v[c] + wb * b[x].v[c];
            out[x] = glm::vec4(float(s[0]), float(s[1]), float(s[2]), float(s[3]));
        }
        return;
    }
    for (size_t x = 0; x < width; ++x) {
        double s[4] = {0.0, 0.0, 0.0, 0.0};
        for (int k = 0; k < t.count; ++k)
            for (int c = 0; c < 4; ++c) s[c] += t.weight[k] * rows[k][x].v[c];
        out[x] = glm::vec4(float(s[0]), float(s[1]), float(s[2]), float(s[3]));
    }
}

// Below this many destination texels a level is built on the calling thread: starting threads costs more.
constexpr size_t parallel_threshold = size_t(1) << 15;
// In place, destination rows are built into a scratch band of about this many texels, then copied over
// source rows that no later band reads.
constexpr size_t band_texels = size_t(1) << 20;

} // namespace

void downsample_into(const glm::vec4* src, int width, int height, glm::vec4* dst) {
    if (width < 1 || height < 1)
        throw Error("downsample of an empty " + std::to_string(width) + "x" + std::to_string(height) + " image");
    const int w = std::max(1, width >> 1), h = std::max(1, height >> 1);
    const std::vector<Taps> xtaps = axis_taps(width, w), ytaps = axis_taps(height, h);
    const size_t dw = size_t(w), sw = size_t(width);
    const bool in_place = dst == src;
    // The even-width fast path: every destination texel takes source texels 2x and 2x+1 at 1/2 (exact).
    const bool pairs = width % 2 == 0;
    const unsigned threads = dw * size_t(h) >= parallel_threshold ? hardware_threads() : 1u;

    // Why in place is safe: band [y0, y1) is copied over texels [y0*w', y1*w'), all before texel 2*y1*w where
    // source row 2*y1 starts, and later bands read only rows from 2*y1 on (the vertical scale is at least 2,
    // or the level is one row and one band).
    const size_t band = in_place ? std::max<size_t>(1, band_texels / dw) : size_t(h);
    std::vector<glm::vec4> scratch(in_place ? std::min(band, size_t(h)) * dw : 0);
    std::vector<std::vector<Double4>> rows(threads, std::vector<Double4>(4 * dw));
    for (size_t y0 = 0; y0 < size_t(h); y0 += band) {
        const size_t y1 = std::min(size_t(h), y0 + band);
        glm::vec4* out = in_place ? scratch.data() : dst + y0 * dw;
        // Rows are handed out one at a time, so a thread the system holds back delays the band by one row.
        std::atomic<size_t> next{y0};
        run_on_threads(threads, [&](unsigned t) {
            Double4* buffers[4];
            for (int k = 0; k < 4; ++k) buffers[k] = rows[t].data() + size_t(k) * dw;
            for (size_t y; (y = next.fetch_add(1)) < y1;) {
                const Taps& taps = ytaps[y];
                for (int k = 0; k < taps.count; ++k)
                    horizontal(src + size_t(taps.index[k]) * sw, xtaps, pairs, buffers[k]);
                vertical(taps, buffers, dw, out + (y - y0) * dw);
            }
        });
        if (in_place) std::memcpy(dst + y0 * dw, scratch.data(), (y1 - y0) * dw * sizeof(glm::vec4));
    }
}

namespace {

// Throws for an image whose texels do not match its size, or an empty one; `what` names the caller.
void check_image(const Image& image, const char* what) {
    if (image.texels.size() != size_t(std::max(0, image.width)) * size_t(std::max(0, image.height)))
        throw Error(std::string(what) + ": a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                    " image holding " + std::to_string(image.texels.size()) + " texels");
    if (image.width < 1 || image.height < 1) throw Error(std::string(what) + " of an empty image");
}

} // namespace

Image downsample(const Image& source) {
    check_image(source, "downsample");
    Image result;
    result.width = std::max(1, source.width >> 1);
    result.height = std::max(1, source.height >> 1);
    result.texels.resize(size_t(result.width) * size_t(result.height));
    downsample_into(source.texels.data(), source.width, source.height, result.texels.data());
    return result;
}

MipChain build_mip_chain(Image level0) {
    check_image(level0, "MIP chain"); // here too: a 1x1 level 0 is never downsampled
    MipChain chain;
    const int count = mip_level_count(level0.width, level0.height);
    chain.levels.reserve(size_t(count));
    chain.levels.push_back(std::move(level0));
    while (int(chain.levels.size()) < count) chain.levels.push_back(downsample(chain.levels.back()));
    return chain;
}

} // namespace tf
