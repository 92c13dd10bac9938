#include "vulkan/resources.h"
#include "harness/config.h"
#include "texture/error.h"
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

Buffer create_host_buffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage)
{
    Buffer b;
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
    allocate.memoryTypeIndex = find_memory_type(context, requirements.memoryTypeBits,
                                                VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                    VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    VkResult result = vkAllocateMemory(context.device, &allocate, nullptr, &b.memory);
    if (result != VK_SUCCESS) {
        destroy_buffer(context, b);
        throw Error("out of memory for a " + std::to_string(size) + "-byte buffer on " + context.info.name);
    }
    TF_VK(vkBindBufferMemory(context.device, b.buffer, b.memory, 0));
    TF_VK(vkMapMemory(context.device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped));
    return b;
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

VkSampler create_sampler(const VulkanContext& context, const SamplerOptions& options, int levels)
{
    VkSamplerAddressMode address = options.wrap == Wrap::clamp    ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE
                                   : options.wrap == Wrap::mirror ? VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT
                                                                  : VK_SAMPLER_ADDRESS_MODE_REPEAT;
    bool nearest = options.filter == Filter::hw_nearest;
    bool level0_only = options.filter == Filter::hw_nearest || options.filter == Filter::hw_bilinear;
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = info.minFilter = nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
    info.mipmapMode = level0_only ? VK_SAMPLER_MIPMAP_MODE_NEAREST : VK_SAMPLER_MIPMAP_MODE_LINEAR;
    info.addressModeU = info.addressModeV = info.addressModeW = address;
    float max_bias = context.info.max_sampler_lod_bias;
    if (is_hardware(options.filter) && (options.lod_bias > max_bias || options.lod_bias < -max_bias))
        throw Error("--lod-bias " + std::to_string(options.lod_bias) + " exceeds this device's maxSamplerLodBias " +
                    std::to_string(max_bias) + " for hardware filters");
    bool hw = is_hardware(options.filter);
    // Manual filters apply bias and LOD clamps in the shader; hardware taps ask for explicit LODs.
    info.mipLodBias = hw ? options.lod_bias : 0.0f;
    info.minLod = level0_only || !hw ? 0.0f : options.lod_min;
    info.maxLod = level0_only ? 0.0f : hw ? std::min(options.lod_max, float(levels - 1)) : float(levels - 1);
    if (info.minLod > info.maxLod)
        info.minLod = info.maxLod;
    if (options.filter == Filter::hw_aniso) {
        if (!context.info.sampler_anisotropy)
            throw Error(context.info.name + " does not support anisotropic filtering (samplerAnisotropy)");
        info.anisotropyEnable = VK_TRUE;
        info.maxAnisotropy = std::min(float(options.aniso), context.info.max_sampler_anisotropy);
    }
    info.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
    VkSampler sampler = VK_NULL_HANDLE;
    TF_VK(vkCreateSampler(context.device, &info, nullptr, &sampler));
    return sampler;
}

void image_barrier(VkCommandBuffer command_buffer, VkImage image, uint32_t levels, VkImageLayout from,
                   VkImageLayout to, VkAccessFlags src_access, VkAccessFlags dst_access,
                   VkPipelineStageFlags src_stage, VkPipelineStageFlags dst_stage)
{
    VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    barrier.srcAccessMask = src_access;
    barrier.dstAccessMask = dst_access;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, levels, 0, 1};
    vkCmdPipelineBarrier(command_buffer, src_stage, dst_stage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

DescriptorSet allocate_descriptor_set(const VulkanContext& context, VkDescriptorSetLayout layout)
{
    VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 3},
                                    {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                                    {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 3}};
    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = 1;
    pool_info.poolSizeCount = 3;
    pool_info.pPoolSizes = sizes;
    DescriptorSet d;
    TF_VK(vkCreateDescriptorPool(context.device, &pool_info, nullptr, &d.pool));
    VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocate.descriptorPool = d.pool;
    allocate.descriptorSetCount = 1;
    allocate.pSetLayouts = &layout;
    TF_VK(vkAllocateDescriptorSets(context.device, &allocate, &d.set));
    return d;
}

const VkSpecializationInfo* filter_specialization(Filter filter, FilterSpecialization& s)
{
    s.filter_id = int32_t(filter);
    s.entry = {HARNESS_SPEC_FILTER, 0, sizeof(int32_t)};
    s.info = {1, &s.entry, sizeof(int32_t), &s.filter_id};
    return &s.info;
}

PushConstants make_push_constants(const SamplerOptions& options, uint32_t count, glm::vec4 sat_offset,
                                  glm::vec4 sat_scale, int gradients)
{
    return {int32_t(options.wrap), options.lod_bias, options.lod_min, options.lod_max,
            count, options.band, options.probes, int32_t(options.aniso_shape), int32_t(options.taps),
            options.alpha, options.max_aniso, options.boxes, gradients,
            options.truth_side, int32_t(options.pixel_filter), 0,
            {sat_offset.x, sat_offset.y, sat_offset.z, sat_offset.w},
            {sat_scale.x, sat_scale.y, sat_scale.z, sat_scale.w}};
}

} // namespace tf
