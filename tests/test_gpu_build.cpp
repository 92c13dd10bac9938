// The GPU builds (shaders/texfilter/build_mip.glsl, build_sat.glsl) against the host's builders.
//
// SAT: the tables are integers, so the GPU's must equal tf::build_sat's bit for bit (low words, high
// bytes, offset and scale) on every size: odd, NPOT, 1xN, Nx1, ties of the rounding, and 4096x4096 of random
// 16-bit codes (sums up to 2^40 − 2^24: every carry into the high byte).
//
// MIP: tf::downsample forms each texel's sum in double and rounds once; the GPU sums in float. Bound of
// one level built from the same source level, per texel and channel, with u = 2^-23 (one rounding, RTE or
// RTZ: Vulkan allows either): each weight is one division (≤ 2.5 u relative), the horizontal sum of ≤ 3
// products is ≤ 3 roundings deep, the vertical one ≤ 3 more, and the host's result rounds once (½ u):
// |gpu − host| ≤ (2·2.5 + 3 + 3 + ½) u · Σ w·|x| = 11.5 u Σ w|x|; we allow 12.5 u Σ w|x| for the second-
// order terms and the bound's own rounding (Σ w|x| is tf::downsample of |source|), plus 16·2^-126 where a
// device flushes denormals. Over a whole chain built from one level 0 the errors of each level are
// averages of the ones above plus the level's own: the chain bound is the sum of the levels' bounds.
// A wrong tap or weight is off by a fraction of the texels' contrast (≈ 0.1 here), 10^5 times the bound.
#include "core/procedural.h"
#include "core/texture_format.h"
#include "support.h"
#include "texture/error.h"
#include "texture/mip.h"
#include "texture/sat.h"
#include "vulkan/backend.h"
#include "vulkan/gpu_build.h"
#include "vulkan/render.h"
#include "vulkan/textures.h"
#include "io/pfm.h"
#include <glm/gtc/packing.hpp>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>

using namespace tf;

namespace {

constexpr double u = 1.0 / 8388608.0; // 2^-23
constexpr double level_factor = 12.5 * u;
constexpr double denormal_slack = 16.0 * 1.1754943508222875e-38;

Image random_image(int w, int h, unsigned seed, float lo, float hi)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> value(lo, hi);
    Image image = make_image(w, h);
    for (glm::vec4& t : image.texels)
        t = glm::vec4(value(rng), value(rng), value(rng), value(rng));
    return image;
}

struct Device {
    VulkanContext context;
    Device() : context(create_context(test::test_context_options())) {}
    ~Device() { destroy_context(context); }
};

