#include "core/procedural.h"
#include "core/hash.h"

#include "texture/error.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace tf {

namespace {

constexpr int kMaxSize = 16384;

Image checker(int size) {
    Image image = make_image(size, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            // Cell index floor(x*8/size): exact in integers, cells need not be whole texels.
            const int cx = x * 8 / size, cy = y * 8 / size;
            const float value = (cx + cy) % 2 == 0 ? 0.9f : 0.05f;
            image.at(x, y) = glm::vec4(value, value, value, 1.0f);
        }
    return image;
}

Image zoneplate(int size) {
    Image image = make_image(size, size);
    const double centre = size / 2.0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double dx = x + 0.5 - centre, dy = y + 0.5 - centre;
            // Phase pi*r^2/size: local frequency r/size cycles per texel, Nyquist at r = size/2.
            const double value = 0.5 + 0.5 * std::cos(std::numbers::pi * (dx * dx + dy * dy) / size);
            image.at(x, y) = glm::vec4(float(value), float(value), float(value), 1.0f);
        }
    return image;
}

// True for the first `width` texels of each of the 16 cells along an axis.
bool on_grid_line(int i, int size, int width) {
    const auto cell = [size](int k) { return int(std::floor(double(k) * 16.0 / size)); };
    return cell(i) != cell(i - width);
}

Image grid(int size) {
    const glm::vec4 background(0.02f, 0.03f, 0.08f, 1.0f), line(0.9f, 0.85f, 0.6f, 1.0f);
    const int width = size >= 512 ? 2 : 1;
    Image image = make_image(size, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            image.at(x, y) = on_grid_line(x, size, width) || on_grid_line(y, size, width) ? line : background;
    return image;
}

// Integer avalanche hash (multiply / xor-shift rounds): deterministic on every platform, unlike std::rand.
uint32_t hash3(uint32_t x, uint32_t y, uint32_t z) {
    return mix32(x * 0x8da6b343u ^ y * 0xd8163841u ^ z * 0xcb1ab31fu);
}

Image noise(int size) {
    Image image = make_image(size, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            glm::vec4 texel(1.0f);
            // Top 24 bits -> [0,1) exactly representable in float.
            for (int c = 0; c < 3; ++c)
                texel[c] = float(hash3(uint32_t(x), uint32_t(y), uint32_t(c)) >> 8) * (1.0f / 16777216.0f);
            image.at(x, y) = texel;
        }
    return image;
}

// Twelve saturated hues 30 degrees apart, linear RGB: adjacent levels are always told apart.
const glm::vec4 kPalette[12] = {
    {1.0f, 0.0f, 0.0f, 1.0f}, {1.0f, 0.5f, 0.0f, 1.0f}, {1.0f, 1.0f, 0.0f, 1.0f}, {0.5f, 1.0f, 0.0f, 1.0f},
    {0.0f, 1.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 0.5f, 1.0f}, {0.0f, 1.0f, 1.0f, 1.0f}, {0.0f, 0.5f, 1.0f, 1.0f},
    {0.0f, 0.0f, 1.0f, 1.0f}, {0.5f, 0.0f, 1.0f, 1.0f}, {1.0f, 0.0f, 1.0f, 1.0f}, {1.0f, 0.0f, 0.5f, 1.0f},
};

MipChain mipcolors(int size) {
    MipChain chain;
    const int count = mip_level_count(size, size);
    for (int l = 0; l < count; ++l) {
        const int w = std::max(1, size >> l);
        chain.levels.push_back(make_image(w, w, kPalette[l % 12]));
    }
    return chain;
}

std::string name_list() {
    std::string list;
    for (const std::string& name : procedural_names()) list += (list.empty() ? "" : ", ") + name;
    return list;
}

} // namespace

const std::vector<std::string>& procedural_names() {
    static const std::vector<std::string> names = {"checker", "zoneplate", "grid", "noise", "mipcolors", "dynamic"};
    return names;
}

bool is_procedural(const std::string& name) {
    for (const std::string& n : procedural_names())
        if (n == name) return true;
    return false;
}

MipChain make_procedural(const std::string& name, int size) {
    if (!is_procedural(name))
        throw Error("unknown procedural texture '" + name + "' (expected one of: " + name_list() + ")");
    if (size < 1 || size > kMaxSize)
        throw Error("procedural texture size " + std::to_string(size) + " out of range [1, " +
                    std::to_string(kMaxSize) + "]");
    if (name == "mipcolors") return mipcolors(size);
    if (name == "checker") return build_mip_chain(checker(size));
    if (name == "zoneplate") return build_mip_chain(zoneplate(size));
    if (name == "grid") return build_mip_chain(grid(size));
    if (name == "dynamic") return build_mip_chain(dynamic_texture(size, 0));
    return build_mip_chain(noise(size));
}

// Keep in step with shaders/harness/dynamic_texture.comp.glsl (tests/test_gpu_build.cpp compares them).
Image dynamic_texture(int size, int frame) {
    if (size < 1 || size > kMaxSize)
        throw Error("procedural texture size " + std::to_string(size) + " out of range [1, " +
                    std::to_string(kMaxSize) + "]");
    Image image = make_image(size, size);
    const int64_t cell = std::max(2, size / 16), f = frame;
    // The rings' centre circles the middle on a 16-frame square path (integer steps).
    const int64_t phase = f % 16, step = std::max(1, size / 32);
    const int64_t cx = size / 2 + step * (phase < 8 ? phase - 4 : 12 - phase);
    const int64_t cy = size / 2 + step * (phase < 4 ? phase : phase < 12 ? 8 - phase : phase - 16);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const int64_t sx = (x + 3 * f) % size, sy = (y + 2 * f) % size;
            const bool dark = ((sx / cell + sy / cell) & 1) != 0;
            const int64_t dx = x - cx, dy = y - cy;
            const int64_t ring = ((dx * dx + dy * dy) * 4 / (cell * cell) + f) & 3;
            const int64_t fine = (sx ^ sy) & 15;
            image.at(x, y) = glm::vec4(dark ? 0.1f : 0.85f, float(ring) * 0.25f, float(fine) * 0.0625f, 1.0f);
        }
    return image;
}

} // namespace tf
