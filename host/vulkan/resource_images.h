#pragma once
// The images `sample --resource` binds, beyond the one texture of upload.h: an array image (one view of
// every layer, each with its full MIP chain), the textures of a bindless array, and a depth image
// (VK_FORMAT_D32_SFLOAT, every level, written through the depth aspect) for the shadow kind. Each is a
// device-local sampled image in SHADER_READ_ONLY_OPTIMAL once uploaded.
//
// Use: upload_resources(context, make_resource_chains(base, options), options.resource), bind (see
// harness_variant.h), destroy_resources. Cost: one staging buffer of a level, one submit a level a layer.
#include "core/resource.h"
#include "core/texel_sources.h"
#include "vulkan/resources.h"
#include "vulkan/upload.h"
#include <vector>

namespace tf {

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
