#pragma once
// X Window Dump (XWD, file version 7) reading, for the viewer's "the frame reached the window" check: an
// X-side capture (`xwd -root` of Xvfb) against the swapchain readback (tests/tools/xwd_compare.cpp).
//
// Use:     XwdImage dump = read_xwd("root.xwd"); glm::u8vec3 c = dump.at(x, y);
// Reads:   the big-endian header, ZPixmap, depth 24 in 32 bits a pixel, TrueColor or DirectColor, either
//          byte order of the pixel data, any contiguous red/green/blue masks (scaled to 8 bits).
//          Anything else is refused with a tf::Error naming the file and the field.
// Bounded: every size is checked against the file's length before anything is allocated.
// Cost:    one read of the file, 3 bytes a pixel kept.
#include <glm/glm.hpp>
#include <cstdint>
#include <string>
#include <vector>

namespace tf {

struct XwdImage {
    int width = 0, height = 0;
    std::vector<glm::u8vec3> rgb; // row-major, top row first
    glm::u8vec3 at(int x, int y) const { return rgb[size_t(y) * size_t(width) + size_t(x)]; }
};

// The file's header fields as XWD names them (CARD32 each, big-endian in the file).
enum XwdField {
    xwd_header_size, xwd_file_version, xwd_pixmap_format, xwd_pixmap_depth, xwd_pixmap_width, xwd_pixmap_height,
    xwd_xoffset, xwd_byte_order, xwd_bitmap_unit, xwd_bitmap_bit_order, xwd_bitmap_pad, xwd_bits_per_pixel,
    xwd_bytes_per_line, xwd_visual_class, xwd_red_mask, xwd_green_mask, xwd_blue_mask, xwd_bits_per_rgb,
    xwd_colormap_entries, xwd_ncolors, xwd_window_width, xwd_window_height, xwd_window_x, xwd_window_y,
    xwd_window_bdrwidth, xwd_field_count
};
constexpr size_t xwd_header_bytes = 4 * xwd_field_count; // 100
constexpr size_t xwd_color_bytes = 12;                    // one XWDColor: pixel, r, g, b (16 bits), flags, pad
constexpr int xwd_max_side = 16384;

XwdImage read_xwd(const std::string& path);
// The same from the file's bytes; `name` stands for the file in messages.
XwdImage parse_xwd(const std::vector<std::uint8_t>& bytes, const std::string& name);

} // namespace tf
