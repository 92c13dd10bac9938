#include "core/texture_format.h"

#include "texture/error.h"
#include "texture/image.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace tf {

namespace {

// The one table: name, components, bits, sRGB, integer, encoding.
const FormatInfo kFormats[] = {
    {TextureFormat::rgba32f, "rgba32f", 4, 32, false, false, ChannelEncoding::float32},
    {TextureFormat::rgba8_srgb, "rgba8-srgb", 4, 8, true, false, ChannelEncoding::srgb8},
    {TextureFormat::rgba8, "rgba8", 4, 8, false, false, ChannelEncoding::unorm8},
    {TextureFormat::rgba16f, "rgba16f", 4, 16, false, false, ChannelEncoding::float16},
    {TextureFormat::r8, "r8", 1, 8, false, false, ChannelEncoding::unorm8},
    {TextureFormat::r16f, "r16f", 1, 16, false, false, ChannelEncoding::float16},
    {TextureFormat::r32f, "r32f", 1, 32, false, false, ChannelEncoding::float32},
    {TextureFormat::r16ui, "r16ui", 1, 16, false, true, ChannelEncoding::uint16},
    {TextureFormat::r32ui, "r32ui", 1, 32, false, true, ChannelEncoding::uint32},
};

// r32ui's scale: 2^24 - 1, the largest code range in which every code converts to float32 exactly (the
// shader filters float(code)).
constexpr double kR32uiScale = 16777215.0;

uint8_t unorm8_code(float v)
{
    const double c = std::clamp(double(v), 0.0, 1.0); // NaN: clamp keeps it, then lrint is undefined
    return std::isnan(c) ? 0 : uint8_t(std::lrint(c * 255.0));
}

uint8_t srgb8_code(float v)
{
    const double c = std::clamp(double(v), 0.0, 1.0);
    return std::isnan(c) ? 0 : uint8_t(std::lrint(linear_to_srgb(c) * 255.0));
}

// IEEE binary16, round to nearest, ties to even, from the bits (no _Float16: clang 14 has none on x86-64,
// and GLM's packHalf rounds ties away from zero and flushes tiny values). Inf and NaN stay Inf and (quiet) NaN.
uint16_t half_bits(float v)
{
    uint32_t x;
    std::memcpy(&x, &v, sizeof x);
    const uint16_t sign = uint16_t((x >> 16) & 0x8000u);
    const uint32_t a = x & 0x7fffffffu;
    if (a >= 0x7f800000u) // Inf, NaN
        return uint16_t(sign | 0x7c00u | (a > 0x7f800000u ? 0x200u : 0u));
    if (a >= 0x477ff000u) // 65520 and up: past the midpoint of 65504 and 2^16, rounds to Inf
        return uint16_t(sign | 0x7c00u);
    if (a < 0x38800000u) { // below 2^-14: a subnormal half, round(|v|·2^24) (exact scaling, RNE by default)
        float magnitude;
        std::memcpy(&magnitude, &a, sizeof magnitude);
        return uint16_t(sign | uint16_t(std::nearbyint(magnitude * 16777216.0f))); // 1024 is 2^-14: right
    }
    uint32_t h = ((((a >> 23) - 127u + 15u) << 10) | ((a & 0x7fffffu) >> 13)); // exponent, 10 mantissa bits
    const uint32_t rest = a & 0x1fffu;                                           // the 13 bits dropped
    if (rest > 0x1000u || (rest == 0x1000u && (h & 1u)))
        ++h; // a carry into the exponent is right (1.111..1 rounds up to the next power of two)
    return uint16_t(sign | h);
}

float half_value(uint16_t bits)
{
    const int exponent = (bits >> 10) & 0x1f, mantissa = bits & 0x3ff;
    const float sign = (bits & 0x8000u) ? -1.0f : 1.0f;
    if (exponent == 31)
        return mantissa ? std::numeric_limits<float>::quiet_NaN() : sign * std::numeric_limits<float>::infinity();
    if (exponent == 0)
        return sign * std::ldexp(float(mantissa), -24);
    return sign * std::ldexp(float(mantissa | 0x400), exponent - 25);
}

template <typename Code>
Code uint_code(float v, double scale)
{
    const double top = double(std::numeric_limits<Code>::max());
    const double c = std::isnan(v) ? 0.0 : std::clamp(std::nearbyint(double(v) * scale), 0.0, top);
    return Code(c);
}

// One channel stored and decoded back.
float quantise_channel(float v, ChannelEncoding encoding)
{
    switch (encoding) {
    case ChannelEncoding::float32: return v;
    case ChannelEncoding::float16: return half_value(half_bits(v));
    case ChannelEncoding::unorm8: return float(double(unorm8_code(v)) / 255.0);
    case ChannelEncoding::srgb8: return srgb8_decode_table()[srgb8_code(v)];
    case ChannelEncoding::uint16: return float(uint_code<uint16_t>(v, 65535.0));
    case ChannelEncoding::uint32: return float(uint_code<uint32_t>(v, kR32uiScale));
    }
    return v;
}

ChannelEncoding alpha_encoding(const FormatInfo& info)
{
    return info.encoding == ChannelEncoding::srgb8 ? ChannelEncoding::unorm8 : info.encoding;
}

} // namespace

