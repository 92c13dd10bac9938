#pragma once
// Summed-area tables on the host: integer, per channel, with modular (wrap-around) arithmetic so that
// every box sum is exact. Uploaded beside the MIP chain for the sat / sat-assembly filters.
#include "texture/image.h"
#include <glm/vec4.hpp>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace tf {

// Input quantisation, per channel c, over the texture's own range: offset_c = the smallest texel value,
// scale_c = largest − smallest, rounded up to float (0 for a constant channel). A texel value v becomes
// q = round((v − offset_c) / scale_c · 65535) in [0, 65535] (in double; 0 where scale_c = 0), i.e. the value
// offset_c + q · scale_c / 65535. So a box mean from the table is within 0.5/65535 · scale_c of the float
// texels' mean (plus float32 rounding in the shader); texels equal to the channel's minimum are exact.
// Every texel must be finite (NaN and ±Inf are refused) and each channel's span must fit a float.
constexpr uint32_t sat_quantisation_levels = 65535;
// Bit budget: table entries are running sums kept modulo 2^40 per channel, and box sums A - B - C + D are
// formed modulo 2^40 (host and shader alike), which is exact whenever the box's true sum is below 2^40:
// every box of up to 2^24 texels of 16-bit values (24 + 16 = 40 bits), i.e. up to 4096x4096. The shader
// clamps its boxes to the texture's size, so sides up to 4096 keep every lookup exact.
constexpr int sat_max_dimension = 4096;

struct SatTable {
    int width = 0, height = 0; // the texture's size; the table is (width + 1) x (height + 1), row 0 and column 0 zero
    glm::vec4 offset{0.0f};    // per channel: the value of quantisation level 0 (the smallest texel value)
    glm::vec4 scale{0.0f};     // per channel: level 65535 minus level 0 (largest − smallest, rounded up)
    std::vector<uint32_t> low; // 4 words a table entry (RGBA), bits 0..31 of each channel's running sum mod 2^40
    std::vector<uint32_t> high; // 1 word a table entry: bits 32..39 of R, G, B, A in bytes 0..3
};

// Throws tf::Error "texture NAME: texel (i, j) is NaN: sat needs finite texels" (or +Inf, -Inf; the first
// such texel in row order) or, where a channel's span max − min overflows float, says so. An empty name
// says "summed-area table" instead.
void check_sat_texels(const Image& level0, const std::string& texture_name = "");

// Throws tf::Error for a texture larger than sat_max_dimension on a side, and as check_sat_texels.
SatTable build_sat(const Image& level0);

// Exact sum of the quantised texels in [x0, x1) x [y0, y1) (texel-aligned, inside the texture), per channel,
// computed from the table with the same modular arithmetic the shader uses.
std::array<uint64_t, 4> sat_box_sum(const SatTable& table, int x0, int y0, int x1, int y1);

} // namespace tf
