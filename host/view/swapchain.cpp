#include "view/swapchain.h"
#include "texture/error.h"
#include <algorithm>

namespace tf {

namespace {

VkRenderPass create_render_pass(const VulkanContext& context, VkFormat format, bool load)
{
    // The composition covers every pixel, so nothing is loaded; the image ends ready to present. A screenshot
    // moves it to TRANSFER_SRC and back itself.
    VkAttachmentDescription color{};
    color.format = format;
    color.samples = VK_SAMPLE_COUNT_1_BIT;
    color.loadOp = load ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    color.initialLayout = load ? VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED;
    color.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    VkAttachmentReference reference{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &reference;
    // The acquire semaphore is waited at COLOR_ATTACHMENT_OUTPUT: the layout change waits for it too. (With
    // `load`, the blits before the pass have their own barrier into COLOR_ATTACHMENT_OPTIMAL.)
    VkSubpassDependency dependency{};
    dependency.srcSubpass = VK_SUBPASS_EXTERNAL;
    dependency.dstSubpass = 0;
    dependency.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    dependency.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    dependency.srcAccessMask = 0;
    dependency.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = 1;
    info.pAttachments = &color;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = 1;
    info.pDependencies = &dependency;
    VkRenderPass pass = VK_NULL_HANDLE;
    TF_VK(vkCreateRenderPass(context.device, &info, nullptr, &pass));
    return pass;
}

void destroy_image_objects(const VulkanContext& context, Swapchain& s)
{
    for (VkFramebuffer f : s.framebuffers)
        vkDestroyFramebuffer(context.device, f, nullptr);
    for (VkImageView v : s.views)
        vkDestroyImageView(context.device, v, nullptr);
    for (VkSemaphore r : s.rendered)
        vkDestroySemaphore(context.device, r, nullptr);
    s.framebuffers.clear();
    s.views.clear();
    s.rendered.clear();
    s.images.clear();
}

// Blits put the scene on the window (a fraction of a full-screen pass's cost on a CPU rasterizer); where the
// surface or format does not take them, the composition pass does it all.
bool takes_blits(const VulkanContext& context, const VkSurfaceCapabilitiesKHR& caps, VkFormat format)
{
    VkFormatProperties features{};
    vkGetPhysicalDeviceFormatProperties(context.physical, format, &features);
    return (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT) &&
           (features.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT);
}

VkExtent2D surface_extent(const VkSurfaceCapabilitiesKHR& caps, uint32_t width, uint32_t height)
{
    VkExtent2D extent{width, height};
    if (caps.currentExtent.width != UINT32_MAX)
        extent = caps.currentExtent; // X11: the window's size, which the surface dictates
    extent.width = std::clamp(extent.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent.height = std::clamp(extent.height, caps.minImageExtent.height, caps.maxImageExtent.height);
    return extent;
}

// Each image's view, framebuffer and `rendered` semaphore (destroy_image_objects undoes them).
void create_image_objects(const VulkanContext& context, Swapchain& s)
{
    uint32_t count = 0;
    TF_VK(vkGetSwapchainImagesKHR(context.device, s.handle, &count, nullptr));
    s.images.resize(count);
    TF_VK(vkGetSwapchainImagesKHR(context.device, s.handle, &count, s.images.data()));
    for (VkImage image : s.images) {
        VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        view.image = image;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = s.format;
        view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        s.views.push_back(VK_NULL_HANDLE);
        TF_VK(vkCreateImageView(context.device, &view, nullptr, &s.views.back()));
        VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        fb.renderPass = s.render_pass;
        fb.attachmentCount = 1;
        fb.pAttachments = &s.views.back();
        fb.width = s.extent.width;
        fb.height = s.extent.height;
        fb.layers = 1;
        s.framebuffers.push_back(VK_NULL_HANDLE);
        TF_VK(vkCreateFramebuffer(context.device, &fb, nullptr, &s.framebuffers.back()));
        VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        s.rendered.push_back(VK_NULL_HANDLE);
        TF_VK(vkCreateSemaphore(context.device, &semaphore, nullptr, &s.rendered.back()));
    }
}

} // namespace

void check_present_support(const VulkanContext& context, VkSurfaceKHR surface)
{
    VkBool32 supported = VK_FALSE;
    TF_VK(vkGetPhysicalDeviceSurfaceSupportKHR(context.physical, context.queue_family, surface, &supported));
    if (!supported)
        throw Error("view: " + context.info.name + " cannot present to this window (its graphics queue has no "
                    "present support); pick another with --device");
}

VkSurfaceFormatKHR choose_surface_format(const VulkanContext& context, VkSurfaceKHR surface)
{
    uint32_t count = 0;
    TF_VK(vkGetPhysicalDeviceSurfaceFormatsKHR(context.physical, surface, &count, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(count);
    TF_VK(vkGetPhysicalDeviceSurfaceFormatsKHR(context.physical, surface, &count, formats.data()));
    for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB})
        for (const VkSurfaceFormatKHR& f : formats)
            if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR)
                return f;
    throw Error("view: the window's surface offers no 8-bit sRGB format (B8G8R8A8_SRGB or R8G8B8A8_SRGB) on " +
                context.info.name);
}

void create_swapchain(const VulkanContext& context, VkSurfaceKHR surface, uint32_t width, uint32_t height,
                      Swapchain& s)
{
    VkSurfaceCapabilitiesKHR caps{};
    TF_VK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context.physical, surface, &caps));
    VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    if ((caps.supportedUsageFlags & usage) != usage)
        throw Error("view: the window's surface on " + context.info.name +
                    " cannot be copied from (no TRANSFER_SRC usage): screenshots need it");
    VkSurfaceFormatKHR format = choose_surface_format(context, surface);
    s.blit_target = takes_blits(context, caps, format.format);
    if (s.blit_target)
        usage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    const VkExtent2D extent = surface_extent(caps, width, height);
    uint32_t images = std::max(caps.minImageCount, 2u);
    if (caps.maxImageCount)
        images = std::min(images, caps.maxImageCount);

