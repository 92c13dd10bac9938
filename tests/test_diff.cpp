// Tests for diff.h, image_io.h (OpenImageIO build) and report.h. Plain main(); exits 1 on any failure.
// Needs OpenImageIO itself too: some inputs are written through OIIO directly, in layouts
// (grey, grey+alpha, RGB, 16-bit, 5-channel EXR) that write_image never produces.
#include "core/diff.h"
#include "texture/error.h"
#include "texture/image.h"
#include "io/image_io.h"
#include "io/report.h"
#include "support.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::string file_in(const fs::path& dir, const std::string& name) { return (dir / name).string(); }

size_t entries_in(const fs::path& dir) {
    return size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

tf::Image noise_image(int w, int h, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    tf::Image img = tf::make_image(w, h);
    for (glm::vec4& t : img.texels) t = glm::vec4(u(rng), u(rng), u(rng), u(rng));
    return img;
}

void write_bytes(const std::string& path, const std::vector<char>& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
}

std::vector<char> read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Writes pixels through OIIO directly, in whatever layout the test needs.
template <typename T>
bool oiio_write(const std::string& path, int w, int h, int channels, OIIO::TypeDesc type, const std::vector<T>& px,
                const char* color_space = nullptr) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) return false;
    OIIO::ImageSpec spec(w, h, channels, type);
    if (color_space) spec.attribute("oiio:ColorSpace", color_space);  // PNG: gAMA 1.0 for "Linear"
    spec.attribute("oiio:UnassociatedAlpha", 1);  // the pixels hold straight alpha: store them as given
    if (channels == 2) spec.channelnames = {"Y", "A"}, spec.alpha_channel = 1;
    if (channels == 5) spec.channelnames = {"R", "G", "B", "A", "Z"}, spec.alpha_channel = 3;
    if (!out->open(path, spec)) return false;
    if (!out->write_image(OIIO::BaseTypeFromC<T>::value, px.data())) return false;
    return out->close();
}

// ---------------------------------------------------------------------------------------------
// diff.h

// This executable is built with image I/O only; the lean stub would refuse every file below.
TEST_CASE("image-io-available")
{
    CHECK(tf::image_io_available());
}

TEST_CASE("identical")
{
    const tf::Image a = noise_image(16, 8, 1);
    const tf::DiffResult r = tf::diff_images(a, a, tf::DiffThresholds{});
    CHECK_EQ(r.max_error, 0.0);
    CHECK_EQ(r.max_x, 0);
    CHECK_EQ(r.max_y, 0);
    CHECK_EQ(r.mean_error, 0.0);
    CHECK_EQ(r.rms_error, 0.0);
    CHECK(std::isinf(r.psnr) && r.psnr > 0);
    CHECK_EQ(r.fail_count, 0);
    CHECK(r.pass);
    const std::string text = tf::describe(r, tf::DiffThresholds{});
    CHECK_CONTAINS(text, "PSNR inf dB");
    CHECK_CONTAINS(text, "\nPASS");
}

