#pragma once
// A render kept alive across frames: the benchmark draws one pipeline many times (GPU timestamps) and
// along a camera path (new scene parameters each frame). gpu_render() in vulkan/backend.h is the one-shot form.
#include "vulkan/backend.h"
#include "vulkan/pass.h"
#include <memory>

namespace tf {

// What every form of the pass binds: textures, the scene's uniform buffer, a pixel buffer (compute).
struct PassResources {
    Buffer uniforms, pixels;
    PassSamplers samplers;
    VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
    VkPipelineLayout pipeline_layout = VK_NULL_HANDLE;
    DescriptorSet descriptors;
    VkDescriptorBufferInfo uniform_info{}, pixel_info{};
};

// One pipeline with its target and resources, for one scene size and kind, texture and filter.
struct GpuRenderer {
    const VulkanContext* context = nullptr;
    bool compute = false, mesh = false;
    uint32_t width = 0, height = 0, vertex_count = 3;
    PassResources pass;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkImage target = VK_NULL_HANDLE, depth = VK_NULL_HANDLE; // graphics
    VkImageView target_view = VK_NULL_HANDLE, depth_view = VK_NULL_HANDLE;
    Buffer readback, vertices;
    PushConstants push{};
    VkClearColorValue background{};
    Cleanup cleanup; // last member, so it runs first: destroys everything above in reverse order of creation
};

std::unique_ptr<GpuRenderer> create_renderer(const VulkanContext& context, const GpuTexture& texture,
                                             const SceneParams& scene, const SamplerOptions& options,
                                             const RenderOptions& render);

// Draws one frame of `scene` (same kind and size as at creation; the camera path changes only its
// parameters) and reads it back.
Image render_frame(GpuRenderer& renderer, const SceneParams& scene);

// How frames are timed. timestamps: GPU timestamps written before and after each frame's draw or
// dispatch, all frames in one submit (real GPUs). wall_clock: one submit and wait a frame, timed on the
// host: lavapipe writes timestamps when it records a command, not when its threads finish the work
// (they read 0.3 ms for a 30 ms frame), so on CPU devices only the wall clock measures anything.
enum class FrameTimer { timestamps, wall_clock };
FrameTimer parse_frame_timer(const std::string& name); // "timestamps", "wall-clock"
std::string to_string(FrameTimer timer);

// The time of `frames` frames after `warmup` untimed ones, in milliseconds each. Throws tf::Error when
// timestamps are asked for and the queue has none. The wall clock cuts a pathologically slow case short
// (see vulkan/render.cpp): it may return fewer than `frames` times, never none.
std::vector<double> time_frames(GpuRenderer& renderer, int warmup, int frames, FrameTimer timer);

} // namespace tf
