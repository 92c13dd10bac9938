#pragma once
// The three ways the harness draws a scene, each its own pipeline over the same pass (vulkan/pass.h).
#include "core/filter.h"
#include "core/texture_format.h"
#include "vulkan/pipeline.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"
#include <vector>

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
                                  FilterVariant filter, uint32_t width, uint32_t height, Cleanup& cleanup,
                                  TextureFormat format = TextureFormat::rgba32f);

// Render pipelines kept for reuse by later renderers of one command (golden renders ~120 cases with ~30
// distinct pipelines; lavapipe spends most of a case compiling its pipeline). A pipeline depends only on the
// key below: every renderer of one kind creates an identically defined pipeline layout (create_renderer),
// and Vulkan binds a pipeline with any compatible layout; the layout it was made with may be destroyed.
// Destroy the cache (its cleanup) before the context, after the last frame using its pipelines completed.
struct RenderPipelineCache {
    struct Entry {
        RenderKind kind;
        FilterVariant filter;
        uint32_t width, height;
        bool integer; // the HARNESS_RESOURCE_UINT shaders
        VkPipeline pipeline;
    };
    std::vector<Entry> entries;
    Cleanup cleanup;
};
// create_render_pipeline through `cache`: an entry made earlier for the same key, else a new one kept there.
VkPipeline cached_render_pipeline(const VulkanContext& context, RenderPipelineCache& cache, RenderKind kind,
                                  VkPipelineLayout layout, FilterVariant filter, uint32_t width, uint32_t height,
                                  TextureFormat format);

} // namespace tf
