// --format: the table, the quantisation every upload applies (core/texture_format.h), and each format
// through `texfilter sample` on the device against the CPU reference reading the same rounded texels.
//
// Bounds: unorm (c / (2^b - 1)), binary16 and uint (below 2^24) convert to float exactly, so there the
// manual filters on the GPU match the reference up to float32 arithmetic: float_error of the texel range
// (the one bound the rest of the suite uses for values in [0, 1]), times the integer scale for uint data.
// The sRGB decode is the one conversion a device approximates: lavapipe's texelFetch of R8G8B8A8_SRGB is
// off the exact EOTF by up to 0.16 of a code's step (code 218: 0.699907 for 0.701102). We allow any decode
// that still tells each code from its neighbours, half the step between adjacent codes at the top of the
// range (the widest: 0.5 (1 - EOTF(254/255)) = 0.0043); a missing or doubled decode is off by ~0.15.
#include "core/procedural.h"
#include "core/texture_format.h"
#include "io/texture_source.h"
#include "support.h"
#include "texture/error.h"
#include "texture/image.h"
#include <glm/gtc/packing.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

using namespace tf;

namespace {

const double float_error = 2e-6;

// Half the linear step between sRGB codes 254 and 255 (see the top of the file).
double srgb_decode_allowance() { return 0.5 * (1.0 - double(srgb8_decode_table()[254])); }

uint32_t packed_code(float value, TextureFormat format) // the first channel's stored bits
{
    const glm::vec4 texel(value, value, value, value);
    unsigned char bytes[16] = {};
    pack_texels(&texel, 1, format, bytes);
    uint32_t code = 0;
    std::memcpy(&code, bytes, format_info(format).bits / 8);
    return code;
}

// GLM's decode as the independent oracle (its encode rounds ties away from zero, so only the decode).
float half_from_bits(uint16_t bits) { return glm::unpackHalf1x16(bits); }

} // namespace

TEST_SUITE_BEGIN("reference");

TEST_CASE("names")
{
    for (TextureFormat f : all_texture_formats())
        CHECK(parse_texture_format(to_string(f)) == f, to_string(f));
    CHECK(all_texture_formats().size() == 9);
    CHECK_THROWS_WITH(parse_texture_format("rgba8_srgb"),
                      "unknown texture format 'rgba8_srgb' (expected one of: rgba32f, rgba8-srgb, rgba8, rgba16f, r8, "
                      "r16f, r32f, r16ui, r32ui)");
    CHECK(texel_bytes(TextureFormat::rgba8_srgb) == 4 && texel_bytes(TextureFormat::rgba16f) == 8 &&
          texel_bytes(TextureFormat::r16ui) == 2 && texel_bytes(TextureFormat::r32f) == 4);
}

// unorm8: code = round(v * 255), read back as code / 255; every code survives the round trip.
TEST_CASE("unorm8-codes")
{
    for (int c = 0; c <= 255; ++c) {
        const float exact = float(c / 255.0);
        CHECK(quantise_texel(glm::vec4(exact), TextureFormat::rgba8).r == exact, std::to_string(c));
        CHECK(packed_code(exact, TextureFormat::r8) == uint32_t(c), std::to_string(c));
        if (c < 255) {
            CHECK(packed_code(float((c + 0.49) / 255.0), TextureFormat::rgba8) == uint32_t(c), std::to_string(c));
            CHECK(packed_code(float((c + 0.51) / 255.0), TextureFormat::rgba8) == uint32_t(c + 1), std::to_string(c));
        }
    }
    CHECK(packed_code(-0.5f, TextureFormat::rgba8) == 0 && packed_code(7.0f, TextureFormat::rgba8) == 255);
}

// sRGB8: R, G, B are the rounded sRGB encode of the linear value, decoded by the exact EOTF; alpha is unorm8.
TEST_CASE("srgb8-codes")
{
    const auto& table = srgb8_decode_table();
    for (int c = 0; c <= 255; ++c) {
        const glm::vec4 q = quantise_texel(glm::vec4(table[size_t(c)], table[size_t(c)], table[size_t(c)], float(c / 255.0)),
                                           TextureFormat::rgba8_srgb);
        CHECK(q.r == table[size_t(c)] && q.a == float(c / 255.0), std::to_string(c));
        CHECK(packed_code(table[size_t(c)], TextureFormat::rgba8_srgb) == uint32_t(c), std::to_string(c));
        CHECK_NEAR(table[size_t(c)], srgb_to_linear(c / 255.0), 1e-7);
    }
    // Linear 0.5 encodes to 0.7354 (code 188 after rounding 187.52), not 128 (what unorm would store).
    CHECK(packed_code(0.5f, TextureFormat::rgba8_srgb) == 188, std::to_string(packed_code(0.5f, TextureFormat::rgba8_srgb)));
    // Alpha stays linear: 0.5 -> round(127.5) = 128 (ties to even).
    glm::vec4 texel(0.5f);
    unsigned char bytes[4];
    pack_texels(&texel, 1, TextureFormat::rgba8_srgb, bytes);
    CHECK(bytes[0] == 188 && bytes[3] == 128, std::to_string(bytes[0]) + " " + std::to_string(bytes[3]));
}

