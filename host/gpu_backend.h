#pragma once
// The Vulkan backend: uploads a MIP chain, renders a scene through the fragment harness, runs point
// lookups through the compute harness. Results come back as RGBA32F, linear.
#include "filter.h"
#include "lookup_stats.h"
#include "mip.h"
#include "reference.h"
#include "scene.h"
#include "vk_context.h"
#include <glm/vec4.hpp>
#include <vector>

namespace tf {

struct GpuImage {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
};

struct GpuTexture {
    GpuImage chain;              // RGBA32F, every MIP level
    GpuImage sat_low, sat_high;  // the summed-area table (1x1 zeros unless asked for)
    glm::vec4 sat_offset{0.0f}, sat_scale{0.0f}; // SatTable::offset, ::scale (zeros without a table)
    int width = 0, height = 0, levels = 0;
};

// with_sat: also build and upload the summed-area table (sat, sat-assembly filters).
GpuTexture upload_texture(const VulkanContext& context, const MipChain& chain, bool with_sat);
void destroy_texture(const VulkanContext& context, GpuTexture& texture);

// Uploads the texture, runs body(texture) and destroys it again, also when body throws.
template <typename Body>
auto with_texture(const VulkanContext& context, const MipChain& chain, bool with_sat, Body&& body)
{
    GpuTexture texture = upload_texture(context, chain, with_sat);
    struct Release {
        const VulkanContext& context;
        GpuTexture& texture;
        ~Release() { destroy_texture(context, texture); }
    } release{context, texture};
    return body(texture);
}

// Renders the scene: ray-cast in a fragment shader (full-screen triangle) or a compute shader (2x2 quads
// from subgroup quad operations), or, with render.rasterize, its triangles through the raster pipeline.
Image gpu_render(const VulkanContext& context, const GpuTexture& texture, const SceneParams& scene,
                 const SamplerOptions& options, const RenderOptions& render);

std::vector<glm::vec4> gpu_sample(const VulkanContext& context, const GpuTexture& texture,
                                  const std::vector<Lookup>& lookups, const SamplerOptions& options,
                                  std::vector<LookupStats>* stats = nullptr);

bool needs_sat(Filter filter);

} // namespace tf