TEST_CASE("one-pixel-off")
{
    const int w = 8, h = 4;  // 32 pixels: one failing pixel is exactly 3.125 %
    const tf::Image a = noise_image(w, h, 2);
    tf::Image b = a;
    b.at(5, 2).g += 0.5f;
    const double d = double(b.at(5, 2).g) - double(a.at(5, 2).g);  // 0.5 up to float rounding of the sum

    tf::DiffThresholds t;
    t.fail = 0.1;
    t.fail_percent = 100.0 / (w * h);
    const tf::DiffResult r = tf::diff_images(a, b, t);
    CHECK_EQ(r.max_error, d);
    CHECK_NEAR(r.max_error, 0.5, 1e-7);
    CHECK_EQ(r.max_x, 5);
    CHECK_EQ(r.max_y, 2);
    CHECK_NEAR(r.mean_error, d / (w * h * 4), 1e-15);
    CHECK_NEAR(r.rms_error, std::sqrt(d * d / (w * h * 4)), 1e-15);
    CHECK_NEAR(r.psnr, 20.0 * std::log10(1.0 / std::sqrt(d * d / (w * h * 4))), 1e-12);
    CHECK_EQ(r.fail_count, 1);
    CHECK_EQ(r.fail_percent, 3.125);
    CHECK(r.pass);  // 3.125 % allowed, exactly at the boundary

    t.fail_percent = std::nextafter(100.0 / (w * h), 0.0);
    CHECK(!tf::diff_images(a, b, t).pass);  // just under the boundary
    t.fail_percent = 0.0;
    CHECK(!tf::diff_images(a, b, t).pass);

    t.fail_percent = 100.0;
    t.hard_fail = d;
    CHECK(tf::diff_images(a, b, t).pass);  // hard limit exactly at the max
    t.hard_fail = std::nextafter(d, 0.0);
    CHECK(!tf::diff_images(a, b, t).pass);

    // The per-pixel threshold is strict: a pixel exactly at `fail` does not fail.
    t = tf::DiffThresholds{};
    t.fail = d;
    CHECK_EQ(tf::diff_images(a, b, t).fail_count, 0);
    CHECK(tf::diff_images(a, b, t).pass);
    t.fail = std::nextafter(d, 0.0);
    CHECK_EQ(tf::diff_images(a, b, t).fail_count, 1);
    CHECK(!tf::diff_images(a, b, t).pass);

    t = tf::DiffThresholds{};
    t.fail = 0.002;
    t.fail_percent = 0.5;
    const std::string text = tf::describe(tf::diff_images(a, b, t), t);
    CHECK_CONTAINS(text, "max error 0.5 at (5, 2)\n");
    CHECK_CONTAINS(text, "1 pixels (3.12%) over 0.002 (allowed 0.5%)");
    CHECK_CONTAINS(text, "\nFAIL");

    // Several pixels at the same maximum: the first in row-major order is reported.
    tf::Image base = a, c = a;
    base.at(6, 1).r = base.at(2, 3).b = base.at(7, 1).a = 0.125f;
    c.at(6, 1).r = c.at(2, 3).b = c.at(7, 1).a = 0.875f;
    const tf::DiffResult rc = tf::diff_images(base, c, tf::DiffThresholds{});
    CHECK_EQ(rc.max_error, 0.75);
    CHECK_EQ(rc.max_x, 6);
    CHECK_EQ(rc.max_y, 1);
}

TEST_CASE("nan-fails")
{
    const tf::Image a = noise_image(4, 4, 3);
    tf::Image b = a;
    b.at(1, 3).r = std::numeric_limits<float>::quiet_NaN();
    tf::DiffThresholds t;
    t.fail_percent = 100.0;
    const tf::DiffResult r = tf::diff_images(a, b, t);
    CHECK(std::isinf(r.max_error));
    CHECK_EQ(r.max_x, 1);
    CHECK_EQ(r.max_y, 3);
    t.hard_fail = 1.0;
    CHECK(!tf::diff_images(a, b, t).pass);
    CHECK(tf::diff_images(b, b, t).pass);  // NaN in both at the same place is no difference
}

TEST_CASE("size-mismatch")
{
    const tf::Image a = tf::make_image(256, 256), b = tf::make_image(128, 128);
    CHECK_THROWS_WITH(tf::diff_images(a, b, tf::DiffThresholds{}), "image sizes differ: 256x256 vs 128x128");
    CHECK_THROWS_WITH(tf::diff_image(a, b, 1.0), "image sizes differ: 256x256 vs 128x128");
}

TEST_CASE("diff-image")
{
    tf::Image a = tf::make_image(2, 1, glm::vec4(0.5f, 0.5f, 0.5f, 0.5f));
    tf::Image b = a;
    b.at(0, 0) = glm::vec4(0.25f, 0.5f, 0.75f, 0.0f);
    b.at(1, 0) = glm::vec4(0.5f, 0.4f, 0.5f, 1.0f);
    const tf::Image d = tf::diff_image(a, b, 2.0);
    CHECK_EQ(d.width, 2);
    CHECK_EQ(d.height, 1);
    CHECK_EQ(d.at(0, 0).r, 0.5f);
    CHECK_EQ(d.at(0, 0).g, 0.0f);
    CHECK_EQ(d.at(0, 0).b, 0.5f);
    CHECK_EQ(d.at(0, 0).a, 1.0f);
    CHECK_NEAR(d.at(1, 0).g, 0.2, 1e-6);
    CHECK_EQ(d.at(1, 0).a, 1.0f);
    const tf::Image clamped = tf::diff_image(a, b, 100.0);
    CHECK_EQ(clamped.at(0, 0).r, 1.0f);
    CHECK_EQ(clamped.at(0, 0).g, 0.0f);
}

// ---------------------------------------------------------------------------------------------
// image_io.h

