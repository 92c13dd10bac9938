#pragma once
// The harness pass of one resource kind (`sample --resource`): the variant's descriptors at
// HARNESS_BINDING_TEXTURE (a combined image sampler, a sampled image, or an array of them) and, for the
// separate kinds, the sampler at HARNESS_BINDING_SAMPLER (shadow: a comparison sampler with compareOp),
// the summed-area table's placeholders, and the pass's own buffers (pass.h).
#include "core/resource.h"
#include "vulkan/harness_variant.h"
#include "vulkan/pass.h"
#include "vulkan/resource_images.h"

namespace tf {

// Everything made is destroyed by `cleanup`.
Pass create_resource_pass(const VulkanContext& context, const GpuResources& resources, const HarnessVariant& variant,
                          const SamplerOptions& options, const ResourceOptions& resource, VkShaderStageFlags stages,
                          const std::vector<PassBuffer>& buffers, Cleanup& cleanup);

} // namespace tf
