#pragma once
// A render kept alive across frames: the benchmark draws one pipeline many times (vulkan/frame_timer.h)
// and along a camera path (new scene parameters each frame). gpu_render() in vulkan/backend.h is the
// one-shot form.
#include "vulkan/backend.h"
#include "vulkan/pass.h"
#include "vulkan/render_pipeline.h"
#include "vulkan/render_targets.h"
#include <memory>

namespace tf {

// One pipeline with its pass, buffers and targets, for one scene size and kind, texture and filter.
struct GpuRenderer {
    const VulkanContext* context = nullptr;
    RenderKind kind = RenderKind::fragment;
    uint32_t width = 0, height = 0;
    Buffer uniforms;           // the scene (SceneParams), rewritten each frame
    // compute: the frame, RGBA32F, in device-local memory, and its host copy (made only for a readback). A frame
    // written straight into host-visible memory crosses the bus on a discrete GPU: 16 MiB a 1024² frame, ~0.3 ms
    // over PCIe, about what every compute frame took on an NVIDIA H200 whatever the filter (not re-measured there).
    Buffer pixels;
    Buffer pixels_readback;
    Buffer vertices;           // mesh: its triangles
    uint32_t vertex_count = 3; // the full-screen triangle, or the mesh's vertices
    Pass pass;
    VkPipeline pipeline = VK_NULL_HANDLE;
    RenderTargets targets; // fragment and mesh
    PushConstants push{};
    VkClearColorValue background{};
    int scene_kind = -1; // the pipeline's HARNESS_SPEC_SCENE: render_frame draws scenes of this kind only
    Cleanup cleanup; // last member, so it runs first: destroys everything above in reverse order of creation
};

// The pipeline variant of a render: the sampler options' filter_variant with the render's debug view and
// gradient form (tf::DebugView and tf::Gradients take the HARNESS_VIEW_* and HARNESS_GRADIENTS_* values) and
// the ray-cast scene's kind (scene_kind, HARNESS_SCENE_*; -1 for shaders that cast no 2D scene).
FilterVariant render_variant(const SamplerOptions& options, const RenderOptions& render, int scene_kind);

// cache: reuse a pipeline made earlier for the same kind, filter and size (null: the renderer's own).
std::unique_ptr<GpuRenderer> create_renderer(const VulkanContext& context, const GpuTexture& texture,
                                             const SceneParams& scene, const SamplerOptions& options,
                                             const RenderOptions& render, RenderPipelineCache* cache = nullptr);

// Draws one frame of `scene` (same kind and size as at creation; the camera path changes only its
// parameters) and reads it back.
Image render_frame(GpuRenderer& renderer, const SceneParams& scene);
// render_frame, or with --stochastic --accumulate N the mean of N frames, each with its own random numbers.
Image render_accumulated(GpuRenderer& renderer, const SceneParams& scene, const SamplerOptions& options);

} // namespace tf