TEST_CASE("png-round-trip")
{
    const fs::path dir = tf::test::make_work_dir("test-diff-png-round-trip");
    tf::Image img = noise_image(37, 23, 4);  // odd sizes catch stride mistakes
    img.at(0, 0) = glm::vec4(0.0f, 1.0f, 0.001f, 0.0f);
    img.at(1, 0) = glm::vec4(2.0f, -1.0f, std::numeric_limits<float>::quiet_NaN(), 1.5f);  // clamped
    const std::string path = file_in(dir, "round.png");
    tf::write_image(path, img);
    const tf::Image back = tf::read_image(path, tf::ColorSpace::automatic, 16384);
    CHECK_EQ(back.width, 37);
    CHECK_EQ(back.height, 23);

    // Quantising the encoded value moves it by at most half a code; the linear bound follows from
    // the decode curve around each value (the curve is monotonic, so the end points bound it).
    const double half_code = 0.5 / 255.0;
    // Globally: the decode curve's steepest slope is at code 1, d/de ((e+0.055)/1.055)^2.4 = 2.4/1.055.
    const double global_bound = 2.4 / 1.055 * half_code;  // about 0.00446
    for (size_t i = 0; i < img.texels.size(); ++i) {
        for (int c = 0; c < 4; ++c) {
            float v = img.texels[i][c];
            v = std::isnan(v) ? 0.0f : std::fmin(std::fmax(v, 0.0f), 1.0f);
            const double got = back.texels[i][c];
            double lo, hi;
            if (c == 3) {
                lo = v - half_code;
                hi = v + half_code;
            } else {
                const double e = tf::linear_to_srgb(v);
                lo = tf::srgb_to_linear(std::fmax(0.0, e - half_code));
                hi = tf::srgb_to_linear(std::fmin(1.0, e + half_code));
                // And the exact expected value: the decode of the rounded code.
                CHECK_NEAR(got, tf::srgb_to_linear(std::round(e * 255.0) / 255.0), 1e-6);
            }
            CHECK(got >= lo - 1e-6 && got <= hi + 1e-6);
            CHECK(std::fabs(got - v) <= global_bound + 1e-6);
        }
    }
    // Straight alpha survives: an alpha-0 texel keeps its colour.
    CHECK_EQ(back.at(0, 0).g, 1.0f);
    CHECK_EQ(back.at(0, 0).a, 0.0f);
    CHECK_EQ(back.at(1, 0).r, 1.0f);
    CHECK_EQ(back.at(1, 0).g, 0.0f);
    CHECK_EQ(back.at(1, 0).b, 0.0f);
    CHECK_EQ(back.at(1, 0).a, 1.0f);

    // Raw read: the stored codes / 255, no decode.
    const tf::Image raw = tf::read_image_raw(path);
    CHECK_NEAR(raw.at(0, 0).b, std::round(tf::linear_to_srgb(0.001f) * 255.0) / 255.0, 1e-7);
    CHECK_EQ(entries_in(dir), 1u);  // no temp file left beside it
}

TEST_CASE("exr-round-trip")
{
    const fs::path dir = tf::test::make_work_dir("test-diff-exr-round-trip");
    tf::Image img = noise_image(19, 11, 5);
    img.at(0, 0) = glm::vec4(1000.5f, 1e-3f, 0.0f, 2.0f);  // outside [0,1] is kept, linear
    img.at(1, 0) = glm::vec4(std::numeric_limits<float>::infinity(), -3.0f, 0.1f, 0.9f);
    const std::string path = file_in(dir, "round.exr");
    tf::write_image(path, img);
    // As a texture the +Inf texel is refused, naming it; diff's raw read keeps every value (EXR: linear).
    CHECK_THROWS_WITH(tf::read_image(path, tf::ColorSpace::automatic, 16384),
                      (path + ": texel (1, 0) is +Inf (channel R; 1 of 209 texels hold NaN or Inf): every filter "
                              "needs finite texels").c_str());
    const tf::Image back = tf::read_image_raw(path);
    CHECK_EQ(back.width, 19);
    CHECK_EQ(back.height, 11);
    const double rel = std::ldexp(1.0, -11);  // half: 10 mantissa bits, round to nearest
    for (size_t i = 0; i < img.texels.size(); ++i)
        for (int c = 0; c < 4; ++c) {
            const double v = img.texels[i][c], got = back.texels[i][c];
            if (std::isinf(v)) CHECK_EQ(got, v);
            else CHECK_NEAR(got, v, std::fabs(v) * rel + std::ldexp(1.0, -25));  // abs term: subnormals
        }
    CHECK_EQ(entries_in(dir), 1u);  // no temp file left beside it
}

