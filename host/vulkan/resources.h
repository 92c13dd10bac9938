#pragma once
// Small Vulkan helpers: host-visible buffers, shader modules, samplers matching SamplerOptions,
// image layout barriers. Everything the render and sample paths share.
#include "core/filter.h"
#include "scene/shader_interface.h"
#include "vulkan/context.h"
#include <glm/vec4.hpp>
#include <cstddef>
#include <cstdint>

namespace tf {

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    void* mapped = nullptr; // host-visible and coherent: persistently mapped
};

Buffer create_host_buffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage);
void destroy_buffer(const VulkanContext& context, Buffer& buffer);

uint32_t find_memory_type(const VulkanContext& context, uint32_t type_bits, VkMemoryPropertyFlags properties);

VkShaderModule create_shader_module(const VulkanContext& context, const uint32_t* code, size_t size_bytes);

// The sampler bound with the texture. hw-* filters: hw-nearest and hw-bilinear see level 0 only
// (maxLod 0), hw-trilinear all levels, hw-aniso adds maxAnisotropy. Manual filters (texelFetch ignores
// the sampler) get plain trilinear with the wrap mode, which their hardware taps use.
VkSampler create_sampler(const VulkanContext& context, const SamplerOptions& options, int levels);

void image_barrier(VkCommandBuffer command_buffer, VkImage image, uint32_t levels, VkImageLayout from,
                   VkImageLayout to, VkAccessFlags src_access, VkAccessFlags dst_access,
                   VkPipelineStageFlags src_stage, VkPipelineStageFlags dst_stage);

// Descriptor pool + set for one set layout (one-shot use).
struct DescriptorSet {
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;
};
DescriptorSet allocate_descriptor_set(const VulkanContext& context, VkDescriptorSetLayout layout);

// The filter, as the harness shaders' specialization constant HARNESS_SPEC_FILTER (pipelines are per filter).
struct FilterSpecialization {
    int32_t filter_id;
    VkSpecializationMapEntry entry;
    VkSpecializationInfo info;
};
// Fills `s` and returns &s.info, which points into s: keep s alive until the pipeline is created.
const VkSpecializationInfo* filter_specialization(Filter filter, FilterSpecialization& s);

PushConstants make_push_constants(const SamplerOptions& options, uint32_t count, glm::vec4 sat_offset,
                                  glm::vec4 sat_scale, int gradients);

} // namespace tf
