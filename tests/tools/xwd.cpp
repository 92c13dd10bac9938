// XWD reading (tools/xwd.h), written from the format's field list (X11's XWDFile.h): a 100-byte header of
// big-endian CARD32s, the window name up to header_size, ncolors 12-byte colour entries, then the pixels.
#include "xwd.h"
#include "texture/error.h"
#include <bit>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace tf {

namespace {

constexpr std::uint32_t zpixmap = 2;
constexpr std::uint32_t true_color = 4, direct_color = 5;
constexpr std::uint32_t lsb_first = 0, msb_first = 1;

std::uint32_t big_endian(const std::uint8_t* p)
{
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | std::uint32_t(p[3]);
}

// One colour channel's mask: where it starts and how many bits wide (contiguous, 1..16 bits).
struct Channel {
    int shift = 0;
    std::uint32_t max = 0;
    std::uint8_t value(std::uint32_t pixel, std::uint32_t mask) const
    {
        std::uint32_t v = (pixel & mask) >> shift;
        return std::uint8_t(max == 255 ? v : (v * 255 + max / 2) / max);
    }
};

Channel channel_of(std::uint32_t mask, const char* name, const std::string& file)
{
    if (mask == 0)
        throw Error(file + ": " + name + " is 0 (a TrueColor dump needs a mask for each colour)");
    int shift = std::countr_zero(mask);
    std::uint32_t bits = mask >> shift;
    if ((bits & (bits + 1)) != 0 || bits > 0xffff)
        throw Error(file + ": " + name + " 0x" + [&] {
            char hex[16];
            std::snprintf(hex, sizeof hex, "%x", mask);
            return std::string(hex);
        }() + " is not one run of at most 16 bits");
    return {shift, bits};
}

} // namespace