TEST_CASE("bad-inputs")
{
    const fs::path dir = tf::test::make_work_dir("test-diff-bad-inputs");
    const std::string missing = file_in(dir, "missing.png");
    CHECK_THROWS_WITH(tf::read_image(missing, tf::ColorSpace::automatic, 16384), missing + ": no such file");
    CHECK_THROWS_WITH(tf::read_image_raw(missing), missing + ": no such file");

    const std::string empty = file_in(dir, "empty.png");
    write_bytes(empty, {});
    CHECK_THROWS_WITH(tf::read_image(empty, tf::ColorSpace::automatic, 16384), empty + ": file is empty");

    const std::string random = file_in(dir, "random.png");
    std::mt19937 rng(6);
    std::vector<char> noise(1000);
    for (char& ch : noise) ch = char(rng() & 0xff);
    write_bytes(random, noise);
    CHECK_THROWS_WITH(tf::read_image(random, tf::ColorSpace::automatic, 16384), random + ":");
    const std::string random_exr = file_in(dir, "random.exr");
    write_bytes(random_exr, noise);
    CHECK_THROWS_WITH(tf::read_image(random_exr, tf::ColorSpace::automatic, 16384), random_exr + ":");

    // A real PNG cut short, and one with its compressed data scrambled: the header parses, pixels do not.
    const std::string good = file_in(dir, "good.png");
    tf::write_image(good, noise_image(64, 64, 7));
    std::vector<char> bytes = read_bytes(good);
    CHECK(bytes.size() > 1000);
    const std::string truncated = file_in(dir, "truncated.png");
    write_bytes(truncated, std::vector<char>(bytes.begin(), bytes.begin() + long(bytes.size() / 2)));
    CHECK_THROWS_WITH(tf::read_image(truncated, tf::ColorSpace::automatic, 16384), truncated + ":");
    CHECK_THROWS_WITH(tf::read_image_raw(truncated), truncated + ":");
    const std::string scrambled = file_in(dir, "scrambled.png");
    for (size_t i = 200; i < bytes.size() - 100; i += 7) bytes[i] = char(bytes[i] ^ 0x5a);
    write_bytes(scrambled, bytes);
    CHECK_THROWS_WITH(tf::read_image(scrambled, tf::ColorSpace::automatic, 16384), scrambled + ":");

    // A directory is not a file.
    CHECK_THROWS_WITH(tf::read_image(dir.string(), tf::ColorSpace::automatic, 16384), dir.string());

    // Too large for the caller's limit, on either side.
    tf::write_image(file_in(dir, "wide.png"), tf::make_image(20, 10, glm::vec4(0.5f)));
    CHECK_THROWS_WITH(tf::read_image(file_in(dir, "wide.png"), tf::ColorSpace::automatic, 16),
                      file_in(dir, "wide.png") + ": 20x10 exceeds the maximum texture size 16");
    CHECK_EQ(tf::read_image(file_in(dir, "wide.png"), tf::ColorSpace::automatic, 20).width, 20);
    tf::write_image(file_in(dir, "tall.png"), tf::make_image(3, 40, glm::vec4(0.5f)));
    CHECK_THROWS_WITH(tf::read_image(file_in(dir, "tall.png"), tf::ColorSpace::automatic, 39),
                      "3x40 exceeds the maximum texture size 39");
}

TEST_CASE("bad-outputs")
{
    const fs::path dir = tf::test::make_work_dir("test-diff-bad-outputs");
    const fs::path sub = dir / "out";
    fs::create_directories(sub);
    const tf::Image img = noise_image(4, 4, 8);

    const std::string tga = (sub / "image.tga").string();
    CHECK_THROWS_WITH(tf::write_image(tga, img), tga);
    CHECK_THROWS_WITH(tf::write_image((sub / "noext").string(), img), (sub / "noext").string());
    CHECK_EQ(entries_in(sub), 0u);

    const std::string nowhere = (sub / "no" / "such" / "dir" / "image.png").string();
    CHECK_THROWS_WITH(tf::write_image(nowhere, img), nowhere);
    const std::string nowhere_exr = (sub / "nodir" / "image.exr").string();
    CHECK_THROWS_WITH(tf::write_image(nowhere_exr, img), nowhere_exr);
    CHECK_EQ(entries_in(sub), 0u);

    CHECK_THROWS_WITH(tf::write_image((sub / "empty.png").string(), tf::Image{}), "empty.png");
    CHECK_EQ(entries_in(sub), 0u);

    // Upper-case extensions are still PNG / EXR.
    tf::write_image((sub / "UPPER.PNG").string(), img);
    CHECK(fs::exists(sub / "UPPER.PNG"));
    CHECK_EQ(entries_in(sub), 1u);
}