const FormatInfo& format_info(TextureFormat format)
{
    for (const FormatInfo& info : kFormats)
        if (info.format == format) return info;
    throw Error("invalid texture format value " + std::to_string(int(format)));
}

std::string texture_format_names()
{
    std::string list;
    for (const FormatInfo& info : kFormats)
        list += (list.empty() ? "" : ", ") + std::string(info.name);
    return list;
}

TextureFormat parse_texture_format(const std::string& name)
{
    for (const FormatInfo& info : kFormats)
        if (name == info.name) return info.format;
    throw Error("unknown texture format '" + name + "' (expected one of: " + texture_format_names() + ")");
}

std::string to_string(TextureFormat format) { return format_info(format).name; }

const std::vector<TextureFormat>& all_texture_formats()
{
    static const std::vector<TextureFormat> formats = [] {
        std::vector<TextureFormat> list;
        for (const FormatInfo& info : kFormats)
            list.push_back(info.format);
        return list;
    }();
    return formats;
}

size_t texel_bytes(TextureFormat format)
{
    const FormatInfo& info = format_info(format);
    return size_t(info.channels) * size_t(info.bits / 8);
}

double integer_scale(TextureFormat format)
{
    switch (format_info(format).encoding) {
    case ChannelEncoding::uint16: return 65535.0;
    case ChannelEncoding::uint32: return kR32uiScale;
    default: return 0.0;
    }
}

double format_quantum(TextureFormat format, double value)
{
    switch (format_info(format).encoding) {
    case ChannelEncoding::float32: return 0.0;
    case ChannelEncoding::unorm8: return 1.0 / 255.0;
    case ChannelEncoding::uint16:
    case ChannelEncoding::uint32: return 1.0;
    case ChannelEncoding::float16: { // the ULP of binary16 at |value| (subnormals: 2^-24)
        const double a = std::max(std::fabs(value), std::ldexp(1.0, -14));
        return std::ldexp(1.0, std::ilogb(a) - 10);
    }
    case ChannelEncoding::srgb8: { // the linear step between the codes around value
        const int code = srgb8_code(float(value));
        const int up = std::min(code + 1, 255), down = std::max(code - 1, 0);
        const auto& table = srgb8_decode_table();
        return std::max(double(table[up]) - table[code], double(table[code]) - table[down]);
    }
    }
    return 0.0;
}

glm::vec4 quantise_texel(glm::vec4 linear, TextureFormat format)
{
    const FormatInfo& info = format_info(format);
    if (info.channels == 1)
        return {quantise_channel(linear.r, info.encoding), 0.0f, 0.0f, 1.0f};
    return {quantise_channel(linear.r, info.encoding), quantise_channel(linear.g, info.encoding),
            quantise_channel(linear.b, info.encoding), quantise_channel(linear.a, alpha_encoding(info))};
}

