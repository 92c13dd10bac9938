#include "texture/sat.h"

#include "texture/error.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include <glm/common.hpp>

namespace tf {

namespace {

constexpr uint64_t kMask40 = (uint64_t(1) << 40) - 1;

// 16-bit level of one (finite) channel value on the channel's range.
uint64_t quantise(float value, double offset, double scale) {
    if (!(scale > 0)) return 0;
    const double level = std::round((double(value) - offset) / scale * double(sat_quantisation_levels));
    return uint64_t(std::clamp(level, 0.0, double(sat_quantisation_levels)));
}

// The span rounded up to float: the smallest float at or above d, so that no finite texel lands above 65535.
float span_at_or_above(double d)
{
    float f = float(d);
    if (double(f) < d)
        f = std::nextafter(f, INFINITY);
    return f;
}

const char* channel_name(int c) { return c == 0 ? "R" : c == 1 ? "G" : c == 2 ? "B" : "A"; }

uint64_t entry(const SatTable& t, size_t index, int channel) {
    return uint64_t(t.low[index * 4 + size_t(channel)]) | (uint64_t((t.high[index] >> (8 * channel)) & 0xFFu) << 32);
}

} // namespace

void check_sat_texels(const Image& level0, const std::string& texture_name) {
    const std::string what = texture_name.empty() ? "summed-area table" : "texture " + texture_name;
    glm::vec4 lo(INFINITY), hi(-INFINITY);
    for (int j = 0; j < level0.height; ++j)
        for (int i = 0; i < level0.width; ++i) {
            const glm::vec4& texel = level0.at(i, j);
            for (int c = 0; c < 4; ++c) {
                const float v = texel[c];
                if (!std::isfinite(v))
                    throw Error(what + ": texel (" + std::to_string(i) + ", " + std::to_string(j) + ") is " +
                                (std::isnan(v) ? "NaN" : v > 0 ? "+Inf" : "-Inf") +
                                ": sat needs finite texels (channel " + channel_name(c) + ")");
                lo[c] = std::min(lo[c], v);
                hi[c] = std::max(hi[c], v);
            }
        }
    for (int c = 0; c < 4; ++c)
        if (!level0.texels.empty() && double(hi[c]) - double(lo[c]) > double(std::numeric_limits<float>::max()))
            throw Error(what + ": channel " + channel_name(c) + " spans " + std::to_string(lo[c]) + " .. " +
                        std::to_string(hi[c]) + ", more than a float holds: sat quantises each channel over its range");
}

SatTable build_sat(const Image& level0) {
    const int w = level0.width, h = level0.height;
    if (w < 1 || h < 1 || w > sat_max_dimension || h > sat_max_dimension)
        throw Error("summed-area table: texture " + std::to_string(w) + "x" + std::to_string(h) +
                    " is outside 1.." + std::to_string(sat_max_dimension) +
                    " a side (40-bit sums are exact only up to 4096x4096 texels of 16 bits)");
    if (level0.texels.size() != size_t(w) * size_t(h))
        throw Error("summed-area table: texture " + std::to_string(w) + "x" + std::to_string(h) + " holds " +
                    std::to_string(level0.texels.size()) + " texels");
    check_sat_texels(level0);

    // Per channel: level 0 at the smallest value, level 65535 at the largest (the span rounded up to float,
    // so that no finite texel lands above 65535).
    glm::vec4 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec4& texel : level0.texels) {
        lo = glm::min(lo, texel);
        hi = glm::max(hi, texel);
    }
    glm::vec4 span;
    for (int c = 0; c < 4; ++c)
        span[c] = span_at_or_above(double(hi[c]) - double(lo[c]));

    SatTable t;
    t.width = w;
    t.height = h;
    t.offset = lo;
    t.scale = span;
    const size_t stride = size_t(w) + 1;
    t.low.assign(stride * (size_t(h) + 1) * 4, 0u);
    t.high.assign(stride * (size_t(h) + 1), 0u);

