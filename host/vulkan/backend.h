#pragma once
// The Vulkan backend: uploads a MIP chain, renders a scene through the fragment harness, runs point
// lookups through the compute harness. Results come back as RGBA32F, linear.
#include "core/filter.h"
#include "core/lookup_stats.h"
#include "core/lookup.h"
#include "scene/scene.h"
#include "vulkan/device.h"
#include "vulkan/gpu_build.h"
#include "vulkan/pipelines.h"
#include "vulkan/textures.h"
#include <glm/vec4.hpp>
#include <functional>
#include <vector>

namespace tf {

// Renders the scene: ray-cast in a fragment shader (full-screen triangle) or a compute shader (2x2 quads
// from subgroup quad operations), or, with render.rasterize, its triangles through the raster pipeline.
// cache: pipelines kept across renders (vulkan/render.h; golden), null for a pipeline of its own.
struct RenderPipelineCache;
Image gpu_render(const VulkanContext& context, const GpuTexture& texture, const SceneParams& scene,
                 const SamplerOptions& options, const RenderOptions& render, RenderPipelineCache* cache = nullptr);

std::vector<glm::vec4> gpu_sample(const VulkanContext& context, const GpuTexture& texture,
                                  const std::vector<Lookup>& lookups, const SamplerOptions& options,
                                  std::vector<LookupStats>* stats = nullptr,
                                  const std::function<void(VkCommandBuffer)>& prelude = {}); // recorded first, same submission
// The same through a lookup shader given instead of the built-in one (sample --spirv: SPIR-V from another
// compiler, checked by vulkan/pipelines.h), for a float texture bound as the combined kind.
std::vector<glm::vec4> gpu_sample_with_shader(const VulkanContext& context, const GpuTexture& texture,
                                              const std::vector<Lookup>& lookups, const SamplerOptions& options,
                                              ShaderCode shader, std::vector<LookupStats>* stats = nullptr,
                                              const std::function<void(VkCommandBuffer)>& prelude = {});


} // namespace tf
