#pragma once
// The pieces every harness pass (render, sample) shares: scoped cleanup, descriptor layouts with the
// three texture bindings, samplers, descriptor writes.
#include "vulkan/backend.h"
#include "vulkan/resources.h"
#include <functional>
#include <vector>

namespace tf {

// Destroys what a function created, in reverse order, however it leaves (return or exception).
struct Cleanup {
    std::vector<std::function<void()>> steps;
    ~Cleanup()
    {
        for (auto it = steps.rbegin(); it != steps.rend(); ++it)
            (*it)();
    }
    void add(std::function<void()> step) { steps.push_back(std::move(step)); }
};

VkDescriptorSetLayout create_set_layout(const VulkanContext& context, const std::vector<VkDescriptorSetLayoutBinding>& bindings);

// The three textures every harness shader declares: the MIP chain and the two SAT words.
std::vector<VkDescriptorSetLayoutBinding> texture_bindings(VkShaderStageFlags stage);

// Samplers for one pass: the filter's (see create_sampler) and a nearest one for the integer SAT.
struct PassSamplers {
    VkSampler texture = VK_NULL_HANDLE, table = VK_NULL_HANDLE;
    VkDescriptorImageInfo infos[3];
};
void create_pass_samplers(const VulkanContext& context, const GpuTexture& texture, const SamplerOptions& options,
                          PassSamplers& samplers, Cleanup& cleanup);

VkPipelineLayout create_pipeline_layout(const VulkanContext& context, VkDescriptorSetLayout set_layout,
                                        VkShaderStageFlags push_stages);

VkWriteDescriptorSet write_texture(VkDescriptorSet set, uint32_t binding, const VkDescriptorImageInfo* image);
VkWriteDescriptorSet write_buffer(VkDescriptorSet set, uint32_t binding, VkDescriptorType type,
                                  const VkDescriptorBufferInfo* buffer);
// The writes for the three texture bindings of texture_bindings().
void write_textures(std::vector<VkWriteDescriptorSet>& writes, VkDescriptorSet set, const PassSamplers& samplers);

void destroy_image(const VulkanContext& context, GpuImage& image);

// A compute pipeline from embedded SPIR-V, specialised to `filter`; destroyed (with its module) by cleanup.
VkPipeline create_compute_pipeline(const VulkanContext& context, const uint32_t* code, size_t size_bytes,
                                   VkPipelineLayout layout, Filter filter, Cleanup& cleanup);

} // namespace tf