TEST_CASE("channel-layouts")
{
    const fs::path dir = tf::test::make_work_dir("test-diff-channel-layouts");
    const double decoded128 = 0.2158605;  // sRGB code 128 in linear light
    const int w = 3, h = 2;

    const std::string grey = file_in(dir, "grey.png");
    CHECK(oiio_write(grey, w, h, 1, OIIO::TypeDesc::UINT8, std::vector<uint8_t>(w * h, 128)));
    const tf::Image g = tf::read_image(grey, tf::ColorSpace::automatic, 16384);
    CHECK_EQ(g.width, w);
    CHECK_EQ(g.height, h);
    for (const glm::vec4& t : g.texels) {
        CHECK_NEAR(t.r, decoded128, 1e-6);
        CHECK_EQ(t.g, t.r);
        CHECK_EQ(t.b, t.r);
        CHECK_EQ(t.a, 1.0f);
    }
    const tf::Image gl = tf::read_image(grey, tf::ColorSpace::linear, 16384);
    CHECK_NEAR(gl.at(2, 1).r, 128.0 / 255.0, 1e-7);
    CHECK_EQ(gl.at(2, 1).a, 1.0f);
    CHECK_NEAR(tf::read_image_raw(grey).at(1, 1).b, 128.0 / 255.0, 1e-7);

    const std::string rgb = file_in(dir, "rgb.png");
    std::vector<uint8_t> px;
    for (int i = 0; i < w * h; ++i) px.insert(px.end(), {128, 0, 255});
    px[3 * 4 + 1] = 10;  // pixel (1, 1) green: below the linear-segment breakpoint
    CHECK(oiio_write(rgb, w, h, 3, OIIO::TypeDesc::UINT8, px));
    const tf::Image c = tf::read_image(rgb, tf::ColorSpace::automatic, 16384);
    CHECK_NEAR(c.at(0, 0).r, decoded128, 1e-6);
    CHECK_EQ(c.at(0, 0).g, 0.0f);
    CHECK_NEAR(c.at(0, 0).b, 1.0, 1e-7);
    CHECK_EQ(c.at(0, 0).a, 1.0f);
    CHECK_NEAR(c.at(1, 1).g, 10.0 / 255.0 / 12.92, 1e-8);
    const tf::Image cl = tf::read_image(rgb, tf::ColorSpace::linear, 16384);
    CHECK_NEAR(cl.at(2, 0).r, 128.0 / 255.0, 1e-7);
    CHECK_EQ(cl.at(2, 0).a, 1.0f);

    // An 8-bit file that says it is linear is taken at its word, unless sRGB is forced.
    const std::string lin = file_in(dir, "linear_tagged.png");
    CHECK(oiio_write(lin, w, h, 3, OIIO::TypeDesc::UINT8, std::vector<uint8_t>(w * h * 3, 128), "Linear"));
    CHECK_NEAR(tf::read_image(lin, tf::ColorSpace::automatic, 16384).at(1, 0).r, 128.0 / 255.0, 1e-7);
    CHECK_NEAR(tf::read_image(lin, tf::ColorSpace::srgb, 16384).at(1, 0).r, decoded128, 1e-6);

    // Grey + alpha: alpha is never decoded.
    const std::string ga = file_in(dir, "grey_alpha.png");
    std::vector<uint8_t> gapx;
    for (int i = 0; i < w * h; ++i) gapx.insert(gapx.end(), {128, 64});
    CHECK(oiio_write(ga, w, h, 2, OIIO::TypeDesc::UINT8, gapx));
    const tf::Image gat = tf::read_image(ga, tf::ColorSpace::automatic, 16384);
    CHECK_NEAR(gat.at(1, 0).r, decoded128, 1e-6);
    CHECK_EQ(gat.at(1, 0).b, gat.at(1, 0).r);
    CHECK_NEAR(gat.at(1, 0).a, 64.0 / 255.0, 1e-7);  // unassociated: no premultiply on read

    // 16-bit PNG is sRGB too.
    const std::string deep = file_in(dir, "deep.png");
    CHECK(oiio_write(deep, w, h, 4, OIIO::TypeDesc::UINT16, std::vector<uint16_t>(w * h * 4, 32768)));
    const tf::Image d = tf::read_image(deep, tf::ColorSpace::automatic, 16384);
    CHECK_NEAR(d.at(0, 1).g, tf::srgb_to_linear(32768.0 / 65535.0), 1e-6);
    CHECK_NEAR(d.at(0, 1).a, 32768.0 / 65535.0, 1e-7);

    // Float EXR is linear unless forced; one channel expands like grey.
    const std::string fexr = file_in(dir, "grey.exr");
    CHECK(oiio_write(fexr, w, h, 1, OIIO::TypeDesc::FLOAT, std::vector<float>(w * h, 0.5f)));
    const tf::Image fe = tf::read_image(fexr, tf::ColorSpace::automatic, 16384);
    CHECK_EQ(fe.at(2, 1).r, 0.5f);
    CHECK_EQ(fe.at(2, 1).b, 0.5f);
    CHECK_EQ(fe.at(2, 1).a, 1.0f);
    CHECK_NEAR(tf::read_image(fexr, tf::ColorSpace::srgb, 16384).at(0, 0).g, tf::srgb_to_linear(0.5), 1e-6);

    // More than four channels: the first four (R, G, B, A) are used.
    const std::string five = file_in(dir, "five.exr");
    std::vector<float> fpx;
    for (int i = 0; i < w * h; ++i) fpx.insert(fpx.end(), {0.1f, 0.2f, 0.3f, 0.4f, 9.0f});
    CHECK(oiio_write(five, w, h, 5, OIIO::TypeDesc::FLOAT, fpx));
    const tf::Image f5 = tf::read_image(five, tf::ColorSpace::automatic, 16384);
    CHECK_EQ(f5.at(1, 1).r, 0.1f);
    CHECK_EQ(f5.at(1, 1).g, 0.2f);
    CHECK_EQ(f5.at(1, 1).b, 0.3f);
    CHECK_EQ(f5.at(1, 1).a, 0.4f);
}

