#pragma once
// A frame: render targets and their readback, the pass (descriptor set and pipeline layout) every harness
// shader shares, the mesh, the render pipelines, a renderer recording a frame into a command buffer, and
// gpu_render (backend.h) around it.
#include "core/filter.h"
#include "core/texture_format.h"
#include "scene/scene.h"
#include "scene/shader_interface.h"
#include "texture/image.h"
#include "vulkan/backend.h"
#include "vulkan/cleanup.h"
#include "vulkan/device.h"
#include "vulkan/memory.h"
#include "vulkan/pipelines.h"
#include "vulkan/textures.h"
#include <glm/vec4.hpp>
#include <memory>
#include <vector>

namespace tf {

// What the graphics pipelines draw into: an RGBA32F colour target, a depth buffer for the rasterized
// mesh, and the host buffer each frame is copied to; and the layout changes around a frame's drawing.
constexpr VkFormat render_color_format = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkFormat render_depth_format = VK_FORMAT_D32_SFLOAT;

struct RenderTargets {
    GpuImage color;
    GpuImage depth;  // with_depth only
    Buffer readback; // width x height RGBA32F texels, host-visible
    uint32_t width = 0, height = 0;
};

// Destroyed by `cleanup`.
RenderTargets create_render_targets(const VulkanContext& context, uint32_t width, uint32_t height, bool with_depth,
                                    Cleanup& cleanup);

// Before the draw: both targets into attachment layouts. Their content is not kept from frame to frame.
void record_targets_for_drawing(VkCommandBuffer command_buffer, const RenderTargets& targets);
// Starts dynamic rendering over the whole target. background: the colour target cleared to it; null: every
// pixel is drawn, so it is not cleared. The depth buffer, where there is one, is cleared to 1.
void record_begin_rendering(VkCommandBuffer command_buffer, const RenderTargets& targets,
                            const VkClearColorValue* background);
// After vkCmdEndRendering: the colour target into TRANSFER_SRC layout, for record_target_readback.
void record_targets_for_readback(VkCommandBuffer command_buffer, const RenderTargets& targets);

// Results back to the host: the barrier that makes a pass's writes visible to it, the colour target's
// copy into its host buffer, and the pixels out of a mapped buffer.
// After the commands (at `stage`, with `access`) that wrote host-visible memory: those writes made
// visible to the host once the submit has completed.
void record_host_read(VkCommandBuffer command_buffer, VkPipelineStageFlags stage, VkAccessFlags access);

// After record_targets_for_readback: the colour target into targets.readback, visible to the host.
void record_target_readback(VkCommandBuffer command_buffer, const RenderTargets& targets);

// One level of a colour image back to the host: width x height texels of texel_bytes each, tightly packed.
// The image is in `layout` before and after (its last writes, at any shader or transfer stage, are
// waited for). Submits and waits. For `texfilter build` and the tests of the GPU builds.
std::vector<unsigned char> read_image_level(const VulkanContext& context, VkImage image, uint32_t level,
                                            uint32_t width, uint32_t height, size_t texel_bytes, VkImageLayout layout);

// width x height RGBA32F texels from a mapped buffer (once the submit that wrote it has completed).
Image read_pixels(const Buffer& buffer, int width, int height);

// What every harness pass (render in each stage, sample) creates the same way: one descriptor set with
// the three textures and the pass's own buffers, its layout, the pipeline layout with the push constants,
// and the commands that bind them. Only the pipeline and the buffers differ from pass to pass.
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

// The same with the pass's images given (sample.h's kinds); pass.samplers stays empty.
Pass create_pass_with_images(const VulkanContext& context, const std::vector<PassImages>& images,
                             VkShaderStageFlags stages, VkShaderStageFlags push_stages,
                             const std::vector<PassBuffer>& buffers, Cleanup& cleanup);

// Binds `pipeline` (made with pass.pipeline_layout), the pass's descriptor set and `push`.
void bind_pass(VkCommandBuffer command_buffer, VkPipelineBindPoint bind_point, VkPipeline pipeline, const Pass& pass,
               const PushConstants& push);

PushConstants make_push_constants(const SamplerOptions& options, uint32_t count, glm::vec4 sat_offset,
                                  glm::vec4 sat_scale);

// The mesh scene's vertex buffer: each triangle of SceneParams as three vertices with position and uv,
// the layout mesh.vert.glsl reads.
struct MeshVertex {
    float position[3];
    float uv[2];
};

uint32_t mesh_vertex_count(const SceneParams& scene);

// A host-visible vertex buffer holding the scene's triangles, destroyed by `cleanup`.
Buffer create_mesh_vertices(const VulkanContext& context, const SceneParams& scene, Cleanup& cleanup);

// The three ways the harness draws a scene, each its own pipeline over the same pass (create_pass above).
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

// A render kept alive across frames: the benchmark draws one pipeline many times (vulkan/timing.h)
// and along a camera path (new scene parameters each frame). gpu_render() in vulkan/backend.h is the
// one-shot form.
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

// The commands of one frame of a GpuRenderer, shared by render_frame and the frame timers.
// The dispatch (into the pixel buffer) or the draw (into the colour target, which ends in TRANSFER_SRC
// layout). `timestamps` (or null) bracket the work itself, not the layout changes around it, at queries
// `query` and `query + 1`.
void record_frame(const GpuRenderer& renderer, VkCommandBuffer command_buffer, VkQueryPool timestamps,
                  uint32_t query);

// After record_frame: the frame in host-visible memory (the pixel buffer or the targets' readback buffer).
void record_frame_readback(const GpuRenderer& renderer, VkCommandBuffer command_buffer);

} // namespace tf
