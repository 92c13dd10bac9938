#include "vulkan/resources.h"
#include "texture/error.h"
#include "vulkan/cleanup.h"
#include <algorithm>

namespace tf {

uint32_t find_memory_type(const VulkanContext& context, uint32_t type_bits, VkMemoryPropertyFlags properties)
{
    VkPhysicalDeviceMemoryProperties memory{};
    vkGetPhysicalDeviceMemoryProperties(context.physical, &memory);
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((type_bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & properties) == properties)
            return i;
    throw Error("the Vulkan device has no memory type with the needed properties");
}

namespace {

Buffer create_buffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage,
                     VkMemoryPropertyFlags properties)
{
    Buffer b;
    Cleanup on_failure;
    on_failure.add([&] { destroy_buffer(context, b); });
    b.size = std::max<VkDeviceSize>(size, 16);
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = b.size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    TF_VK(vkCreateBuffer(context.device, &info, nullptr, &b.buffer));
    VkMemoryRequirements requirements{};
    vkGetBufferMemoryRequirements(context.device, b.buffer, &requirements);
    VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    allocate.allocationSize = requirements.size;
    allocate.memoryTypeIndex = find_memory_type(context, requirements.memoryTypeBits, properties);
    if (vkAllocateMemory(context.device, &allocate, nullptr, &b.memory) != VK_SUCCESS)
        throw Error("out of memory for a " + std::to_string(size) + "-byte buffer on " + context.info.name);
    TF_VK(vkBindBufferMemory(context.device, b.buffer, b.memory, 0));
    if (properties & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)
        TF_VK(vkMapMemory(context.device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped));
    on_failure.dismiss();
    return b;
}

} // namespace

Buffer create_host_buffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage)
{
    return create_buffer(context, size, usage, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
}

Buffer create_device_buffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage)
{
    return create_buffer(context, size, usage, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
}

void destroy_buffer(const VulkanContext& context, Buffer& buffer)
{
    if (buffer.buffer)
        vkDestroyBuffer(context.device, buffer.buffer, nullptr);
    if (buffer.memory)
        vkFreeMemory(context.device, buffer.memory, nullptr); // unmaps implicitly
    buffer = Buffer{};
}

VkShaderModule create_shader_module(const VulkanContext& context, const uint32_t* code, size_t size_bytes)
{
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = size_bytes;
    info.pCode = code;
    VkShaderModule module = VK_NULL_HANDLE;
    TF_VK(vkCreateShaderModule(context.device, &info, nullptr, &module));
    return module;
}

} // namespace tf