// ---------------------------------------------------------------------------------------------
// report.h

TEST_CASE("report")
{
    const fs::path dir = tf::test::make_work_dir("test-diff-report");
    const fs::path sub = dir / "report";
    fs::create_directories(sub);
    const std::string path = (sub / "index.html").string();
    std::vector<tf::ReportCase> cases = {
        {"plane/bilinear", true, "max error 0 at (0, 0)\nPASS", "", "", ""},
        {"plane/<ewa> & \"friends\"", false, "max error 0.5 at (5, 2)\nFAIL", "ewa.actual.png", "ewa.golden.png",
         "ewa.diff.png"},
        {"plane/trilinear", true, "PASS", "", "", ""},
    };
    tf::write_html_report(path, "texfilter golden <regression>", cases);
    CHECK_EQ(entries_in(sub), 1u);
    const std::vector<char> bytes = read_bytes(path);
    const std::string html(bytes.begin(), bytes.end());
    CHECK_CONTAINS(html, "2 passed");
    CHECK_CONTAINS(html, "1 failed");
    CHECK_CONTAINS(html, "texfilter golden &lt;regression&gt;");
    CHECK_CONTAINS(html, "plane/&lt;ewa&gt; &amp; &quot;friends&quot;");
    CHECK(html.find("<ewa>") == std::string::npos);
    CHECK_CONTAINS(html, "src=\"ewa.actual.png\"");
    CHECK_CONTAINS(html, "src=\"ewa.golden.png\"");
    CHECK_CONTAINS(html, "src=\"ewa.diff.png\"");
    CHECK_CONTAINS(html, "image-rendering: pixelated");
    CHECK(html.find("<script") == std::string::npos);
    CHECK(html.find("http") == std::string::npos);
    const size_t fail_at = html.find("friends"), pass_at = html.find("plane/bilinear");
    CHECK(fail_at != std::string::npos && pass_at != std::string::npos && fail_at < pass_at);
    CHECK(html.find("plane/bilinear") < html.find("plane/trilinear"));

    CHECK_THROWS_WITH(tf::write_html_report((sub / "nodir" / "x.html").string(), "t", cases), "x.html");
    CHECK_EQ(entries_in(sub), 1u);
}

} // namespace

