#pragma once
// The Vulkan side of the --format table (core/texture_format.h): each format's VkFormat, and whether this
// device can sample it and filter it linearly (VkFormatProperties::optimalTilingFeatures), checked before
// any work starts.
#include "core/filter.h"
#include "core/texture_format.h"
#include "vulkan/context.h"

namespace tf {

VkFormat vk_format(TextureFormat format);

// SAMPLED_IMAGE_FILTER_LINEAR with optimal tiling on this device.
bool format_filterable(const VulkanContext& context, TextureFormat format);

// Throws tf::Error naming the device and the format when it cannot sample the format with optimal tiling
// (and as a transfer destination), or, for options that filter through the sampler (hw-* modes, --taps
// hardware), cannot filter it linearly; and as check_format_filter for integer formats.
void check_format_support(const VulkanContext& context, TextureFormat format, const SamplerOptions& options);

} // namespace tf
