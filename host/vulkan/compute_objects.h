#pragma once
// The plain Vulkan objects a compute pass of the GPU builds makes (gpu_build.cpp, dynamic_texture.cpp): a
// descriptor set layout, a pipeline layout with compute push constants, one descriptor set in a pool of its
// own, and a one-level view. Each is destroyed by `cleanup`.
#include "vulkan/cleanup.h"
#include "vulkan/context.h"
#include <vector>

namespace tf {

VkDescriptorSetLayout create_set_layout(const VulkanContext& context,
                                        const std::vector<VkDescriptorSetLayoutBinding>& bindings, Cleanup& cleanup);
VkPipelineLayout create_push_layout(const VulkanContext& context, VkDescriptorSetLayout set_layout,
                                    uint32_t push_bytes, Cleanup& cleanup);
// `pool` receives the pool (destroyed by cleanup, which frees the set).
VkDescriptorSet allocate_set(const VulkanContext& context, VkDescriptorSetLayout layout,
                             const std::vector<VkDescriptorPoolSize>& sizes, VkDescriptorPool& pool, Cleanup& cleanup);
VkImageView create_level_view(const VulkanContext& context, VkImage image, VkFormat format, uint32_t level,
                              Cleanup& cleanup);

} // namespace tf
