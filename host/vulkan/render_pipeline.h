#pragma once
// The three ways the harness draws a scene, each its own pipeline over the same pass (vulkan/pass.h).
#include "core/filter.h"
#include "core/texture_format.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"

namespace tf {

enum class RenderKind {
    fragment, // a full-screen triangle whose fragment shader ray-casts the scene
    compute,  // a compute shader whose invocations form 2x2 quads (subgroup quad operations)
    mesh,     // the scene's triangles rasterized from a vertex buffer, depth-tested
};

// Throws a tf::Error when the device cannot run `kind` (compute: quads over its subgroups).
void check_render_kind(const VulkanContext& context, RenderKind kind);

// The pipeline for `kind` drawing width x height pixels, specialised to `filter`, built for a texture of
// `format` (integer formats: the HARNESS_RESOURCE_UINT shaders); destroyed by `cleanup`.
VkPipeline create_render_pipeline(const VulkanContext& context, RenderKind kind, VkPipelineLayout layout,
                                  Filter filter, uint32_t width, uint32_t height, Cleanup& cleanup,
                                  TextureFormat format = TextureFormat::rgba32f);

} // namespace tf
