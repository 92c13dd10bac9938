#pragma once
// The Vulkan backend: uploads a MIP chain, renders a scene through the fragment harness, runs point
// lookups through the compute harness. Results come back as RGBA32F, linear.
#include "filter.h"
#include "mip.h"
#include "reference.h"
#include "scene.h"
#include "vk_context.h"
#include <glm/vec4.hpp>
#include <vector>

namespace tf {

struct GpuTexture {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    int width = 0, height = 0, levels = 0;
};

GpuTexture upload_texture(const VulkanContext& context, const MipChain& chain);
void destroy_texture(const VulkanContext& context, GpuTexture& texture);

Image gpu_render(const VulkanContext& context, const GpuTexture& texture, const SceneParams& scene,
                 const SamplerOptions& options);

std::vector<glm::vec4> gpu_sample(const VulkanContext& context, const GpuTexture& texture,
                                  const std::vector<Lookup>& lookups, const SamplerOptions& options);

} // namespace tf
