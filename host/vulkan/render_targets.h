#pragma once
// What the graphics pipelines draw into: an RGBA32F colour target, a depth buffer for the rasterized
// mesh, and the host buffer each frame is copied to; and the layout changes around a frame's drawing.
#include "vulkan/cleanup.h"
#include "vulkan/image.h"
#include "vulkan/resources.h"

namespace tf {

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

} // namespace tf
