// libFuzzer target: every CPU reference filter (host/reference*.cpp, through tf::reference_sample) on a
// tiny texture with sampler options anywhere in their valid ranges and lookups made of raw doubles
// (NaN, ±Inf, ±0, 1e300, 1e154, 1e100, 1e37, denormals, any bit pattern, any power of two).
// Asserts, for every lookup and every filter but hw-aniso (which has no reference by contract):
// - no exception: a lookup's contract is a result, whatever its numbers;
// - the result is finite; non-finite uv (NaN, or past float range) gives exactly (0,0,0,0); otherwise
//   every channel lies within the texture's range, give or take 1e-4 (every filter is a weighted average
//   with non-negative weights, or, ewa, a least-squares fit clamped to the range of the texels it read);
// - the work is bounded: one call takes under a second (microseconds in practice, on at most 32x32
//   texels; libFuzzer's -timeout catches a call that never returns).
//
// Input layout (fuzz/make_seeds.py writes seeds in it; missing bytes read as 0):
//   [0] texture: % 7 < 5 a procedural (procedural_names()), else texels from the input
//   [1] width (or the procedural's side) 1 + b % 32   [2] height 1 + b % 32   [3] wrap b % 3
//   [4] lod bias -16..16   [5] [6] lod min / max 0..20, 255 = 1000 (swapped if min > max)
//   [7] band 0..1   [8] probes 1 + b % 16   [9] bit 0 aniso shape feline, bit 1 hardware taps
//   [10] alpha 0.05..16   [11] max aniso 1..64   [12] boxes 1 + b % 16   [13] lookups 1 + b % 8
//   then 6 values a lookup, each a selector byte s:
//     s < 64: specials[s % count]; s < 96: the next 8 bytes as a double's bits (little-endian);
//     s < 160: ((s - 96) * 256 + next byte) / 8192 - 1 (uv-like, [-1, 1));
//     else: ±(s - 160) / 95 * 2^(next byte - 128) (any magnitude)
//   then 4 bytes a texel (RGBA / 255) for texels from the input.
#include "texture/error.h"
#include "fuzz_common.h"
#include "texture/mip.h"
#include "core/procedural.h"
#include "reference/reference.h"

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <limits>

