#pragma once
// Pipeline barriers, the two shapes the layer records: an image's layout change and a global memory
// dependency.
#include "vulkan/loader.h"
#include <cstdint>

namespace tf {

void image_barrier(VkCommandBuffer command_buffer, VkImage image, uint32_t levels, VkImageLayout from,
                   VkImageLayout to, VkAccessFlags src_access, VkAccessFlags dst_access,
                   VkPipelineStageFlags src_stage, VkPipelineStageFlags dst_stage,
                   VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT, uint32_t layers = 1,
                   uint32_t base_level = 0); // levels [base_level, base_level + levels)

void memory_barrier(VkCommandBuffer command_buffer, VkAccessFlags src_access, VkAccessFlags dst_access,
                    VkPipelineStageFlags src_stage, VkPipelineStageFlags dst_stage);

} // namespace tf
