#pragma once
// What every harness pass (render in each stage, sample) creates the same way: one descriptor set with
// the three textures and the pass's own buffers, its layout, the pipeline layout with the push constants,
// and the commands that bind them. Only the pipeline and the buffers differ from pass to pass.
#include "core/filter.h"
#include "scene/shader_interface.h"
#include "vulkan/cleanup.h"
#include "vulkan/samplers.h"
#include <glm/vec4.hpp>
#include <vector>

namespace tf {

// One buffer the pass's shaders read or write, at a binding of shaders/harness/config.h.
struct PassBuffer {
    uint32_t binding;
    VkDescriptorType type; // uniform or storage
    VkBuffer buffer;
    VkDeviceSize range = VK_WHOLE_SIZE;
};

// The image descriptors at one binding (one, or an array of them: bindless).
struct PassImages {
    uint32_t binding;
    VkDescriptorType type; // combined image sampler, sampled image or sampler
    std::vector<VkDescriptorImageInfo> infos;
};

struct Pass {
    PassSamplers samplers;
    VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
    VkPipelineLayout pipeline_layout = VK_NULL_HANDLE;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE; // written: textures and buffers bound
    VkShaderStageFlags push_stages = 0;
};

// `stages` see the bindings, `push_stages` the push constants. Everything made is destroyed by `cleanup`.
Pass create_pass(const VulkanContext& context, const GpuTexture& texture, const SamplerOptions& options,
                 VkShaderStageFlags stages, VkShaderStageFlags push_stages, const std::vector<PassBuffer>& buffers,
                 Cleanup& cleanup);

// The same with the pass's images given (resource_pass.h's kinds); pass.samplers stays empty.
Pass create_pass_with_images(const VulkanContext& context, const std::vector<PassImages>& images,
                             VkShaderStageFlags stages, VkShaderStageFlags push_stages,
                             const std::vector<PassBuffer>& buffers, Cleanup& cleanup);

// Binds `pipeline` (made with pass.pipeline_layout), the pass's descriptor set and `push`.
void bind_pass(VkCommandBuffer command_buffer, VkPipelineBindPoint bind_point, VkPipeline pipeline, const Pass& pass,
               const PushConstants& push);

PushConstants make_push_constants(const SamplerOptions& options, uint32_t count, glm::vec4 sat_offset,
                                  glm::vec4 sat_scale);

} // namespace tf
