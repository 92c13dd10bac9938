#pragma once
// The composition pass: the scene images (filter A, filter B, the ground truth) on the window, through
// shaders/viewer/compose.frag.glsl, in the swapchain's render pass (the UI draws after it, same subpass).
// The images live in host-visible buffers the viewer fills with the renderer's pixels.
#include "texture/image.h"
#include "vulkan/cleanup.h"
#include "vulkan/memory.h"
#include <glm/glm.hpp>

namespace tf {

// The push constants of compose.frag.glsl, in its order.
struct ComposeParams {
    glm::ivec2 size_a{0}, size_b{0}, size_truth{0}, full{0};
    glm::ivec2 loupe_center{0};
    int32_t loupe_radius = 0, loupe_zoom = 1;
    int32_t divider = 1 << 30;
    int32_t mode = 0; // 0 images, 1 error heat map
    float error_max = 0.1f;
    int32_t pad = 0;
};
static_assert(sizeof(ComposeParams) == 64);

enum class ComposeImage { a = 0, b = 1, truth = 2 };

struct ComposePass {
    const VulkanContext* context = nullptr;
    VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;
    Buffer images[3]; // grown by set_compose_image
};

// Everything made (the buffers as they are then) is destroyed by `cleanup`; `pass` stays where it is until then.
void create_compose_pass(const VulkanContext& context, VkRenderPass render_pass, ComposePass& pass, Cleanup& cleanup);
// Copies `image` into the pass's buffer for `which`, growing it when needed (waits for the device first:
// the viewer keeps one frame in flight).
void set_compose_image(ComposePass& pass, ComposeImage which, const Image& image);
// Inside the render pass: the full-window triangle, viewport and scissor set to `extent`.
void record_compose(VkCommandBuffer command_buffer, const ComposePass& pass, VkExtent2D extent,
                    const ComposeParams& params);

} // namespace tf