// binary16: round to nearest, ties to even, subnormals kept; every finite half survives the round trip.
TEST_CASE("half-round-to-nearest-even")
{
    for (uint32_t bits = 0; bits < 0x10000; ++bits) {
        if ((bits & 0x7c00) == 0x7c00)
            continue; // Inf and NaN
        const float h = half_from_bits(uint16_t(bits));
        CHECK(quantise_texel(glm::vec4(h), TextureFormat::rgba16f).r == h, std::to_string(bits));
        if (bits != 0x8000) // -0 packs as itself too, but compare the bits of the rest
            CHECK(packed_code(h, TextureFormat::r16f) == bits, std::to_string(bits));
    }
    const float ulp1 = std::ldexp(1.0f, -10); // binary16's step on [1, 2)
    CHECK(quantise_texel(glm::vec4(1.0f + ulp1 / 2), TextureFormat::r16f).r == 1.0f);               // tie: to even
    CHECK(quantise_texel(glm::vec4(1.0f + 3 * ulp1 / 2), TextureFormat::r16f).r == 1.0f + 2 * ulp1); // tie: to even
    CHECK(quantise_texel(glm::vec4(1.0f + ulp1 * 0.51f), TextureFormat::r16f).r == 1.0f + ulp1);
    const float tiny = std::ldexp(1.0f, -24); // the smallest subnormal
    CHECK(quantise_texel(glm::vec4(tiny / 2), TextureFormat::r16f).r == 0.0f);        // tie: to even (zero)
    CHECK(quantise_texel(glm::vec4(tiny * 0.75f), TextureFormat::r16f).r == tiny);     // kept, not flushed
    CHECK(quantise_texel(glm::vec4(1e6f), TextureFormat::r16f).r == INFINITY);
    // Bits known from IEEE 754 itself, not from the code under test: the largest half, the rounding to Inf
    // at the midpoint 65520, a negative power of two, 1/3 (0x3555: 0.333251953125), the smallest normal.
    CHECK(packed_code(65504.0f, TextureFormat::r16f) == 0x7bffu);
    CHECK(packed_code(65519.0f, TextureFormat::r16f) == 0x7bffu);
    CHECK(packed_code(65520.0f, TextureFormat::r16f) == 0x7c00u);
    CHECK(packed_code(-2.0f, TextureFormat::r16f) == 0xc000u);
    CHECK(packed_code(1.0f / 3.0f, TextureFormat::r16f) == 0x3555u);
    CHECK(packed_code(std::ldexp(1.0f, -14), TextureFormat::r16f) == 0x0400u);
    CHECK(half_from_bits(0x3555u) == 0.333251953125f);
}

// uint data: a texel value v in [0, 1] is the code round(v * scale), clamped; read as float(code).
TEST_CASE("uint-mapping")
{
    CHECK(integer_scale(TextureFormat::r16ui) == 65535.0 && integer_scale(TextureFormat::r32ui) == 16777215.0);
    CHECK(quantise_texel(glm::vec4(1.0f), TextureFormat::r16ui).r == 65535.0f);
    CHECK(quantise_texel(glm::vec4(0.5f), TextureFormat::r16ui).r == 32768.0f); // 32767.5, ties to even
    CHECK(quantise_texel(glm::vec4(-1.0f), TextureFormat::r16ui).r == 0.0f);
    CHECK(quantise_texel(glm::vec4(3.0f), TextureFormat::r16ui).r == 65535.0f); // clamped to the type
    CHECK(quantise_texel(glm::vec4(1.0f), TextureFormat::r32ui).r == 16777215.0f);
    CHECK(quantise_texel(glm::vec4(1000.0f), TextureFormat::r32ui).r == float(4294967295.0)); // the type's top
    for (float code : {0.0f, 1.0f, 12345.0f, 65535.0f}) {
        CHECK(packed_code(code, TextureFormat::r16ui) == uint32_t(code), std::to_string(code));
        CHECK(packed_code(code, TextureFormat::r32ui) == uint32_t(code), std::to_string(code));
    }
    CHECK(packed_code(16777215.0f, TextureFormat::r32ui) == 16777215u);
}

