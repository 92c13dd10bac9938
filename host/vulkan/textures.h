#pragma once
// Textures on the device: the MIP chain and summed-area table uploaded (or streamed), the samplers a pass
// binds with them, and the images of each resource kind `sample --resource` binds.
#include "core/filter.h"
#include "core/resource.h"
#include "core/texel_sources.h"
#include "core/texture_format.h"
#include "texture/mip.h"
#include "vulkan/cleanup.h"
#include "vulkan/device.h"
#include "vulkan/memory.h"
#include <functional>
#include <glm/vec4.hpp>
#include <utility>
#include <vector>

namespace tf {

// Textures onto the device: the MIP chain (every level, in the --format's VkFormat; RGBA32F by default)
// and, for the sat filters, the two summed-area table images, each a sampled image in device-local memory.
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

// Uploads the texture, runs body(texture) and destroys it again, also when body throws (with a TextureBuild:
// gpu_build.h).
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

// The samplers a pass binds with the texture: the filter's own and a nearest one for the integer SAT.
// The sampler bound with the texture. hw-* filters: hw-nearest and hw-bilinear see level 0 only
// (maxLod 0), hw-trilinear all levels, hw-aniso adds maxAnisotropy. Manual filters (texelFetch ignores
// the sampler) get plain trilinear with the wrap mode, which their hardware taps use.
VkSampler create_sampler(const VulkanContext& context, const SamplerOptions& options, int levels);
// What create_sampler creates, for a caller that adds to it (the shadow kind's depth comparison).
VkSamplerCreateInfo sampler_create_info(const VulkanContext& context, const SamplerOptions& options, int levels);

// The three images every harness shader samples (the MIP chain and the two SAT words), each with its
// sampler, as the descriptor image infos for HARNESS_BINDING_TEXTURE, _SAT_LOW and _SAT_HIGH.
struct PassSamplers {
    VkSampler texture = VK_NULL_HANDLE, table = VK_NULL_HANDLE;
    VkDescriptorImageInfo infos[3]{};
};
// The samplers are destroyed by `cleanup`.
PassSamplers create_pass_samplers(const VulkanContext& context, const GpuTexture& texture,
                                  const SamplerOptions& options, Cleanup& cleanup);

// The images `sample --resource` binds, beyond the one texture of upload_texture: an array image (one view of
// every layer, each with its full MIP chain), the textures of a bindless array, and a depth image
// (VK_FORMAT_D32_SFLOAT, every level, written through the depth aspect) for the shadow kind. Each is a
// device-local sampled image in SHADER_READ_ONLY_OPTIMAL once uploaded.
//
// Use: upload_resources(context, make_resource_chains(base, options), options.resource), bind (see
// pipelines.h), destroy_resources. Cost: one staging buffer of a level, one submit a level a layer.
struct GpuResources {
    Resource resource = Resource::combined;
    GpuTexture base;                    // chains[0] as RGBA32F (combined, separate; bindless index 0),
                                        // and the summed-area table's placeholders every kind binds
    GpuImage layered;                   // array kinds: chains[k] in layer k, view VK_IMAGE_VIEW_TYPE_2D_ARRAY
    std::vector<GpuTexture> textures;   // bindless: chains[1..] (chains[0] is base)
    GpuImage depth;                     // shadow: chains[0].r as D32_SFLOAT
    Buffer source;                      // atlas, virtual: the words at HARNESS_BINDING_SOURCE (base holds
                                        // the atlas or the physical texture)
    VkImageView sat_low_array = VK_NULL_HANDLE, sat_high_array = VK_NULL_HANDLE; // array kinds: base's
                                        // summed-area table images as one-layer arrays (what they declare)
    int width = 0, height = 0, levels = 0, layers = 1;
};

// chains: core/resource_textures.h's make_resource_chains for `resource` (one size for all). Throws
// tf::Error when the device cannot sample what the kind needs (a depth format with comparison and
// linear filtering, say), naming the device and what is missing.
// with_sat: base gets its summed-area table (the sat filters, on the kinds that run them).
GpuResources upload_resources(const VulkanContext& context, const std::vector<MipChain>& chains, Resource resource,
                              bool with_sat);
void destroy_resources(const VulkanContext& context, GpuResources& resources);

// atlas, virtual (core/texel_sources.h): source.image as base (RGBA32F, its levels as they are: the atlas's
// per-tile levels are not rebuilt) and source.words in a host-visible storage buffer.
GpuResources upload_texel_source(const VulkanContext& context, const SourceBinding& source);

// Every level of every chain into layer k of `g` (RGBA32F, or D32 from .r with depth_only), one level at a
// time through one staging buffer of level 0's size; the image ends SHADER_READ_ONLY_OPTIMAL. The chains
// have g's size and level count (array kinds, a cube's faces).
void upload_layers(const VulkanContext& context, const GpuImage& g, const std::vector<MipChain>& chains,
                   VkImageAspectFlags aspect, bool depth_only);

// The depth format the shadow kind uploads, and its check (also for an early refusal): sampled, with
// depth comparison, and (linear: for the hardware's bilinear/trilinear comparison lookups) linear filtering,
// which Vulkan does not require of depth formats (lavapipe 22.3 lacks it).
constexpr VkFormat shadow_depth_format = VK_FORMAT_D32_SFLOAT;
void check_shadow_format(const VulkanContext& context, bool linear);

} // namespace tf
