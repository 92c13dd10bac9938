#include "vulkan/render_targets.h"
#include "vulkan/barriers.h"
#include <glm/vec4.hpp>

namespace tf {

RenderTargets create_render_targets(const VulkanContext& context, uint32_t width, uint32_t height, bool with_depth,
                                    Cleanup& cleanup)
{
    RenderTargets t;
    t.width = width;
    t.height = height;
    GpuImage color = t.color = create_image(context, render_color_format, width, height, 1,
                                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                            VK_IMAGE_ASPECT_COLOR_BIT);
    cleanup.add([&context, color]() mutable { destroy_image(context, color); });
    if (with_depth) {
        GpuImage depth = t.depth = create_image(context, render_depth_format, width, height, 1,
                                                VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT);
        cleanup.add([&context, depth]() mutable { destroy_image(context, depth); });
    }
    Buffer readback = t.readback = create_host_buffer(context, VkDeviceSize(width) * height * sizeof(glm::vec4),
                                                      VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    cleanup.add([&context, readback]() mutable { destroy_buffer(context, readback); });
    return t;
}

void record_targets_for_drawing(VkCommandBuffer cb, const RenderTargets& targets)
{
    // UNDEFINED: the previous frame's content is not needed (the whole target is redrawn or cleared).
    image_barrier(cb, targets.color.image, 1, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                  VK_ACCESS_TRANSFER_READ_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                  VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                  VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT);
    if (targets.depth.image)
        image_barrier(cb, targets.depth.image, 1, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                      VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                      VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
                      VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT, VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT,
                      VK_IMAGE_ASPECT_DEPTH_BIT);
}

void record_begin_rendering(VkCommandBuffer cb, const RenderTargets& targets, const VkClearColorValue* background)
{
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = targets.color.view;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = background ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    if (background)
        color.clearValue.color = *background;
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth.imageView = targets.depth.view;
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depth.clearValue.depthStencil = {1.0f, 0};
    VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
    info.renderArea = {{0, 0}, {targets.width, targets.height}};
    info.layerCount = 1;
    info.colorAttachmentCount = 1;
    info.pColorAttachments = &color;
    info.pDepthAttachment = targets.depth.view ? &depth : nullptr;
    vkCmdBeginRendering(cb, &info);
}

void record_targets_for_readback(VkCommandBuffer cb, const RenderTargets& targets)
{
    image_barrier(cb, targets.color.image, 1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                  VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                  VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                  VK_PIPELINE_STAGE_TRANSFER_BIT);
}

} // namespace tf