void quantise_chain(MipChain& chain, TextureFormat format)
{
    if (format == TextureFormat::rgba32f)
        return;
    for (Image& level : chain.levels)
        for (glm::vec4& texel : level.texels)
            texel = quantise_texel(texel, format);
}

void pack_texels(const glm::vec4* texels, size_t count, TextureFormat format, void* out)
{
    const FormatInfo& info = format_info(format);
    const int n = info.channels;
    auto* bytes = static_cast<unsigned char*>(out);
    for (size_t i = 0; i < count; ++i) {
        for (int c = 0; c < n; ++c) {
            const float v = texels[i][c];
            const ChannelEncoding encoding = c == 3 ? alpha_encoding(info) : info.encoding;
            switch (encoding) {
            case ChannelEncoding::float32: std::memcpy(bytes, &v, 4); bytes += 4; break;
            case ChannelEncoding::float16: { uint16_t h = half_bits(v); std::memcpy(bytes, &h, 2); bytes += 2; break; }
            case ChannelEncoding::unorm8: *bytes++ = unorm8_code(v); break;
            case ChannelEncoding::srgb8: *bytes++ = srgb8_code(v); break;
            case ChannelEncoding::uint16: { uint16_t u = uint_code<uint16_t>(v, 1.0); std::memcpy(bytes, &u, 2); bytes += 2; break; }
            case ChannelEncoding::uint32: { uint32_t u = uint_code<uint32_t>(v, 1.0); std::memcpy(bytes, &u, 4); bytes += 4; break; }
            }
        }
    }
}

void unpack_texels(const void* in, size_t count, TextureFormat format, glm::vec4* texels)
{
    const FormatInfo& info = format_info(format);
    const auto* bytes = static_cast<const unsigned char*>(in);
    for (size_t i = 0; i < count; ++i) {
        glm::vec4 t(0.0f, 0.0f, 0.0f, 1.0f);
        for (int c = 0; c < info.channels; ++c) {
            const ChannelEncoding encoding = c == 3 ? alpha_encoding(info) : info.encoding;
            switch (encoding) {
            case ChannelEncoding::float32: std::memcpy(&t[c], bytes, 4); bytes += 4; break;
            case ChannelEncoding::float16: { uint16_t h; std::memcpy(&h, bytes, 2); t[c] = half_value(h); bytes += 2; break; }
            case ChannelEncoding::unorm8: t[c] = float(double(*bytes++) / 255.0); break;
            case ChannelEncoding::srgb8: t[c] = srgb8_decode_table()[*bytes++]; break;
            case ChannelEncoding::uint16: { uint16_t u; std::memcpy(&u, bytes, 2); t[c] = float(u); bytes += 2; break; }
            case ChannelEncoding::uint32: { uint32_t u; std::memcpy(&u, bytes, 4); t[c] = float(u); bytes += 4; break; }
            }
        }
        texels[i] = t;
    }
}

bool needs_hardware_filtering(const SamplerOptions& options)
{
    switch (options.filter) {
    case Filter::hw_bilinear:
    case Filter::hw_trilinear:
    case Filter::hw_aniso:
    case Filter::ewa_fast:
        return true;
    case Filter::aniso:
    case Filter::ewa:
    case Filter::bspline:
    case Filter::catmull_rom:
        return options.taps == Taps::hardware;
    default:
        return false;
    }
}

void check_format_filter(TextureFormat format, const SamplerOptions& options)
{
    if (!format_info(format).integer)
        return;
    if (is_hardware(options.filter) || options.filter == Filter::ewa_fast)
        throw Error("--format " + to_string(format) + " holds integer data, which no sampler filters: --filter " +
                    to_string(options.filter) + " needs a float format (the manual filters read integer texels)");
    if (needs_hardware_filtering(options))
        throw Error("--format " + to_string(format) + " holds integer data, which no sampler filters: --taps "
                    "hardware needs a float format (use --taps manual)");
}

} // namespace tf
