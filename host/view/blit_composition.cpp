#include "view/blit_composition.h"
#include "view/viewer.h"
#include "vulkan/memory.h"
#include <algorithm>
#include <cmath>

namespace tf {

namespace {

// Window pixels [x0, x1) x [y0, y1) of the scene from `half`'s image, which spans the whole scene.
void blit_region(VkCommandBuffer cb, const Viewer& v, const HalfImage& half, VkImage target, glm::dvec2 d0,
                 glm::dvec2 d1, glm::dvec2 s0, glm::dvec2 s1)
{
    const glm::dvec2 full(v.scene_width, v.scene_height);
    const glm::dvec2 size(half.shown->width, half.shown->height);
    // Window coordinates to the image's: identity at full size, a scaling for a preview.
    const glm::ivec2 src0 = glm::ivec2(glm::round(s0 * size / full)), src1 = glm::ivec2(glm::round(s1 * size / full));
    const glm::ivec2 dst0 = glm::ivec2(glm::round(d0)), dst1 = glm::ivec2(glm::round(d1));
    if (src1.x <= src0.x || src1.y <= src0.y || dst1.x <= dst0.x || dst1.y <= dst0.y)
        return;
    VkImageBlit region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.srcOffsets[0] = {src0.x, src0.y, 0};
    region.srcOffsets[1] = {src1.x, src1.y, 1};
    region.dstOffsets[0] = {dst0.x, dst0.y, 0};
    region.dstOffsets[1] = {dst1.x, dst1.y, 1};
    vkCmdBlitImage(cb, half.shown->targets.color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_NEAREST);
}

int divider_column(const Viewer& v)
{
    return v.images.has_b ? std::clamp(int(std::lround(v.state.divider * v.scene_width)), 0, v.scene_width)
                          : v.scene_width;
}

} // namespace

bool can_blit(const Viewer& v)
{
    const SceneImages& im = v.images;
    return v.swapchain.blit_target && v.state.view != "error" && im.a.shown && (!im.has_b || im.b.shown) &&
           im.a.shown->width == uint32_t(im.a.image.width) && (!im.has_b || im.b.shown->width == uint32_t(im.b.image.width));
}

void record_blit_composition(VkCommandBuffer cb, const Viewer& v, VkImage target, bool with_loupe)
{
    image_barrier(cb, {.image = target, .from = {VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_IMAGE_LAYOUT_UNDEFINED},
                       .to = scope::transfer_dst});
    const VkExtent2D extent = v.swapchain.extent;
    if (extent.width != uint32_t(v.scene_width) || extent.height != uint32_t(v.scene_height)) {
        // An odd last column or row beyond the scene's even size: black, as the composition pass leaves it.
        VkClearColorValue black{{0.0f, 0.0f, 0.0f, 1.0f}};
        VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdClearColorImage(cb, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &black, 1, &range);
        memory_barrier(cb, {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT},
                           {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT});
    }
    const glm::dvec2 full(v.scene_width, v.scene_height);
    const int divider = divider_column(v);
    blit_region(cb, v, v.images.a, target, {0, 0}, {divider, full.y}, {0, 0}, {divider, full.y});
    if (v.images.has_b)
        blit_region(cb, v, v.images.b, target, {divider, 0}, full, {divider, 0}, full);
    if (with_loupe && v.controls.loupe) {
        // The square around the centre, magnified from the half under the centre; clipped to the scene.
        const glm::dvec2 c(v.controls.loupe_center), r(v.controls.loupe_radius);
        const double zoom = std::max(1, v.controls.loupe_zoom);
        const glm::dvec2 d0 = glm::max(c - r, glm::dvec2(0.0)), d1 = glm::min(c + r, full);
        const HalfImage& half = v.images.has_b && c.x >= divider ? v.images.b : v.images.a;
        memory_barrier(cb, {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT},
                           {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT});
        blit_region(cb, v, half, target, d0, d1, c + (d0 - c) / zoom, c + (d1 - c) / zoom);
    }
    image_barrier(cb, {.image = target, .from = scope::transfer_dst,
                       .to = {VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                              VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                              VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL}});
}

} // namespace tf