namespace {

struct Reader {
    const uint8_t* data;
    size_t size;
    uint8_t byte()
    {
        if (size == 0)
            return 0;
        --size;
        return *data++;
    }
    double unit() { return byte() / 255.0; }
    double raw()
    {
        uint64_t bits = 0;
        for (int i = 0; i < 8; ++i)
            bits |= uint64_t(byte()) << (8 * i);
        double d;
        std::memcpy(&d, &bits, sizeof d);
        return d;
    }
};

const double specials[] = {0.0,
                           -0.0,
                           std::numeric_limits<double>::quiet_NaN(),
                           -std::numeric_limits<double>::quiet_NaN(),
                           INFINITY,
                           -INFINITY,
                           1e300,
                           -1e300,
                           1e154,
                           -1e154,
                           1e100,
                           1e37,
                           -1e37,
                           1e30,
                           DBL_MAX,
                           -DBL_MAX,
                           DBL_MIN,
                           std::numeric_limits<double>::denorm_min(),
                           -std::numeric_limits<double>::denorm_min(),
                           1e-300,
                           1e-30,
                           0.5,
                           1.0,
                           -1.0,
                           1.0 - DBL_EPSILON / 2,
                           4503599627370496.0, // 2^52
                           9007199254740993.0, // 2^53 + 1
                           1.0 / 256,
                           1e-7,
                           double(FLT_MAX),
                           double(FLT_MIN),
                           1e20};
constexpr size_t special_count = sizeof specials / sizeof specials[0];

double value(Reader& in)
{
    const uint8_t s = in.byte();
    if (s < 64)
        return specials[s % special_count];
    if (s < 96)
        return in.raw();
    if (s < 160)
        return ((s - 96) * 256 + in.byte()) / 8192.0 - 1.0;
    const double mantissa = (s - 160) / 95.0;
    return std::ldexp((s & 1) ? -mantissa : mantissa, int(in.byte()) - 128);
}

double lod_limit(uint8_t b) { return b == 255 ? 1000.0 : b / 254.0 * 20.0; }

std::string show(double x)
{
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", x);
    return text;
}

std::string describe(const tf::SamplerOptions& o, const tf::Lookup& l, int width, int height)
{
    return tf::to_string(o.filter) + " on " + std::to_string(width) + "x" + std::to_string(height) + " wrap " +
           tf::to_string(o.wrap) + " bias " + show(o.lod_bias) + " lod [" + show(o.lod_min) + ", " +
           show(o.lod_max) + "] band " + show(o.band) + " probes " + std::to_string(o.probes) + " shape " +
           tf::to_string(o.aniso_shape) + " taps " + tf::to_string(o.taps) + " alpha " + show(o.alpha) +
           " max-aniso " + show(o.max_aniso) + " boxes " + std::to_string(o.boxes) + "; lookup u " + show(l.u) +
           " v " + show(l.v) + " dudx " + show(l.dudx) + " dvdx " + show(l.dvdx) + " dudy " + show(l.dudy) +
           " dvdy " + show(l.dvdy);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    Reader in{data, size};
    const uint8_t kind = in.byte() % 7;
    const int width = 1 + in.byte() % 32, height = 1 + in.byte() % 32;
    tf::SamplerOptions base;
    base.wrap = tf::Wrap(in.byte() % 3);
    base.lod_bias = float(-16.0 + 32.0 * in.unit());
    double lo = lod_limit(in.byte()), hi = lod_limit(in.byte());
    if (lo > hi)
        std::swap(lo, hi);
    base.lod_min = float(lo);
    base.lod_max = float(hi);
    base.band = float(in.unit());
    base.probes = 1 + in.byte() % 16;
    const uint8_t bits = in.byte();
    base.aniso_shape = (bits & 1) ? tf::AnisoShape::feline : tf::AnisoShape::gpu;
    base.taps = (bits & 2) ? tf::Taps::hardware : tf::Taps::manual;
    base.alpha = float(0.05 + 15.95 * in.unit());
    base.max_aniso = float(1.0 + 63.0 * in.unit());
    base.boxes = 1 + in.byte() % 16;
    tf::fuzz::check_sampler_options(base);

    std::vector<tf::Lookup> lookups(1 + in.byte() % 8);
    for (tf::Lookup& l : lookups) {
        l.u = value(in);
        l.v = value(in);
        l.dudx = value(in);
        l.dvdx = value(in);
        l.dudy = value(in);
        l.dvdy = value(in);
    }

    tf::MipChain chain;
    if (kind < 5) {
        const auto& names = tf::procedural_names();
        chain = tf::make_procedural(names[kind % names.size()], width);
    } else {
        tf::Image level0 = tf::make_image(width, height);
        for (glm::vec4& t : level0.texels)
            t = glm::vec4(in.unit(), in.unit(), in.unit(), in.unit());
        chain = tf::build_mip_chain(std::move(level0));
    }
    const int w0 = chain.levels[0].width, h0 = chain.levels[0].height;
    // The range every result must lie in: all levels' texels (mipcolors' levels are not downsamples).
    glm::dvec4 low(INFINITY), high(-INFINITY);
    for (const tf::Image& level : chain.levels)
        for (const glm::vec4& t : level.texels)
            for (int c = 0; c < 4; ++c) {
                low[c] = std::min(low[c], double(t[c]));
                high[c] = std::max(high[c], double(t[c]));
            }
    // Rounding, not a bug: some families work in float like the shaders (a few ulps past the range).
    const double tolerance = 1e-4;

    for (tf::Filter filter : tf::all_filters()) {
        if (filter == tf::Filter::hw_aniso)
            continue; // no CPU reference, by contract (reference.h)
        tf::SamplerOptions options = base;
        options.filter = filter;
        for (const tf::Lookup& l : lookups) {
            const auto start = std::chrono::steady_clock::now();
            glm::dvec4 r;
            try {
                r = tf::reference_sample(chain, options, l);
            } catch (const tf::Error& e) {
                FUZZ_CHECK(false, std::string(e.what()) + " [" + describe(options, l, w0, h0) + "]");
            }
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            const std::string where = " = (" + show(r.r) + ", " + show(r.g) + ", " + show(r.b) + ", " + show(r.a) +
                                      ") [" + describe(options, l, w0, h0) + "]";
            FUZZ_CHECK(seconds < 1.0, show(seconds) + " s" + where);
            for (int c = 0; c < 4; ++c)
                FUZZ_CHECK(std::isfinite(r[c]), "not finite" + where);
            // The shaders see float input: uv past float range is the ±Inf a float holds (reference.h).
            if (!(std::abs(l.u) <= FLT_MAX && std::abs(l.v) <= FLT_MAX)) {
                FUZZ_CHECK(r == glm::dvec4(0.0), "non-finite uv must give 0" + where);
                continue;
            }
            // Catmull-Rom's negative lobes ring past the texels' range: an axis's |weights| sum to at most 1.25
            // (t = 1/2), so the negative weights of the 2D kernel sum to at most (1.25² - 1) / 2 = 0.28125.
            const bool rings = filter == tf::Filter::catmull_rom || options.magnify == tf::Reconstruction::catmull_rom;
            for (int c = 0; c < 4; ++c) {
                const double ringing = rings ? 0.28125 * (high[c] - low[c]) : 0.0;
                FUZZ_CHECK(r[c] >= low[c] - ringing - tolerance && r[c] <= high[c] + ringing + tolerance,
                           "outside the texture's range [" + show(low[c]) + ", " + show(high[c]) + "]" + where);
            }
        }
    }
    return 0;
}
