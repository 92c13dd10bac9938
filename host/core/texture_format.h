#pragma once
// The formats the harness uploads a texture in (--format): one table, with parse and to-string like the
// filter names, and the quantisation each format's upload applies. The CPU reference reads the chain
// through quantise_chain, so both backends see the same texels: the values the device decodes back.
//
// Every level is built in linear float first (build_mip_chain, sRGB decoded before averaging), then each
// texel is rounded to the format exactly as the upload stores it:
//   unorm8   code = round(clamp(v, 0, 1) * 255), read back as code / 255
//   sRGB8    code = round(linear_to_srgb(clamp(v, 0, 1)) * 255) for R, G, B (alpha as unorm8), read back
//            through the exact IEC 61966-2-1 decode (srgb8_decode_table)
//   float16  IEEE binary16, round to nearest even (the compiler's _Float16 conversion), read back exactly
//   uint     data: code = round(v * integer_scale), clamped to the type's range, read back as float(code);
//            r16ui scales by 65535, r32ui by 2^24 - 1 (every code then converts to float exactly)
// One-channel formats keep R; the device reads G = B = 0, A = 1 (Vulkan's rule for missing components).
#include "core/filter.h"
#include "texture/mip.h"
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tf {

enum class TextureFormat { rgba32f, rgba8_srgb, rgba8, rgba16f, r8, r16f, r32f, r16ui, r32ui };

// How one channel is stored.
enum class ChannelEncoding { float32, float16, unorm8, srgb8, uint16, uint32 };

struct FormatInfo {
    TextureFormat format;
    const char* name;     // the --format value
    int channels;         // stored components: 4 (RGBA) or 1 (R)
    int bits;             // bits a component
    bool srgb;            // R, G, B sRGB-encoded (alpha linear)
    bool integer;         // unsigned integer data: bound as usampler2D, never filtered by a sampler
    ChannelEncoding encoding; // of R, G, B (alpha: unorm8 for sRGB8, else the same)
};

const FormatInfo& format_info(TextureFormat format);
TextureFormat parse_texture_format(const std::string& name); // throws tf::Error listing the valid names
std::string to_string(TextureFormat format);
const std::vector<TextureFormat>& all_texture_formats();
std::string texture_format_names(); // "rgba32f, rgba8-srgb, ...": for help and messages

// Bytes of one stored texel.
size_t texel_bytes(TextureFormat format);
// uint formats: the code a texel value of 1.0 maps to (0 for the other formats).
double integer_scale(TextureFormat format);
// The step between adjacent stored values near `value` of one channel, in the units the shader reads
// (1/255 for unorm8, the sRGB code's step in linear light, half's ULP, 1 for uint; 0 for float32).
double format_quantum(TextureFormat format, double value);

// One texel rounded to the format and decoded back as the device reads it (see the header comment).
glm::vec4 quantise_texel(glm::vec4 linear, TextureFormat format);
// Every level of the chain, in place (rgba32f: unchanged).
void quantise_chain(MipChain& chain, TextureFormat format);
// `count` texels, as quantise_chain left them (uint formats: the codes as floats), in the format's memory
// layout (texel_bytes each): what the upload copies.
void pack_texels(const glm::vec4* texels, size_t count, TextureFormat format, void* out);
// The inverse: `count` stored texels (texel_bytes each) decoded as the shader reads them (sRGB by the exact
// decode; uint: the codes as floats; a one-channel format gives (r, 0, 0, 1)).
void unpack_texels(const void* bytes, size_t count, TextureFormat format, glm::vec4* texels);

// Refuses, before any work, what cannot work on any device: a sampler filtering integer texels (hw-* modes
// and --taps hardware). Throws tf::Error naming the format and the filter.
void check_format_filter(TextureFormat format, const SamplerOptions& options);
// Whether the options filter through the device's sampler (hw-* modes, hardware taps): then the format
// must support linear filtering.
bool needs_hardware_filtering(const SamplerOptions& options);

} // namespace tf