// One-channel formats keep R and read G = B = 0, A = 1, as Vulkan fills missing components.
TEST_CASE("one-channel")
{
    for (TextureFormat f : {TextureFormat::r8, TextureFormat::r16f, TextureFormat::r32f, TextureFormat::r16ui}) {
        const glm::vec4 q = quantise_texel(glm::vec4(0.25f, 0.5f, 0.75f, 0.125f), f);
        CHECK(q.g == 0.0f && q.b == 0.0f && q.a == 1.0f && q.r > 0.0f, to_string(f));
    }
    CHECK(quantise_texel(glm::vec4(0.25f, 0.5f, 0.75f, 0.125f), TextureFormat::r32f).r == 0.25f);
}

// load_texture rounds every level (built in linear float first): each texel of each level is a code.
TEST_CASE("chain-quantised")
{
    TextureSource source;
    source.name_or_path = "zoneplate";
    source.procedural_size = 64;
    source.format = TextureFormat::rgba8;
    const MipChain chain = load_texture(source);
    const MipChain linear = make_procedural("zoneplate", 64);
    CHECK(chain.levels.size() == linear.levels.size());
    int moved = 0;
    for (size_t l = 0; l < chain.levels.size(); ++l)
        for (size_t i = 0; i < chain.levels[l].texels.size(); ++i) {
            const float r = chain.levels[l].texels[i].r;
            CHECK(r * 255.0f == std::nearbyint(r * 255.0f), "level " + std::to_string(l));
            CHECK(std::abs(r - linear.levels[l].texels[i].r) <= 0.5 / 255 + 1e-7, "level " + std::to_string(l));
            moved += r != linear.levels[l].texels[i].r;
        }
    CHECK(moved > 0);
}

// Integer data cannot be filtered by a sampler: hw-* modes and hardware taps are refused up front.
TEST_CASE("integer-refuses-hardware")
{
    SamplerOptions options;
    options.filter = Filter::hw_bilinear;
    CHECK_THROWS_WITH(check_format_filter(TextureFormat::r16ui, options), "--format r16ui holds integer data");
    options.filter = Filter::ewa;
    options.taps = Taps::hardware;
    CHECK_THROWS_WITH(check_format_filter(TextureFormat::r32ui, options), "--taps hardware");
    options.taps = Taps::manual;
    check_format_filter(TextureFormat::r32ui, options); // manual: fine
    options.filter = Filter::hw_aniso;
    check_format_filter(TextureFormat::rgba8_srgb, options); // float formats: fine
}

TEST_SUITE_END();

namespace {

const std::string& lookups_path()
{
    static const std::string path = [] {
        const std::string p = (test::work_dir() / "lookups.csv").string();
        test::write_lookups_csv(p, test::as_float(test::random_footprint_lookups(
                                       384, 913, {.octave_max = 6.0, .max_stretch = 2.0, .texture_size = 64.0})));
        return p;
    }();
    return path;
}

// The device's manual filters against the reference for one format, on a 64x64 zoneplate (every level
// rounded to the format on both sides).
void compare_format(const std::string& format, const std::vector<std::string>& filters)
{
    const TextureFormat f = parse_texture_format(format);
    const double scale = format_info(f).integer ? integer_scale(f) : 1.0;
    const double decode = format_info(f).srgb ? srgb_decode_allowance() : 0.0;
    for (const std::string& filter : filters) {
        const std::string flags = "--texture zoneplate --texture-size 64 --format " + format + " --filter " + filter;
        const auto gpu = test::run_sample(flags, lookups_path(), false).colors;
        const auto cpu = test::run_sample(flags + " --backend reference", lookups_path(), false).colors;
        double worst = 0;
        for (size_t i = 0; i < gpu.size(); ++i)
            worst = std::max(worst, test::max_channel_diff(gpu[i], cpu[i]));
        const double bound = float_error * scale + decode;
        std::printf("%-10s %-12s worst |gpu - reference| %.3g (bound %.3g)\n", format.c_str(), filter.c_str(), worst, bound);
        CHECK(worst <= bound, format + " " + filter + ": " + test::show(worst));
    }
}

} // namespace

TEST_SUITE_BEGIN("gpu");
TEST_CASE("rgba8-srgb") { compare_format("rgba8-srgb", {"nearest", "trilinear", "ewa"}); }
TEST_CASE("rgba8") { compare_format("rgba8", {"trilinear", "aniso"}); }
TEST_CASE("rgba16f") { compare_format("rgba16f", {"trilinear", "ewa"}); }
TEST_CASE("r8") { compare_format("r8", {"bilinear-mip"}); }
TEST_CASE("r16f") { compare_format("r16f", {"brilinear"}); }
TEST_CASE("r32f") { compare_format("r32f", {"trilinear"}); }
TEST_CASE("r16ui") { compare_format("r16ui", {"nearest", "trilinear"}); }
TEST_CASE("r32ui") { compare_format("r32ui", {"bilinear", "ewa"}); }
TEST_SUITE_END();