    // S(i, j+1) = S(i, j) + (sum of row j over [0, i)). Row 0 and column 0 stay zero. Held in 64 bits and
    // stored modulo 2^40 (the true values never exceed 4096^2 x 65535 < 2^40, but the format says mod 2^40).
    std::vector<uint64_t> above(stride * 4, 0);
    for (int j = 0; j < h; ++j) {
        uint64_t row[4] = {0, 0, 0, 0};
        for (int i = 0; i < w; ++i) {
            const glm::vec4& texel = level0.at(i, j);
            const size_t index = size_t(j + 1) * stride + size_t(i + 1);
            uint32_t high = 0;
            for (int c = 0; c < 4; ++c) {
                row[c] += quantise(texel[c], double(t.offset[c]), double(t.scale[c]));
                uint64_t& s = above[size_t(i + 1) * 4 + size_t(c)];
                s = (s + row[c]) & kMask40;
                t.low[index * 4 + size_t(c)] = uint32_t(s);
                high |= uint32_t(s >> 32) << (8 * c);
            }
            t.high[index] = high;
        }
    }
    return t;
}

std::array<uint32_t, sat_range_words> sat_range_initial()
{
    return {0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu, 0u, 0u, 0u, 0u, 0xFFFFFFFFu};
}

namespace {

float unkey(uint32_t key)
{
    const uint32_t bits = (key & 0x80000000u) ? key & 0x7FFFFFFFu : ~key;
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

} // namespace

void sat_range_offset_scale(const std::array<uint32_t, sat_range_words>& words, int width,
                            const std::string& texture_name, glm::vec4& offset, glm::vec4& scale)
{
    const std::string what = texture_name.empty() ? "summed-area table" : "texture " + texture_name;
    if (words[8] != 0xFFFFFFFFu) {
        const uint32_t index = words[8] >> 4, kind = (words[8] >> 2) & 3u, c = words[8] & 3u;
        const int w = std::max(1, width);
        throw Error(what + ": texel (" + std::to_string(index % uint32_t(w)) + ", " + std::to_string(index / uint32_t(w)) +
                    ") is " + (kind == 1 ? "NaN" : kind == 2 ? "+Inf" : "-Inf") +
                    ": sat needs finite texels (channel " + channel_name(int(c)) + ")");
    }
    for (int c = 0; c < 4; ++c) {
        const float lo = unkey(words[size_t(c)]), hi = unkey(words[size_t(4 + c)]);
        const double d = double(hi) - double(lo);
        if (d > double(std::numeric_limits<float>::max()))
            throw Error(what + ": channel " + channel_name(c) + " spans " + std::to_string(lo) + " .. " +
                        std::to_string(hi) + ", more than a float holds: sat quantises each channel over its range");
        offset[c] = lo;
        scale[c] = span_at_or_above(d);
    }
}

std::array<uint64_t, 4> sat_box_sum(const SatTable& table, int x0, int y0, int x1, int y1) {
    if (x0 < 0 || y0 < 0 || x1 < x0 || y1 < y0 || x1 > table.width || y1 > table.height)
        throw Error("sat_box_sum: box [" + std::to_string(x0) + ", " + std::to_string(x1) + ") x [" +
                    std::to_string(y0) + ", " + std::to_string(y1) + ") is not inside the " +
                    std::to_string(table.width) + "x" + std::to_string(table.height) + " texture");
    const size_t stride = size_t(table.width) + 1;
    const size_t a = size_t(y0) * stride + size_t(x0), b = size_t(y0) * stride + size_t(x1);
    const size_t c = size_t(y1) * stride + size_t(x0), d = size_t(y1) * stride + size_t(x1);
    std::array<uint64_t, 4> sum{};
    for (int ch = 0; ch < 4; ++ch) // modulo 2^40, as the shader does: exact while the true sum < 2^40
        sum[size_t(ch)] = (entry(table, d, ch) - entry(table, b, ch) - entry(table, c, ch) + entry(table, a, ch)) & kMask40;
    return sum;
}

} // namespace tf
