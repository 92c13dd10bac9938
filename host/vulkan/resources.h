#pragma once
// Host-visible buffers, memory types and shader modules: the plain Vulkan objects every pass makes.
#include "vulkan/context.h"
#include <cstddef>
#include <cstdint>

namespace tf {

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    void* mapped = nullptr; // host-visible and coherent: persistently mapped
};

// Throws a tf::Error naming the size and the device when there is no memory for it.
Buffer create_host_buffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage);
// The same in device-local memory, not mapped (mapped stays null).
Buffer create_device_buffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage);
void destroy_buffer(const VulkanContext& context, Buffer& buffer); // also a half-made or empty one

uint32_t find_memory_type(const VulkanContext& context, uint32_t type_bits, VkMemoryPropertyFlags properties);

VkShaderModule create_shader_module(const VulkanContext& context, const uint32_t* code, size_t size_bytes);

} // namespace tf
