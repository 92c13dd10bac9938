#pragma once
// The samplers a pass binds with the texture: the filter's own and a nearest one for the integer SAT.
#include "core/filter.h"
#include "vulkan/cleanup.h"
#include "vulkan/upload.h"

namespace tf {

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

} // namespace tf
