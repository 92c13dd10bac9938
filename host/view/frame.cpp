// One frame of the viewer: the halves one step on, the composition, the UI, acquire, submit and present;
// the swapchain remade to the window's size. It reads and changes the state through viewer_state.cpp.
#include "view/viewer.h"
#include "view/blit_composition.h"
#include "vulkan/device.h"
#include "vulkan/memory.h"
#include "vulkan/render.h"
#include <algorithm>

namespace tf {

namespace {

// The frame budget that picks the preview's fraction: 30 frames a second.
constexpr double frame_budget_ms = 1000.0 / 30.0;
// Ground truth: samples a step, so that a step stays near the frame budget.
constexpr int truth_samples_a_step = 4;

} // namespace

namespace {

void recreate_swapchain(Viewer& v, int width, int height)
{
    TF_VK(vkDeviceWaitIdle(v.context.device));
    create_swapchain(v.context, v.surface, uint32_t(width), uint32_t(height), v.swapchain);
    imgui_swapchain_recreated(v.swapchain);
    v.window->resized = false;
    int w = int(v.swapchain.extent.width) & ~1, h = int(v.swapchain.extent.height) & ~1;
    if (w != v.scene_width || h != v.scene_height) {
        v.scene_width = std::max(2, w);
        v.scene_height = std::max(2, h);
        v.state.width = v.scene_width;
        v.state.height = v.scene_height;
        scene_changed(v);
    }
}

// The halves one step on; previews adapt their fraction to the frame budget.
void update_images(Viewer& v)
{
    // A new texture frame first, in its own submission: the halves then render from it.
    v.stats.texture_ms = set_texture_frame(v.images, v.state.texture.texture_frame) ? v.images.dynamic_ms : 0.0;
    const bool preview = v.options.preview && moving_now(v);
    const int scale = preview ? v.preview_scale : 1;
    const SceneParams scene = current_scene(v);
    SceneImages& im = v.images;
    double ms = 0;
    bool changed = false, first = false; // first: a renderer's first frame, which on lavapipe includes its JIT
    for (HalfImage* h : {&im.a, &im.b, &im.truth}) {
        if ((h == &im.b && !im.has_b) || (h == &im.truth && !im.wants_truth))
            continue;
        if (step_half(im, *h, scene, scale, truth_samples_a_step)) {
            changed = true;
            ms += h->last_ms;
            first = first || h->last_was_first;
        }
    }
    if (changed) {
        v.stats.render_ms = ms;
        v.stats.preview_scale = scale;
        v.compose_stale = true;
    }
    // The preview's fraction from the last full-size render (a render's time goes with its pixels), corrected
    // by the previews' own times only when well off: each new fraction is a new pipeline (~1 s on lavapipe).
    if (changed && first) {
        // a compile's time says nothing about the next frame's
    } else if (changed && scale == 1) {
        int k = 1;
        while (k < 16 && ms / (k * k) > frame_budget_ms)
            k *= 2;
        v.preview_scale = k;
    } else if (changed && preview) {
        if (ms > 2 * frame_budget_ms && v.preview_scale < 16)
            v.preview_scale *= 2;
        else if (ms < frame_budget_ms / 8 && v.preview_scale > 1)
            v.preview_scale /= 2;
    }
}

ComposeParams compose_params(const Viewer& v, bool with_ui)
{
    const SceneImages& im = v.images;
    ComposeParams p;
    p.size_a = {im.a.image.width, im.a.image.height};
    p.size_b = im.has_b ? glm::ivec2(im.b.image.width, im.b.image.height) : p.size_a;
    p.size_truth = im.wants_truth ? glm::ivec2(im.truth.image.width, im.truth.image.height) : p.size_a;
    p.full = {v.scene_width, v.scene_height};
    p.divider = im.has_b ? int(std::lround(v.state.divider * v.scene_width)) : (1 << 30);
    p.mode = v.state.view == "error" ? 1 : 0;
    p.error_max = v.controls.error_max;
    if (with_ui && v.controls.loupe) { // UI: the screenshot of the scene has no loupe
        p.loupe_center = v.controls.loupe_center;
        p.loupe_radius = v.controls.loupe_radius;
        p.loupe_zoom = std::max(1, v.controls.loupe_zoom);
    }
    return p;
}

void record_capture(VkCommandBuffer cb, VkImage image, VkExtent2D extent, const Buffer& capture)
{
    image_barrier(cb, {.image = image,
                       .from = {VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                                VK_IMAGE_LAYOUT_PRESENT_SRC_KHR},
                       .to = scope::transfer_src});
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(cb, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, capture.buffer, 1, &region);
    image_barrier(cb, {.image = image, .from = scope::transfer_src,
                       .to = {VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR}});
    record_host_read(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
}

} // namespace

void upload_compose_images(Viewer& v)
{
    const SceneImages& im = v.images;
    set_compose_image(v.compose, ComposeImage::a, im.a.image);
    if (im.has_b)
        set_compose_image(v.compose, ComposeImage::b, im.b.image);
    if (im.wants_truth)
        set_compose_image(v.compose, ComposeImage::truth, im.truth.image);
}

namespace {

// A swapchain of the window's size; false while minimised (no swapchain at zero extent).
bool swapchain_ready(Viewer& v)
{
    int width = 0, height = 0;
    framebuffer_size(*v.window, width, height);
    if (width == 0 || height == 0)
        return false;
    if (v.window->resized || !v.swapchain.handle || uint32_t(width) != v.swapchain.extent.width ||
        uint32_t(height) != v.swapchain.extent.height)
        recreate_swapchain(v, width, height);
    return true;
}

// What the frame does besides drawing: at rest, the next move's preview pipelines and the HUD's fetches.
void work_at_rest(Viewer& v, bool with_ui)
{
    if (v.options.preview && !moving_now(v) && images_complete(v)) { // at rest: the next move's pipelines now
        const SceneParams scene = current_scene(v);
        if (!warm_preview(v.images, v.images.a, scene, v.preview_scale) && v.images.has_b)
            warm_preview(v.images, v.images.b, scene, v.preview_scale); // one a frame: the UI keeps answering
    }
    if (with_ui && !v.stats.fetches_measured && images_complete(v)) {
        v.stats.fetches_per_pixel = fetches_per_pixel(v.images, v.images.a, current_scene(v));
        v.stats.fetches_measured = true;
    }
}

// The composition (blits or the pass), the UI and the capture into swapchain image `index`.
void record_frame(Viewer& v, uint32_t index, bool with_ui, const Buffer* capture)
{
    VkCommandBuffer cb = v.command_buffer;
    TF_VK(vkResetCommandBuffer(cb, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    TF_VK(vkBeginCommandBuffer(cb, &begin));
    const bool blit = can_blit(v);
    if (!blit && v.compose_stale) { // the composition pass reads the images from its buffers
        upload_compose_images(v);
        v.compose_stale = false;
    }
    if (blit) // the scene by blits, the UI over it in the pass that keeps them
        record_blit_composition(cb, v, v.swapchain.images[index], with_ui);
    VkRenderPassBeginInfo pass{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    pass.renderPass = blit ? v.swapchain.load_pass : v.swapchain.render_pass;
    pass.framebuffer = v.swapchain.framebuffers[index];
    pass.renderArea = {{0, 0}, v.swapchain.extent};
    vkCmdBeginRenderPass(cb, &pass, VK_SUBPASS_CONTENTS_INLINE);
    if (!blit)
        record_compose(cb, v.compose, v.swapchain.extent, compose_params(v, with_ui));
    if (with_ui)
        record_imgui(cb);
    vkCmdEndRenderPass(cb);
    if (capture)
        record_capture(cb, v.swapchain.images[index], v.swapchain.extent, *capture);
    TF_VK(vkEndCommandBuffer(cb));
}

// Submits the recorded frame after the acquire, presents image `index` and waits for the frame.
void submit_and_present(Viewer& v, uint32_t index)
{
    // The blits write the image too: they wait for the acquire as the attachment writes do.
    VkPipelineStageFlags wait_stage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &v.acquired;
    submit.pWaitDstStageMask = &wait_stage;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &v.command_buffer;
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &v.swapchain.rendered[index];
    TF_VK(vkResetFences(v.context.device, 1, &v.frame_done));
    TF_VK(vkQueueSubmit(v.context.queue, 1, &submit, v.frame_done));
    VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    present.waitSemaphoreCount = 1;
    present.pWaitSemaphores = &v.swapchain.rendered[index];
    present.swapchainCount = 1;
    present.pSwapchains = &v.swapchain.handle;
    present.pImageIndices = &index;
    VkResult presented = vkQueuePresentKHR(v.context.queue, &present);
    if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR)
        v.window->resized = true;
    else
        TF_VK(presented);
    // One frame in flight: the next frame rewrites the compose buffers and the command buffer.
    TF_VK(vkWaitForFences(v.context.device, 1, &v.frame_done, VK_TRUE, UINT64_MAX));
}

} // namespace

bool draw_frame(Viewer& v, bool with_ui, const Buffer* capture)
{
    if (!swapchain_ready(v))
        return false;
    const auto start = std::chrono::steady_clock::now();
    update_images(v);
    work_at_rest(v, with_ui);
    if (with_ui) {
        imgui_begin_frame();
        build_ui(v);
        imgui_end_frame();
    }
    uint32_t index = 0;
    VkResult acquired = vkAcquireNextImageKHR(v.context.device, v.swapchain.handle, UINT64_MAX, v.acquired,
                                              VK_NULL_HANDLE, &index);
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
        v.window->resized = true;
        return false;
    }
    if (acquired != VK_SUBOPTIMAL_KHR)
        TF_VK(acquired);
    record_frame(v, index, with_ui, capture);
    submit_and_present(v, index);
    v.stats.frame_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return true;
}

void finish_images(Viewer& v)
{
    v.last_move = {};
    v.controls.animate = false;
    v.controls.texture_animate = false; // the texture stays at the frame shot
    set_texture_frame(v.images, v.state.texture.texture_frame);
    const SceneParams scene = current_scene(v);
    SceneImages& im = v.images;
    // Bounded: each step adds at least one sample, and a ground truth has at most 4096.
    for (HalfImage* h : {&im.a, &im.b, &im.truth}) {
        if ((h == &im.b && !im.has_b) || (h == &im.truth && !im.wants_truth))
            continue;
        while (!h->complete)
            step_half(im, *h, scene, 1, samples_per_pixel(h->options));
    }
    v.compose_stale = true;
}

} // namespace tf
