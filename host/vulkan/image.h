#pragma once
// Device-local images with their memory and a view: the uploaded textures and the render targets.
#include "vulkan/context.h"
#include <cstdint>

namespace tf {

struct GpuImage {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    uint32_t memory_type = 0;    // the memory type index it was allocated from
    VkDeviceSize memory_size = 0; // its allocation's size
};

// A 2D image of `levels` levels and `layers` layers in device-local memory, in UNDEFINED layout, with a view
// of every level and layer (VK_IMAGE_VIEW_TYPE_2D, or 2D_ARRAY for a texture array).
// Throws a tf::Error naming the size and the device when there is no memory for it.
GpuImage create_image(const VulkanContext& context, VkFormat format, uint32_t width, uint32_t height,
                      uint32_t levels, VkImageUsageFlags usage, VkImageAspectFlags aspect, uint32_t layers = 1,
                      VkImageViewType view_type = VK_IMAGE_VIEW_TYPE_2D, VkImageCreateFlags flags = 0);
// flags with VK_IMAGE_CREATE_EXTENDED_USAGE_BIT: `usage` may include what only other view formats support
// (STORAGE through an integer view of an sRGB image); the image's own view then omits STORAGE.
void destroy_image(const VulkanContext& context, GpuImage& image); // also a half-made or empty one

} // namespace tf
