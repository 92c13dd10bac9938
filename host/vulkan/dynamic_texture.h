#pragma once
// The "dynamic" procedural texture made on the device every frame: a compute shader writes level 0
// (dynamic_texture.comp.glsl, tf::dynamic_texture's integers), the GPU build completes the chain, and the
// frame's filter reads it, all in the caller's command buffer: what a render target, a reflection probe or
// any animated texture asks of an engine's MIP builder (bench --gpu-build's dynamic row, the viewer).
#include "vulkan/gpu_built_texture.h"

namespace tf {

struct DynamicTexture {
    GpuBuild build; // RGBA32F, built in place; build.texture is what the filters bind
    int size = 0;
    bool first = true; // the images have no contents yet
    VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;
    std::shared_ptr<Cleanup> objects; // the generator's objects
};

// size x size (1..16384, the device's limits). No summed-area table: its range is read back after a
// build, so a table cannot be filtered in the frame that builds it (sat filters need a static texture).
DynamicTexture create_dynamic_texture(const VulkanContext& context, int size);

// Level 0 at `frame`, then the chain, recorded into `command_buffer`; afterwards the texture is in
// SHADER_READ_ONLY_OPTIMAL, visible to fragment and compute shaders. The previous frame's reads of the
// texture (recorded earlier in this or an earlier submission) finish before level 0 is rewritten.
void record_dynamic_frame(VkCommandBuffer command_buffer, DynamicTexture& texture, int frame);

void destroy_dynamic_texture(const VulkanContext& context, DynamicTexture& texture);

} // namespace tf
