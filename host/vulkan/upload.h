#pragma once
// Textures onto the device: the MIP chain (every level, in the --format's VkFormat; RGBA32F by default)
// and, for the sat filters, the two summed-area table images, each a sampled image in device-local memory.
#include "core/filter.h"
#include "core/texture_build.h"
#include "core/texture_format.h"
#include "texture/mip.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"
#include "vulkan/image.h"
#include <glm/vec4.hpp>
#include <functional>
#include <utility>

namespace tf {

struct GpuTexture {
    GpuImage chain;              // every MIP level, in vk_format(format)
    TextureFormat format = TextureFormat::rgba32f;
    bool filterable = true;      // the device filters the format linearly (else passes bind nearest samplers)
    GpuImage sat_low, sat_high;  // the summed-area table (1x1 zeros unless asked for)
    glm::vec4 sat_offset{0.0f}, sat_scale{0.0f}; // SatTable::offset, ::scale (zeros without a table)
    int width = 0, height = 0, levels = 0;
};

// with_sat: also build and upload the summed-area table (sat, sat-assembly filters). The levels go through
// one staging buffer of level 0's size, one level at a time, packed to `format` (pack_texels): pass the
// chain as load_texture gives it for that format (quantise_chain; for uint formats the codes as floats).
// Throws tf::Error when the device cannot sample the format (check_format_support).
GpuTexture upload_texture(const VulkanContext& context, const MipChain& chain, bool with_sat,
                          TextureFormat format = TextureFormat::rgba32f);

// build = gpu: only chain.levels[0] is read (the rest may be missing); it is uploaded as RGBA32F and the
// device builds every other level (and the summed-area table, with_sat) in one submission
// (upload_gpu_built.cpp). RGBA32F textures are built in place; other float formats in an RGBA32F
// intermediate, each level then blitted into the format (the blit encodes sRGB: sRGB storage images are
// not writable on most devices). Throws tf::Error as upload_texture, as check_gpu_build, and when the
// device cannot store RGBA32F or blit into the format.
GpuTexture upload_texture(const VulkanContext& context, const MipChain& chain, bool with_sat, TextureFormat format,
                          TextureBuild build);
GpuTexture upload_gpu_built_texture(const VulkanContext& context, const Image& level0, bool with_sat,
                                    TextureFormat format);

// The same chain without a MipChain on the host (no summed-area table): fill_level0 writes level 0, width x
// height linear RGBA texels, straight into the staging buffer (an image decoder, say); after each level is
// copied, the next is built over it in place (downsample_into). So the host holds one level's bytes beside
// the device's images, and the levels equal build_mip_chain's to the bit.
GpuTexture upload_streamed_texture(const VulkanContext& context, int width, int height,
                                   const std::function<void(glm::vec4* texels)>& fill_level0);

void destroy_texture(const VulkanContext& context, GpuTexture& texture);

// texture.sat_low and sat_high as 1x1 zeros: what a texture without a table binds (the descriptor set
// stays valid for every filter).
void upload_empty_sat(const VulkanContext& context, GpuTexture& texture);

// Uploads the texture, runs body(texture) and destroys it again, also when body throws.
template <typename Body>
auto with_texture(const VulkanContext& context, const MipChain& chain, bool with_sat, TextureFormat format,
                  TextureBuild build, Body&& body)
{
    GpuTexture texture = upload_texture(context, chain, with_sat, format, build);
    Cleanup cleanup;
    cleanup.add([&] { destroy_texture(context, texture); });
    return body(texture);
}

template <typename Body>
auto with_texture(const VulkanContext& context, const MipChain& chain, bool with_sat, TextureFormat format,
                  Body&& body)
{
    GpuTexture texture = upload_texture(context, chain, with_sat, format);
    Cleanup cleanup;
    cleanup.add([&] { destroy_texture(context, texture); });
    return body(texture);
}

template <typename Body>
auto with_texture(const VulkanContext& context, const MipChain& chain, bool with_sat, Body&& body)
{
    return with_texture(context, chain, with_sat, TextureFormat::rgba32f, std::forward<Body>(body));
}

// upload_streamed_texture, then body(texture), then destroy, also when body throws.
template <typename Body>
auto with_streamed_texture(const VulkanContext& context, int width, int height,
                           const std::function<void(glm::vec4* texels)>& fill_level0, Body&& body)
{
    GpuTexture texture = upload_streamed_texture(context, width, height, fill_level0);
    Cleanup cleanup;
    cleanup.add([&] { destroy_texture(context, texture); });
    return body(texture);
}

bool needs_sat(Filter filter);

} // namespace tf