Image read_level(const VulkanContext& context, VkImage image, int level, int w0, int h0)
{
    const int w = std::max(1, w0 >> level), h = std::max(1, h0 >> level);
    std::vector<unsigned char> bytes =
        read_image_level(context, image, uint32_t(level), uint32_t(w), uint32_t(h), sizeof(glm::vec4),
                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    Image out = make_image(w, h);
    std::memcpy(out.texels.data(), bytes.data(), bytes.size());
    return out;
}

Image absolute(const Image& image)
{
    Image out = image;
    for (glm::vec4& t : out.texels)
        t = glm::abs(t);
    return out;
}

// Every GPU level against tf::downsample of the GPU level above (the level's own rounding) and against the
// host chain from the same level 0 (the summed bounds).
void check_mip_build(int w, int h, unsigned seed)
{
    Device device;
    const Image level0 = random_image(w, h, seed, -0.25f, 1.25f);
    const MipChain host = build_mip_chain(level0);
    GpuTexture t = upload_gpu_built_texture(device.context, level0, false, TextureFormat::rgba32f);
    Cleanup cleanup;
    cleanup.add([&] { destroy_texture(device.context, t); });
    CHECK_EQ(t.levels, int(host.levels.size()));
    Image above = read_level(device.context, t.chain.image, 0, w, h);
    CHECK(above.texels == level0.texels, "level 0 uploaded unchanged");
    double chain_bound = 0, worst_level = 0, worst_chain = 0;
    for (int l = 1; l < t.levels; ++l) {
        const Image gpu = read_level(device.context, t.chain.image, l, w, h);
        const Image expected = downsample(above);
        const Image weights = downsample(absolute(above));
        double level_max = 0;
        for (const glm::vec4& x : weights.texels)
            for (int c = 0; c < 4; ++c)
                level_max = std::max(level_max, double(x[c]));
        chain_bound += level_factor * level_max + denormal_slack;
        int level_failures = 0, chain_failures = 0;
        std::string first_level, first_chain;
        for (size_t i = 0; i < gpu.texels.size(); ++i)
            for (int c = 0; c < 4; ++c) {
                const double bound = level_factor * double(weights.texels[i][c]) + denormal_slack;
                const double error = std::abs(double(gpu.texels[i][c]) - double(expected.texels[i][c]));
                const double chain_error = std::abs(double(gpu.texels[i][c]) - double(host.levels[size_t(l)].texels[i][c]));
                worst_level = std::max(worst_level, error / bound);
                worst_chain = std::max(worst_chain, chain_error / chain_bound);
                if (!(error <= bound) && level_failures++ == 0)
                    first_level = "texel " + std::to_string(i) + " channel " + std::to_string(c) + ": gpu " +
                                  test::show(gpu.texels[i][c]) + " host " + test::show(expected.texels[i][c]) +
                                  " bound " + test::show(bound);
                if (!(chain_error <= chain_bound) && chain_failures++ == 0)
                    first_chain = "texel " + std::to_string(i) + ": off by " + test::show(chain_error) + " > " +
                                  test::show(chain_bound);
            }
        CHECK(level_failures == 0, "level " + std::to_string(l) + ": " + std::to_string(level_failures) +
                                       " values outside the level bound, first " + first_level);
        CHECK(chain_failures == 0, "level " + std::to_string(l) + ": " + std::to_string(chain_failures) +
                                       " values outside the chain bound, first " + first_chain);
        above = gpu;
    }
    std::printf("%dx%d: %d levels in %zu passes; worst level error %.3f of its bound, chain %.3f of its bound\n", w, h,
                t.levels, plan_mip_build(w, h).size(), worst_level, worst_chain);
    CHECK_EQ(validation_message_count(), 0);
}

// The GPU tables against build_sat's, word for word.
// format: level 0 is given as decoded and the table sums it rounded to the format (as load_texture's
// quantise_chain before build_sat).
void check_sat_build(const Image& level0, TextureFormat format = TextureFormat::rgba32f)
{
    Device device;
    Image rounded = level0;
    for (glm::vec4& t : rounded.texels)
        t = quantise_texel(t, format);
    const SatTable host = build_sat(rounded);
    GpuTexture t = upload_gpu_built_texture(device.context, level0, true, format);
    Cleanup cleanup;
    cleanup.add([&] { destroy_texture(device.context, t); });
    const uint32_t tw = uint32_t(level0.width) + 1, th = uint32_t(level0.height) + 1;
    std::vector<unsigned char> low = read_image_level(device.context, t.sat_low.image, 0, tw, th, 16,
                                                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    std::vector<unsigned char> high = read_image_level(device.context, t.sat_high.image, 0, tw, th, 4,
                                                       VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    CHECK(std::memcmp(low.data(), host.low.data(), low.size()) == 0, "low words");
    CHECK(std::memcmp(high.data(), host.high.data(), high.size()) == 0, "high bytes");
    size_t first = low.size() / 4;
    for (size_t i = 0; i < low.size() / 4; ++i) {
        uint32_t word;
        std::memcpy(&word, low.data() + 4 * i, 4);
        if (word != host.low[i]) {
            first = i;
            break;
        }
    }
    if (first < low.size() / 4)
        MESSAGE("first differing low word: entry " << first / 4 << " channel " << first % 4);
    for (int c = 0; c < 4; ++c) {
        CHECK(t.sat_offset[c] == host.offset[c], "offset " + test::show(t.sat_offset[c]) + " vs " + test::show(host.offset[c]));
        CHECK(t.sat_scale[c] == host.scale[c], "scale " + test::show(t.sat_scale[c]) + " vs " + test::show(host.scale[c]));
    }
    CHECK_EQ(validation_message_count(), 0);
}

bool skip_without_fp64()
{
    if (!test::test_device_info().shader_float64) {
        std::printf("SKIP: %s lacks shaderFloat64\n", test::test_device_info().name.c_str());
        return true;
    }
    return false;
}

} // namespace

TEST_SUITE_BEGIN("gpu_build");

// ---- The plan (no device) ---------------------------------------------------------------------------------

TEST_CASE("plan")
{
    // Every level built exactly once, in order, each pass's later levels from even (or 1-texel) sides.
    for (auto [w, h] : std::vector<std::pair<int, int>>{{1, 1}, {2, 2}, {256, 256}, {8192, 8192}, {16384, 16384},
                                                          {1023, 511}, {1000, 1000}, {1, 1000}, {777, 1}, {4097, 3}}) {
        const std::vector<MipBuildPass> plan = plan_mip_build(w, h);
        int next = 1;
        const int last = mip_level_count(w, h) - 1;
        for (const MipBuildPass& p : plan) {
            CHECK_EQ(p.source_level, next - 1);
            CHECK(p.levels >= 1 && p.levels <= 6);
            for (int k = 1; k < p.levels; ++k) {
                const int sw = std::max(1, w >> (p.source_level + k)), sh = std::max(1, h >> (p.source_level + k));
                CHECK((sw % 2 == 0 || sw == 1) && (sh % 2 == 0 || sh == 1), std::to_string(w) + "x" + std::to_string(h));
            }
            CHECK_EQ(p.groups_x, (std::max(1, w >> (p.source_level + 1)) + 31) / 32);
            next = p.source_level + p.levels + 1;
            if (p.tail) {
                CHECK(int64_t(std::max(1, w >> (next - 1))) * std::max(1, h >> (next - 1)) <= mip_build_tail_texels);
                next = last + 1;
            }
        }
        CHECK_EQ(next, last + 1);
    }
    CHECK_EQ(plan_mip_build(8192, 8192).size(), 1);  // one dispatch: 6 tile levels, then the tail
    CHECK_EQ(plan_mip_build(4096, 4096).size(), 1);
    CHECK_EQ(plan_mip_build(16384, 16384).size(), 2);
    CHECK_EQ(plan_mip_build(1023, 1023).size(), 3); // odd levels: 511, 255, then 127^2 fits the tail
    CHECK(plan_mip_build(1, 1).empty());
    CHECK_THROWS_WITH(plan_mip_build(0, 5), "empty 0x5");
}

TEST_CASE("range-words")
{
    // The host's reading of the shader's range words: keys, spans rounded up, the first bad texel.
    std::array<uint32_t, sat_range_words> words = sat_range_initial();
    auto key = [](float f) {
        uint32_t b;
        std::memcpy(&b, &f, 4);
        return (b & 0x80000000u) ? ~b : b | 0x80000000u;
    };
    const float lo[4] = {-3.5f, 0.0f, 1e-30f, 7.0f}, hi[4] = {0.1f, 65535.0f, 3e38f, 7.0f};
    for (int c = 0; c < 4; ++c) {
        words[size_t(c)] = key(lo[c]);
        words[size_t(4 + c)] = key(hi[c]);
    }
    glm::vec4 offset, scale;
    sat_range_offset_scale(words, 10, "t", offset, scale);
    Image two = make_image(2, 1);
    two.texels[0] = glm::vec4(lo[0], lo[1], lo[2], lo[3]);
    two.texels[1] = glm::vec4(hi[0], hi[1], hi[2], hi[3]);
    const SatTable table = build_sat(two);
    for (int c = 0; c < 4; ++c) {
        CHECK(offset[c] == table.offset[c]);
        CHECK(scale[c] == table.scale[c], test::show(scale[c]) + " vs " + test::show(table.scale[c]));
    }
    words[8] = (23u << 4) | (1u << 2) | 2u; // texel 23 of a 10-wide texture: (3, 2), NaN in B
    CHECK_THROWS_WITH(sat_range_offset_scale(words, 10, "t", offset, scale),
                      "texture t: texel (3, 2) is NaN: sat needs finite texels (channel B)");
}

// ---- MIP levels -----------------------------------------------------------------------------------------

TEST_CASE("mip-pow2-256") { check_mip_build(256, 256, 1); }
TEST_CASE("mip-npot-333x199") { check_mip_build(333, 199, 2); }
TEST_CASE("mip-odd-1023x511") { check_mip_build(1023, 511, 3); } // every level odd on both axes
TEST_CASE("mip-1xN") { check_mip_build(1, 1000, 4); }
TEST_CASE("mip-Nx1") { check_mip_build(777, 1, 5); }
TEST_CASE("mip-even-then-odd-1000x600") { check_mip_build(1000, 600, 6); } // tile levels, then odd, then the tail
TEST_CASE("mip-2048") { check_mip_build(2048, 2048, 7); } // one dispatch: the tail takes levels 7..11

TEST_CASE("mip-too-big")
{
    Device device;
    Cleanup cleanup;
    const GpuBuildKernels kernels = create_gpu_build_kernels(device.context, cleanup);
    CHECK_THROWS_WITH(create_mip_build_target(device.context, kernels, VK_NULL_HANDLE, 16385, 4, cleanup),
                      "texture 16385x4 is outside 1..");
    CHECK_THROWS_WITH(upload_gpu_built_texture(device.context, make_image(4, 4), false, TextureFormat::r16ui),
                      "r16ui is integer data");
}

// Formats other than RGBA32F: built in linear RGBA32F, then each level stored into the format (encode.glsl's
// rounding, or the device's blit where it cannot pack). The device's float levels differ from the host's
// by at most the chain bound (values in [0, 1]: 1e-5, check_mip_build), so a stored code may differ from
// the host's only where the host's value lies within that of a rounding boundary, i.e. where v - 1e-5 and
// v + 1e-5 pack to different codes; there one step (adjacent codes or halves) is allowed, elsewhere none.
// A device that cannot pack the format blits instead, whose rounding Vulkan leaves to either neighbour: one
// step anywhere. Level 0 is stored from the host's own codes: exact everywhere. Texels are drawn from [lo, hi].
void check_format_build(TextureFormat format, int w, int h, float lo = 0.0f, float hi = 1.0f)
{
    Device device;
    Image level0 = random_image(w, h, 11, lo, hi);
    for (glm::vec4& t : level0.texels)
        t = quantise_texel(t, format); // what load_texture hands the upload: level 0 as the format stores it
    MipChain host = build_mip_chain(level0);
    const MipChain host_float = host;
    quantise_chain(host, format);
    GpuTexture t = upload_gpu_built_texture(device.context, level0, false, format);
    Cleanup cleanup;
    cleanup.add([&] { destroy_texture(device.context, t); });
    const size_t bytes = texel_bytes(format);
    const size_t channels = size_t(format_info(format).channels);
    const size_t channel_bytes = bytes / channels;
    constexpr float chain_bound = 1e-5f;
    const bool packed = pack_supported(device.context, GpuBuildKernels{}, format); // else blitted
    auto code_of = [&](glm::vec4 texel, size_t channel) { // the host's stored code of one channel
        std::vector<unsigned char> packed(bytes);
        pack_texels(&texel, 1, format, packed.data());
        uint32_t code = 0;
        std::memcpy(&code, packed.data() + channel * channel_bytes, channel_bytes);
        return code;
    };
    int off_by_one = 0, near_boundary = 0, total = 0, failures = 0;
    std::string first;
    for (int l = 0; l < t.levels; ++l) {
        const int lw = std::max(1, w >> l), lh = std::max(1, h >> l);
        std::vector<unsigned char> gpu = read_image_level(device.context, t.chain.image, uint32_t(l), uint32_t(lw),
                                                          uint32_t(lh), bytes, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        std::vector<unsigned char> expected(gpu.size());
        pack_texels(host.levels[size_t(l)].texels.data(), host.levels[size_t(l)].texels.size(), format, expected.data());
        for (size_t i = 0; i < gpu.size() / channel_bytes; ++i) {
            uint32_t a = 0, b = 0;
            std::memcpy(&a, gpu.data() + i * channel_bytes, channel_bytes);
            std::memcpy(&b, expected.data() + i * channel_bytes, channel_bytes);
            const glm::vec4 v = host_float.levels[size_t(l)].texels[i / channels];
            const bool boundary = l > 0 && (!packed || code_of(v - chain_bound, i % channels) !=
                                                           code_of(v + chain_bound, i % channels));
            const int64_t steps = std::abs(int64_t(a) - int64_t(b));
            ++total;
            near_boundary += boundary;
            off_by_one += steps == 1;
            if (!(steps == 0 || (boundary && steps == 1)) && failures++ == 0)
                first = "level " + std::to_string(l) + " value " + std::to_string(i) + " (host " +
                        test::show(v[int(i % channels)]) + "): code " + std::to_string(a) + " vs " + std::to_string(b);
        }
    }
    CHECK(failures == 0, std::to_string(failures) + " stored values off the host's code away from a rounding boundary "
                         "(or more than one step at one), first " + first);
    std::printf("%s (%s): %d of %d stored values one step from the host's, %d allowed to be\n", to_string(format).c_str(),
                packed ? "packed" : "blitted", off_by_one, total, near_boundary);
    CHECK_EQ(validation_message_count(), 0);
}

TEST_CASE("format-rgba16f") { check_format_build(TextureFormat::rgba16f, 301, 157); }
TEST_CASE("format-rgba8-srgb") { check_format_build(TextureFormat::rgba8_srgb, 301, 157); }
TEST_CASE("format-r8") { check_format_build(TextureFormat::r8, 128, 96); }
// Codes 0 and 1 only: the levels' means (0, 1/4, 1/2, 3/4, 1)/255 include values below 2^-8, whose
// unorm8 code 1 encode.glsl once returned as 0.
TEST_CASE("format-r8-darkest") { check_format_build(TextureFormat::r8, 64, 64, 0.0f, 1.5f / 255.0f); }
TEST_CASE("format-rgba8-srgb-darkest") { check_format_build(TextureFormat::rgba8_srgb, 64, 64, 0.0f, 0.002f); }

// ---- Summed-area tables ---------------------------------------------------------------------------------

TEST_CASE("sat-odd-37x23")
{
    if (skip_without_fp64()) return;
    Image image = random_image(37, 23, 21, 0.0f, 1.0f);
    for (glm::vec4& t : image.texels)
        t.a = 1.0f; // a constant channel: scale 0, every level 0
    check_sat_build(image);
}
TEST_CASE("sat-npot-hdr-300x200")
{
    if (skip_without_fp64()) return;
    check_sat_build(random_image(300, 200, 22, -1000.0f, 5000.0f));
}
TEST_CASE("sat-1xN")
{
    if (skip_without_fp64()) return;
    check_sat_build(random_image(1, 777, 23, 0.0f, 1.0f));
}
TEST_CASE("sat-Nx1")
{
    if (skip_without_fp64()) return;
    check_sat_build(random_image(999, 1, 24, 0.0f, 1.0f));
}
TEST_CASE("sat-rounding-ties")
{
    // Offset 0 and scale 65535: q = round(v), so v = k + 0.5 are exact ties (half away from zero: k + 1).
    if (skip_without_fp64()) return;
    Image image = make_image(64, 64);
    for (size_t i = 0; i < image.texels.size(); ++i)
        image.texels[i] = glm::vec4(float(i % 65535) + 0.5f, float(i * 7 % 65535) + 0.5f, float(i), 0.5f + float(i % 2));
    image.texels[0] = glm::vec4(0.0f);
    image.texels[1] = glm::vec4(65535.0f);
    check_sat_build(image);
}
TEST_CASE("sat-4096-random-16bit")
{
    // Random 16-bit codes with 0 and 65535 present: q is the code, and the table's sums reach 2^40 − 2^24.
    if (skip_without_fp64()) return;
    std::mt19937 rng(25);
    std::uniform_int_distribution<int> code(0, 65535);
    Image image = make_image(4096, 4096);
    for (glm::vec4& t : image.texels)
        t = glm::vec4(float(code(rng)), float(code(rng)), float(code(rng)), 65535.0f);
    image.texels[5] = glm::vec4(0.0f);
    image.texels[6] = glm::vec4(65535.0f);
    check_sat_build(image);
}
TEST_CASE("sat-rgba8-srgb")
{
    // Built from the rounded level 0 (the levels from the unrounded one).
    if (skip_without_fp64()) return;
    check_sat_build(random_image(130, 70, 27, 0.0f, 1.0f), TextureFormat::rgba8_srgb);
}
TEST_CASE("sat-non-finite")
{
    Device device;
    Image image = random_image(20, 10, 26, 0.0f, 1.0f);
    image.at(7, 3).g = INFINITY;
    image.at(2, 8).r = NAN; // later in row order: the first one is reported
    CHECK_THROWS_WITH(upload_gpu_built_texture(device.context, image, true, TextureFormat::rgba32f),
                      "summed-area table: texel (7, 3) is +Inf: sat needs finite texels (channel G)");
    CHECK_EQ(validation_message_count(), 0);
}

// ---- Built and filtered in one submission, under synchronisation validation --------------------------------

TEST_CASE("one-submission")
{
    // The layer checks every hazard between the copy, the build's passes and the filter's reads.
    setenv("TEXFILTER_SYNC_VALIDATION", "1", 1);
    Device device;
    const Image level0 = random_image(200, 120, 31, 0.0f, 1.0f);
    const MipChain host = build_mip_chain(level0);
    GpuBuild build = prepare_gpu_build(device.context, &level0, 200, 120, true, TextureFormat::rgba32f);
    Cleanup cleanup;
    cleanup.add([&] { destroy_gpu_build(device.context, build); });
    std::vector<Lookup> lookups = test::as_float(test::random_footprint_lookups(
        256, 32, {.uv_min = -0.5, .uv_max = 1.5, .octave_min = -2, .octave_max = 8, .max_stretch = 3, .texture_size = 200}));
    SamplerOptions options;
    options.filter = Filter::trilinear;
    const std::vector<glm::vec4> built = gpu_sample(device.context, build.texture, lookups, options, nullptr,
                                                    [&](VkCommandBuffer cb) { record_gpu_build(cb, build, Level0::from_staging); });
    finish_gpu_build(build);
    std::vector<glm::vec4> uploaded = with_texture(device.context, host, false, [&](const GpuTexture& t) {
        return gpu_sample(device.context, t, lookups, options);
    });
    // Same filter, levels within the chain bound of each other (< 1e-5 for values in [0, 1]).
    double worst = 0;
    for (size_t i = 0; i < lookups.size(); ++i)
        for (int c = 0; c < 4; ++c)
            worst = std::max(worst, std::abs(double(built[i][c]) - double(uploaded[i][c])));
    CHECK(worst <= 1e-5, "largest difference " + test::show(worst));
    CHECK_EQ(validation_message_count(), 0);
}

// ---- texfilter/encode.glsl's sRGB table and `texfilter build` ------------------------------------------------

TEST_CASE("srgb-table")
{
    // Threshold k-1 must be the smallest float whose host code (tf::pack_texels) is at least k: found here by
    // bisection over the float bit patterns of [0, 1], against the literals in the include.
    std::ifstream file(std::string(TEXFILTER_SOURCE_DIR) + "/shaders/texfilter/encode.glsl");
    std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    const size_t start = text.find("float[255](");
    CHECK(start != std::string::npos, "encode.glsl has the table");
    std::istringstream numbers(text.substr(start + 11, text.find(");", start) - start - 11));
    std::vector<float> table;
    for (std::string item; std::getline(numbers, item, ',');)
        table.push_back(std::stof(item));
    CHECK_EQ(table.size(), 255);
    auto code = [](float f) {
        const glm::vec4 t(f, f, f, 1.0f);
        unsigned char bytes[4];
        pack_texels(&t, 1, TextureFormat::rgba8_srgb, bytes);
        return int(bytes[0]);
    };
    for (int k = 1; k <= 255 && size_t(k) <= table.size(); ++k) {
        uint32_t lo = 0, hi = 0x3F800000u; // 0.0 and 1.0
        while (lo < hi) {
            const uint32_t mid = lo + (hi - lo) / 2;
            float f;
            std::memcpy(&f, &mid, 4);
            if (code(f) >= k)
                hi = mid;
            else
                lo = mid + 1;
        }
        float expected;
        std::memcpy(&expected, &lo, 4);
        CHECK(table[size_t(k - 1)] == expected, "threshold " + std::to_string(k) + ": " + test::show(table[size_t(k - 1)]) +
                                                    " in encode.glsl, the host's rounding gives " + test::show(expected));
    }
}

TEST_CASE("cli-build-cpu-vs-gpu")
{
    // A CLI test (the files the command writes): texfilter build writes what the filters read: the device's table is the host's byte for byte and
    // its levels are within the chain bound (values in [0, 1]: 1e-5).
    const std::filesystem::path work = test::make_work_dir("gpu-build-cli");
    for (const char* build : {"cpu", "gpu"}) {
        const std::string command = test::texfilter_path() + " build --validate --texture zoneplate --texture-size 301 --sat" +
                                    (test::test_device().empty() ? "" : " --device '" + test::test_device() + "'") +
                                    " --build " + build + " --out " + (work / build).string() + " > /dev/null";
        CHECK(std::system(command.c_str()) == 0, command);
    }
    auto bytes = [](const std::filesystem::path& p) {
        std::ifstream in(p, std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    const std::string cpu_sat = bytes(work / "cpu" / "sat.bin"), gpu_sat = bytes(work / "gpu" / "sat.bin");
    CHECK(cpu_sat.size() == 8 + 8 + 32 + size_t(302 * 302) * 20, std::to_string(cpu_sat.size()) + " bytes");
    CHECK(cpu_sat == gpu_sat, "sat.bin identical");
    for (int l = 0; l < 9; ++l) {
        char name[32];
        std::snprintf(name, sizeof name, "level-%02d.pfm", l);
        const Image a = read_pfm((work / "cpu" / name).string()), b = read_pfm((work / "gpu" / name).string());
        CHECK(a.width == b.width && a.height == b.height, name);
        double worst = 0;
        for (size_t i = 0; i < a.texels.size() && i < b.texels.size(); ++i)
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::abs(double(a.texels[i][c]) - double(b.texels[i][c])));
        CHECK(worst <= (l == 0 ? 0.0 : 1e-5), std::string(name) + ": off by " + test::show(worst));
    }
}

// ---- The dynamic texture: generated, built and filtered in one submission ---------------------------------

TEST_CASE("dynamic-frame")
{
    // Frame 13 of the dynamic texture, written on the device, rebuilt and filtered in one command buffer
    // (under synchronisation validation, after two earlier frames so a rebuild's hazards are checked):
    // level 0 equals tf::dynamic_texture's bit for bit, the levels are within the chain bound of the host's,
    // and a trilinear lookup within 1e-5 of the same lookup on the host-built chain.
    setenv("TEXFILTER_SYNC_VALIDATION", "1", 1);
    Device device;
    const int side = 100;
    DynamicTexture dynamic = create_dynamic_texture(device.context, side);
    Cleanup cleanup;
    cleanup.add([&] { destroy_dynamic_texture(device.context, dynamic); });
    std::vector<Lookup> lookups = test::as_float(test::random_footprint_lookups(
        128, 33, {.uv_min = -0.5, .uv_max = 1.5, .octave_min = -2, .octave_max = 7, .max_stretch = 2, .texture_size = 100}));
    SamplerOptions options;
    options.filter = Filter::trilinear;
    std::vector<glm::vec4> built;
    for (int frame : {11, 12, 13})
        built = gpu_sample(device.context, dynamic.build.texture, lookups, options, nullptr,
                           [&](VkCommandBuffer cb) { record_dynamic_frame(cb, dynamic, frame); });
    const MipChain host = build_mip_chain(dynamic_texture(side, 13));
    const Image level0 = read_level(device.context, dynamic.build.texture.chain.image, 0, side, side);
    CHECK(level0.texels == host.levels[0].texels, "level 0 as tf::dynamic_texture(100, 13)");
    double worst_level = 0;
    for (int l = 1; l < dynamic.build.texture.levels; ++l) {
        const Image gpu = read_level(device.context, dynamic.build.texture.chain.image, l, side, side);
        for (size_t i = 0; i < gpu.texels.size(); ++i)
            for (int c = 0; c < 4; ++c)
                worst_level = std::max(worst_level, std::abs(double(gpu.texels[i][c]) - double(host.levels[size_t(l)].texels[i][c])));
    }
    CHECK(worst_level <= 1e-5, "levels off by " + test::show(worst_level));
    const std::vector<glm::vec4> expected = with_texture(device.context, host, false, [&](const GpuTexture& t) {
        return gpu_sample(device.context, t, lookups, options);
    });
    double worst = 0;
    for (size_t i = 0; i < lookups.size(); ++i)
        for (int c = 0; c < 4; ++c)
            worst = std::max(worst, std::abs(double(built[i][c]) - double(expected[i][c])));
    CHECK(worst <= 1e-5, "lookups off by " + test::show(worst));
    // A different frame is a different texture: the test can tell frames apart.
    CHECK(dynamic_texture(side, 12).texels != host.levels[0].texels);
    CHECK_EQ(validation_message_count(), 0);
}
