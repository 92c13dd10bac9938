// The XWD reader (tests/tools/xwd.h) and xwd_compare on synthetic dumps written here: both byte orders of the
// pixel data, RGB and BGR mask orders, row padding, a window name and a colour map to skip; every refusal
// before allocating; and xwd_compare's exit codes against a PNG (0 equal, 1 different, 2 bad input).
#include "support.h"
#include "io/image_io.h"
#include "tools/xwd.h"
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>

using namespace tf;

namespace {

// The dump's layout: XWD's header fields, set per case.
struct XwdLayout {
    int width = 5, height = 3;
    std::uint32_t byte_order = 0; // 0 LSBFirst, 1 MSBFirst
    std::uint32_t red_mask = 0xff0000, green_mask = 0xff00, blue_mask = 0xff;
    std::uint32_t padding = 0;    // bytes after each row
    std::uint32_t pixel_bytes = 4; // 3: packed 24 bits, as xwd writes a root composed of several visuals
    std::uint32_t ncolors = 0;
    std::string window_name = "test-window";
    std::uint32_t overrides[xwd_field_count] = {}; // nonzero: the header field as given
    bool has_override[xwd_field_count] = {};
    void set(XwdField f, std::uint32_t v) { overrides[f] = v, has_override[f] = true; }
};

void put32(std::vector<std::uint8_t>& out, std::uint32_t v, bool msb)
{
    for (int i = 0; i < 4; ++i)
        out.push_back(std::uint8_t(msb ? v >> (24 - 8 * i) : v >> (8 * i)));
}

// The pixel of colour c under the layout's masks (each mask 8 bits wide here).
std::uint32_t pack(glm::u8vec3 c, const XwdLayout& l)
{
    auto place = [](std::uint8_t v, std::uint32_t mask) {
        int shift = 0;
        while (shift < 31 && !((mask >> shift) & 1))
            ++shift;
        return mask == 0 ? 0u : std::uint32_t(v) << shift;
    };
    return place(c.r, l.red_mask) | place(c.g, l.green_mask) | place(c.b, l.blue_mask);
}

glm::u8vec3 colour_at(int x, int y) { return {std::uint8_t(40 * x + 3), std::uint8_t(70 * y + 1), std::uint8_t(x * y * 17 + 200)}; }

std::vector<std::uint8_t> make_xwd(const XwdLayout& l, const std::function<glm::u8vec3(int, int)>& colour = colour_at)
{
    std::uint32_t h[xwd_field_count] = {};
    h[xwd_header_size] = std::uint32_t(xwd_header_bytes + l.window_name.size() + 1);
    h[xwd_file_version] = 7;
    h[xwd_pixmap_format] = 2;
    h[xwd_pixmap_depth] = 24;
    h[xwd_pixmap_width] = std::uint32_t(l.width);
    h[xwd_pixmap_height] = std::uint32_t(l.height);
    h[xwd_byte_order] = l.byte_order;
    h[xwd_bitmap_unit] = 32;
    h[xwd_bitmap_bit_order] = l.byte_order;
    h[xwd_bitmap_pad] = 32;
    h[xwd_bits_per_pixel] = 8 * l.pixel_bytes;
    h[xwd_bytes_per_line] = std::uint32_t(l.pixel_bytes * l.width) + l.padding;
    h[xwd_visual_class] = 4;
    h[xwd_red_mask] = l.red_mask;
    h[xwd_green_mask] = l.green_mask;
    h[xwd_blue_mask] = l.blue_mask;
    h[xwd_bits_per_rgb] = 8;
    h[xwd_colormap_entries] = 256;
    h[xwd_ncolors] = l.ncolors;
    h[xwd_window_width] = std::uint32_t(l.width);
    h[xwd_window_height] = std::uint32_t(l.height);
    for (int f = 0; f < xwd_field_count; ++f)
        if (l.has_override[f])
            h[f] = l.overrides[f];
    std::vector<std::uint8_t> out;
    for (std::uint32_t v : h)
        put32(out, v, true); // the header is big-endian whatever byte_order says
    out.insert(out.end(), l.window_name.begin(), l.window_name.end());
    out.push_back(0);
    for (std::uint32_t i = 0; i < l.ncolors; ++i)
        for (size_t k = 0; k < xwd_color_bytes; ++k)
            out.push_back(std::uint8_t(0xa5)); // colour entries: skipped for TrueColor
    for (int y = 0; y < l.height; ++y) {
        for (int x = 0; x < l.width; ++x)
        {
            std::vector<std::uint8_t> word;
            put32(word, pack(colour(x, y), l), l.byte_order == 1);
            if (l.pixel_bytes == 3) // the low three bytes of the value, in the dump's byte order
                word.erase(l.byte_order == 1 ? word.begin() : word.end() - 1);
            out.insert(out.end(), word.begin(), word.end());
        }
        out.insert(out.end(), l.padding, std::uint8_t(0xee));
    }
    return out;
}

void write_file(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes)
{
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

int wrong_pixels(const XwdImage& image, const std::function<glm::u8vec3(int, int)>& colour = colour_at)
{
    int wrong = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            wrong += image.at(x, y) != colour(x, y);
    return wrong;
}

// Runs xwd_compare ARGS; its exit status, and its stdout and stderr in `output`: the tool's own tests (its
// exit codes and messages).
int run_xwd_compare(const std::filesystem::path& work, const std::string& args, std::string& output)
{
    std::string log = (work / "xwd_compare.log").string();
    int status = std::system(("'" TF_XWD_COMPARE "' " + args + " > '" + log + "' 2>&1").c_str());
    std::stringstream text;
    text << std::ifstream(log).rdbuf();
    output = text.str();
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

} // namespace

TEST_SUITE_BEGIN("reference");

// 1. Both byte orders, both mask orders, padded rows, a name and a colour map: every pixel as written.
TEST_CASE("reader")
{
    for (std::uint32_t order : {0u, 1u})
        for (bool bgr : {false, true}) {
            XwdLayout l;
            l.byte_order = order;
            if (bgr)
                l.red_mask = 0xff, l.blue_mask = 0xff0000;
            l.padding = order == 1 ? 8 : 0;
            l.ncolors = bgr ? 3 : 0;
            XwdImage image = parse_xwd(make_xwd(l), "synthetic.xwd");
            CHECK_EQ(image.width, 5);
            CHECK_EQ(image.height, 3);
            CHECK_EQ(wrong_pixels(image), 0);
        }
    // Packed 24 bits a pixel, lines padded (xwd -root once a window of another visual is on the screen).
    for (std::uint32_t order : {0u, 1u}) {
        XwdLayout packed;
        packed.pixel_bytes = 3;
        packed.byte_order = order;
        packed.padding = 5;
        CHECK_EQ(wrong_pixels(parse_xwd(make_xwd(packed), "packed.xwd")), 0);
    }
    // Masks in the upper bytes (a 32-bit ARGB-style layout with the low byte unused) and GRB order.
    XwdLayout shifted;
    shifted.red_mask = 0xff00, shifted.green_mask = 0xff000000, shifted.blue_mask = 0xff0000;
    CHECK_EQ(wrong_pixels(parse_xwd(make_xwd(shifted), "shifted.xwd")), 0);
    // The two orders differ in the file: reading one as the other would give other colours.
    XwdLayout lsb, msb;
    msb.byte_order = 1;
    CHECK(make_xwd(lsb) != make_xwd(msb));
}

// 2. What the reader refuses, each before allocating the pixels, with the field in the message.
TEST_CASE("reader-refusals")
{
    auto refused = [](XwdLayout l, const std::string& part) { CHECK_THROWS_WITH(parse_xwd(make_xwd(l), "bad.xwd"), part); };
    XwdLayout l;
    l.set(xwd_file_version, 6);
    refused(l, "bad.xwd: file_version is 6, expected 7");
    l = {};
    l.set(xwd_pixmap_format, 1);
    refused(l, "pixmap_format is 1, only ZPixmap (2)");
    l = {};
    l.set(xwd_pixmap_depth, 16);
    refused(l, "depth 16 in 32 bits a pixel; only depth 24 in 24 or 32 bits");
    l = {};
    l.set(xwd_bits_per_pixel, 16);
    refused(l, "depth 24 in 16 bits");
    l = {};
    l.set(xwd_visual_class, 3);
    refused(l, "visual_class is 3, only TrueColor (4) or DirectColor (5)");
    l = {};
    l.set(xwd_byte_order, 7);
    refused(l, "byte_order is 7");
    l = {};
    l.green_mask = 0xff0;
    refused(l, "the red, green and blue masks overlap");
    l = {};
    l.blue_mask = 0x0f0f;
    refused(l, "blue_mask 0xf0f is not one run");
    l = {};
    l.red_mask = 0;
    refused(l, "red_mask is 0");
    l = {};
    l.set(xwd_pixmap_width, 100000);
    refused(l, "100000x3 pixels, expected 1 to 16384 a side");
    l = {};
    l.set(xwd_pixmap_height, 0);
    refused(l, "5x0 pixels");
    l = {};
    l.set(xwd_bytes_per_line, 4);
    refused(l, "bytes_per_line is 4, expected 20");
    l = {};
    l.set(xwd_pixmap_height, 16384); // claims 16384 rows, holds 3: refused from the length, nothing allocated
    refused(l, "5x16384 pixels need 327792 bytes, the file has 172 (truncated?)");
    l = {};
    l.set(xwd_ncolors, 0xffffffff);
    refused(l, "4294967295 colours");
    l = {};
    l.set(xwd_header_size, 1u << 30);
    refused(l, "header_size is 1073741824, outside [100, the file's");
    std::vector<std::uint8_t> header_only = make_xwd({});
    header_only.resize(60);
    CHECK_THROWS_WITH(parse_xwd(header_only, "short.xwd"), "short.xwd: 60 bytes, shorter than an XWD header (100)");
    CHECK_THROWS_WITH(read_xwd("/nonexistent/dump.xwd"), "/nonexistent/dump.xwd: ");
}

// 3. xwd_compare against a PNG: equal (exit 0), one channel off by 3 (exit 1, or 0 with --tolerance 3),
//    the region at --at in a larger dump, and bad input (exit 2 naming it).
TEST_CASE("xwd-compare")
{
    if (!image_io_available()) {
        MESSAGE("skipped: this build reads no PNG");
        return;
    }
    std::filesystem::path work = test::make_work_dir("xwd");
    // A PNG's stored bytes are what xwd_compare compares: write one, read its bytes back as the truth.
    Image picture = make_image(6, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 6; ++x)
            picture.at(x, y) = glm::vec4(x / 5.0f, y / 3.0f, float((x * 7 + y * 3) % 10) / 9.0f, 1.0f);
    std::string png = (work / "shot.png").string();
    write_image(png, picture);
    const Image stored = read_image_raw(png);
    auto stored_colour = [&stored](int x, int y) {
        int px = x - 3, py = y - 2; // the shot sits at 3,2 of the dump; around it a frame of other colours
        if (px < 0 || py < 0 || px >= stored.width || py >= stored.height)
            return glm::u8vec3(x * 9, 255 - y * 9, 77);
        glm::vec4 v = stored.at(px, py);
        return glm::u8vec3(std::lround(v.r * 255), std::lround(v.g * 255), std::lround(v.b * 255));
    };
    XwdLayout l;
    l.width = 12, l.height = 9, l.red_mask = 0xff, l.blue_mask = 0xff0000; // BGR, as some servers write
    write_file(work / "dump.xwd", make_xwd(l, stored_colour));
    std::string output;
    std::string files = "'" + (work / "dump.xwd").string() + "' '" + png + "'";
    CHECK_EQ(run_xwd_compare(work, files + " --at 3,2", output), 0);
    CHECK_CONTAINS(output, "max channel difference 0, 0 of 24 pixels differ");
    CHECK_EQ(run_xwd_compare(work, files, output), 1); // 0,0: the frame, not the shot
    CHECK_EQ(run_xwd_compare(work, files + " --at 4,2", output), 1);

    constexpr int bumped_x = 5, bumped_y = 3;
    auto bumped_colour = [&stored](int x, int y) {
        int px = x - 3, py = y - 2;
        if (px < 0 || py < 0 || px >= stored.width || py >= stored.height)
            return glm::u8vec3(0);
        glm::vec4 v = stored.at(px, py);
        glm::u8vec3 c(std::lround(v.r * 255), std::lround(v.g * 255), std::lround(v.b * 255));
        if (x == bumped_x && y == bumped_y)
            c.g = std::uint8_t(c.g >= 128 ? c.g - 3 : c.g + 3);
        return c;
    };
    l.byte_order = 1;
    write_file(work / "dump.xwd", make_xwd(l, bumped_colour));
    CHECK_EQ(run_xwd_compare(work, files + " --at 3,2", output), 1);
    CHECK_CONTAINS(output, "max channel difference 3, 1 of 24 pixels differ (first at 2,1");
    CHECK_EQ(run_xwd_compare(work, files + " --at 3,2 --tolerance 3", output), 0);
    CHECK_EQ(run_xwd_compare(work, files + " --at 3,2 --tolerance 2", output), 1);

    CHECK_EQ(run_xwd_compare(work, files + " --at 7,2", output), 2);
    CHECK_CONTAINS(output, "(6x4) at 7,2 does not fit in");
    CHECK_EQ(run_xwd_compare(work, files + " --tolerance 300", output), 2);
    CHECK_CONTAINS(output, "xwd_compare: bad --tolerance '300'");
    CHECK_EQ(run_xwd_compare(work, files + " --at 3", output), 2);
    CHECK_EQ(run_xwd_compare(work, "'" + png + "' '" + png + "'", output), 2); // a PNG is no XWD
    CHECK_CONTAINS(output, "file_version is");
    CHECK_EQ(run_xwd_compare(work, "'" + (work / "dump.xwd").string() + "'", output), 2);
    CHECK_CONTAINS(output, "usage: xwd_compare DUMP.xwd SHOT.png");
}

TEST_SUITE_END();
