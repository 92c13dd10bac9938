#pragma once
// The window's swapchain: images, views, one render pass (the scene's composition, then the UI, in one
// subpass) and a framebuffer per image. Recreated when the window's size changes; never made at zero extent
// (a minimised window) — the viewer waits instead.
#include "vulkan/device.h"
#include <vector>

namespace tf {

struct Swapchain {
    VkSwapchainKHR handle = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{};
    uint32_t min_image_count = 2;
    std::vector<VkImage> images;
    std::vector<VkImageView> views;
    std::vector<VkFramebuffer> framebuffers;
    std::vector<VkSemaphore> rendered; // one per image: the image's drawing finished, present may read it
    VkRenderPass render_pass = VK_NULL_HANDLE; // kept across recreation while the format stays
    // The UI over what blits wrote (loads the image, which is in COLOR_ATTACHMENT_OPTIMAL); compatible with
    // render_pass, so the framebuffers and pipelines serve both.
    VkRenderPass load_pass = VK_NULL_HANDLE;
    bool blit_target = false; // the images take blits (TRANSFER_DST usage, BLIT_DST format feature)
};

// An sRGB colour format the surface offers (B8G8R8A8_SRGB first): the composition writes linear light and
// the hardware encodes, as the PNG writer does for `texfilter render`. Throws if the surface has none.
VkSurfaceFormatKHR choose_surface_format(const VulkanContext& context, VkSurfaceKHR surface);

// Makes (or remakes, handing the old one over) the swapchain at width x height (clamped to what the surface
// allows). The images can be copied from (screenshots). Throws tf::Error naming what the surface lacks.
void create_swapchain(const VulkanContext& context, VkSurfaceKHR surface, uint32_t width, uint32_t height,
                      Swapchain& swapchain);
// Everything, render passes included: the viewer registers it in its Cleanup once, after the first create.
void destroy_swapchain(const VulkanContext& context, Swapchain& swapchain);

// Throws unless the context's queue can present to the surface.
void check_present_support(const VulkanContext& context, VkSurfaceKHR surface);

} // namespace tf