XwdImage parse_xwd(const std::vector<std::uint8_t>& bytes, const std::string& name)
{
    if (bytes.size() < xwd_header_bytes)
        throw Error(name + ": " + std::to_string(bytes.size()) + " bytes, shorter than an XWD header (" +
                    std::to_string(xwd_header_bytes) + ")");
    std::uint32_t h[xwd_field_count];
    for (size_t i = 0; i < xwd_field_count; ++i)
        h[i] = big_endian(bytes.data() + 4 * i);
    auto field = [&](const char* what, std::uint32_t got, const std::string& expected) {
        return Error(name + ": " + what + " is " + std::to_string(got) + ", " + expected);
    };
    if (h[xwd_file_version] != 7)
        throw field("file_version", h[xwd_file_version], "expected 7 (not an X11 window dump?)");
    if (h[xwd_header_size] < xwd_header_bytes || h[xwd_header_size] > bytes.size())
        throw field("header_size", h[xwd_header_size],
                    "outside [100, the file's " + std::to_string(bytes.size()) + " bytes]");
    if (h[xwd_pixmap_format] != zpixmap)
        throw field("pixmap_format", h[xwd_pixmap_format], "only ZPixmap (2) is read (0: XYBitmap, 1: XYPixmap)");
    // 32 bits a pixel is the server's own format; xwd writes 24 (packed, lines padded) when it composes a
    // root with windows of several visuals, as it does once a Vulkan window is on the screen.
    if (h[xwd_pixmap_depth] != 24 || (h[xwd_bits_per_pixel] != 32 && h[xwd_bits_per_pixel] != 24))
        throw Error(name + ": depth " + std::to_string(h[xwd_pixmap_depth]) + " in " +
                    std::to_string(h[xwd_bits_per_pixel]) + " bits a pixel; only depth 24 in 24 or 32 bits is read");
    const std::uint32_t pixel_bytes = h[xwd_bits_per_pixel] / 8;
    if (h[xwd_visual_class] != true_color && h[xwd_visual_class] != direct_color)
        throw field("visual_class", h[xwd_visual_class], "only TrueColor (4) or DirectColor (5) is read");
    if (h[xwd_byte_order] != lsb_first && h[xwd_byte_order] != msb_first)
        throw field("byte_order", h[xwd_byte_order], "expected 0 (LSBFirst) or 1 (MSBFirst)");
    if (h[xwd_xoffset] != 0)
        throw field("xoffset", h[xwd_xoffset], "expected 0");
    const std::uint32_t width = h[xwd_pixmap_width], height = h[xwd_pixmap_height];
    if (width == 0 || height == 0 || width > xwd_max_side || height > xwd_max_side)
        throw Error(name + ": " + std::to_string(width) + "x" + std::to_string(height) + " pixels, expected 1 to " +
                    std::to_string(xwd_max_side) + " a side");
    const std::uint64_t line = h[xwd_bytes_per_line];
    if (line < std::uint64_t(width) * pixel_bytes || line > std::uint64_t(width) * 4 + 64)
        throw field("bytes_per_line", h[xwd_bytes_per_line],
                    "expected " + std::to_string(std::uint64_t(width) * pixel_bytes) + " (" +
                        std::to_string(pixel_bytes) + " a pixel) to " + std::to_string(std::uint64_t(width) * 4 + 64));
    Channel red = channel_of(h[xwd_red_mask], "red_mask", name), green = channel_of(h[xwd_green_mask], "green_mask", name),
            blue = channel_of(h[xwd_blue_mask], "blue_mask", name);
    if ((h[xwd_red_mask] & h[xwd_green_mask]) || (h[xwd_red_mask] & h[xwd_blue_mask]) ||
        (h[xwd_green_mask] & h[xwd_blue_mask]))
        throw Error(name + ": the red, green and blue masks overlap");
    // All in 64 bits: ncolors and the sizes are the file's word, not yet believed.
    const std::uint64_t pixels_at = std::uint64_t(h[xwd_header_size]) + std::uint64_t(h[xwd_ncolors]) * xwd_color_bytes;
    const std::uint64_t needed = pixels_at + line * height;
    if (needed > bytes.size())
        throw Error(name + ": header, " + std::to_string(h[xwd_ncolors]) + " colours and " + std::to_string(width) +
                    "x" + std::to_string(height) + " pixels need " + std::to_string(needed) + " bytes, the file has " +
                    std::to_string(bytes.size()) + " (truncated?)");

    XwdImage image;
    image.width = int(width);
    image.height = int(height);
    image.rgb.resize(size_t(width) * height);
    const bool msb = h[xwd_byte_order] == msb_first;
    for (std::uint32_t y = 0; y < height; ++y) {
        const std::uint8_t* row = bytes.data() + pixels_at + line * y;
        for (std::uint32_t x = 0; x < width; ++x) {
            const std::uint8_t* p = row + pixel_bytes * x;
            std::uint32_t pixel = 0;
            for (std::uint32_t b = 0; b < pixel_bytes; ++b) // the pixel's bytes in the dump's byte order
                pixel |= std::uint32_t(p[b]) << (8 * (msb ? pixel_bytes - 1 - b : b));
            image.rgb[size_t(y) * width + x] = {red.value(pixel, h[xwd_red_mask]),
                                                green.value(pixel, h[xwd_green_mask]),
                                                blue.value(pixel, h[xwd_blue_mask])};
        }
    }
    return image;
}

XwdImage read_xwd(const std::string& path)
{
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error)
        throw Error(path + ": " + error.message());
    // The largest dump the reader accepts, plus a generous header and colour map.
    const std::uintmax_t limit = std::uintmax_t(xwd_max_side) * (xwd_max_side * 4 + 64) + (1u << 24);
    if (size > limit)
        throw Error(path + ": " + std::to_string(size) + " bytes, more than any dump of at most " +
                    std::to_string(xwd_max_side) + " pixels a side");
    std::ifstream in(path, std::ios::binary);
    std::vector<std::uint8_t> bytes(size);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size)))
        throw Error(path + ": cannot read " + std::to_string(size) + " bytes");
    return parse_xwd(bytes, path);
}

} // namespace tf