    // FIFO is the one mode every device has; the viewer paces itself (one frame in flight).
    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface;
    info.minImageCount = images;
    info.imageFormat = format.format;
    info.imageColorSpace = format.colorSpace;
    info.imageExtent = extent;
    info.imageArrayLayers = 1;
    info.imageUsage = usage;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    if (!(caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR))
        info.compositeAlpha = VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha & -caps.supportedCompositeAlpha);
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR;
    info.clipped = VK_TRUE;
    info.oldSwapchain = s.handle;
    VkSwapchainKHR handle = VK_NULL_HANDLE;
    TF_VK(vkCreateSwapchainKHR(context.device, &info, nullptr, &handle));
    destroy_image_objects(context, s);
    vkDestroySwapchainKHR(context.device, s.handle, nullptr); // the old one, if any
    s.handle = handle;
    if (s.render_pass && s.format != format.format) {
        vkDestroyRenderPass(context.device, s.render_pass, nullptr);
        vkDestroyRenderPass(context.device, s.load_pass, nullptr);
        s.render_pass = s.load_pass = VK_NULL_HANDLE;
    }
    s.format = format.format;
    s.extent = extent;
    s.min_image_count = images;
    if (!s.render_pass) {
        s.render_pass = create_render_pass(context, s.format, false);
        s.load_pass = create_render_pass(context, s.format, true);
    }
    create_image_objects(context, s);
}

void destroy_swapchain(const VulkanContext& context, Swapchain& s)
{
    destroy_image_objects(context, s);
    vkDestroySwapchainKHR(context.device, s.handle, nullptr);
    vkDestroyRenderPass(context.device, s.render_pass, nullptr);
    vkDestroyRenderPass(context.device, s.load_pass, nullptr);
    s = Swapchain{};
}

} // namespace tf
