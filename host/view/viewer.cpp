// The viewer: its lifetime (checks, window, device, the loop, teardown), a new state applied, and each frame
// drawn (the halves one step on, the composition, the UI, present).
#include "view/viewer.h"
#include "io/texture_source.h"
#include "texture/error.h"
#include "view/blit_composition.h"
#include "view/frame_log.h"
#include "vulkan/device.h"
#include "vulkan/memory.h"
#include "vulkan/render.h"
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <imgui.h>

namespace tf {

namespace {

// A preview while the camera has moved within this long, so a drag renders at the preview's rate.
constexpr std::chrono::milliseconds settle_time{250};
// The frame budget that picks the preview's fraction: 30 frames a second.
constexpr double frame_budget_ms = 1000.0 / 30.0;
// Ground truth: samples a step, so that a step stays near the frame budget.
constexpr int truth_samples_a_step = 4;

} // namespace

bool rebuilt_on_device(const TextureSource& t) { return is_dynamic_texture(t) && t.build == TextureBuild::gpu; }

bool texture_animates(const Viewer& v) { return v.controls.texture_animate && v.images.dynamic.has_value(); }

void advance_texture_frame(Viewer& v)
{
    int& frame = v.state.texture.texture_frame;
    frame = frame >= max_texture_frame ? 0 : frame + 1;
}

void set_viewer_texture_frame(Viewer& v, int frame)
{
    if (!is_dynamic_texture(v.state.texture))
        throw Error("texture " + v.state.texture.name_or_path + " has no frames (only the dynamic texture animates)");
    ViewState next = v.state;
    next.texture.texture_frame = frame;
    apply_state(v, next); // --build gpu: rebuilt on the device; cpu: a new host chain
}

std::string problem_of(const std::function<void()>& change)
{
    try {
        change();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

// Like the camera's animation, a texture animating renders previews: each frame is a new image.
bool moving_now(const Viewer& v)
{
    return v.controls.animate || texture_animates(v) || std::chrono::steady_clock::now() - v.last_move < settle_time;
}

bool images_complete(const Viewer& v)
{
    const SceneImages& im = v.images;
    return im.a.complete && (!im.has_b || im.b.complete) && (!im.wants_truth || im.truth.complete);
}

void take_dropped_files(Viewer& v)
{
    if (v.window->dropped.empty())
        return;
    ViewState next = v.state;
    next.texture.name_or_path = v.window->dropped.back(); // several at once: the last one
    v.window->dropped.clear();
    v.controls.message = problem_of([&] { apply_state(v, next); });
}

void create_frame_objects(Viewer& v, Cleanup& cleanup)
{
    VkDevice device = v.context.device;
    VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    TF_VK(vkCreateSemaphore(device, &semaphore, nullptr, &v.acquired));
    cleanup.add([device, s = v.acquired] { vkDestroySemaphore(device, s, nullptr); });
    VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    TF_VK(vkCreateFence(device, &fence, nullptr, &v.frame_done));
    cleanup.add([device, f = v.frame_done] { vkDestroyFence(device, f, nullptr); });
    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool.queueFamilyIndex = v.context.queue_family;
    TF_VK(vkCreateCommandPool(device, &pool, nullptr, &v.command_pool));
    cleanup.add([device, p = v.command_pool] { vkDestroyCommandPool(device, p, nullptr); }); // frees the buffer
    VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocate.commandPool = v.command_pool;
    allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocate.commandBufferCount = 1;
    TF_VK(vkAllocateCommandBuffers(device, &allocate, &v.command_buffer));
}

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

SceneParams current_scene(const Viewer& v)
{
    SceneParams scene = make_scene(v.state.scene, v.scene_width, v.scene_height, v.images.chain.levels[0].width);
    if (v.state.frame)
        scene = scene_at_frame(scene, v.state.frame, v.images.chain.levels[0].width);
    return v.controls.camera_set ? with_camera(scene, v.controls.camera) : scene;
}

void scene_changed(Viewer& v)
{
    restart(v.images);
    v.state.camera = v.controls.camera_set ? to_string(v.controls.camera) : "";
    v.last_move = std::chrono::steady_clock::now();
    v.stats.fetches_measured = false;
}

std::string view_title(const Viewer& v)
{
    return "texfilter view: " + to_string(v.state.scene) + ", " + to_string(v.state.a.options.filter) +
           (v.images.has_b ? " | " + to_string(v.images.b.options.filter) : std::string());
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

namespace {

bool same_half(const HalfImage& half, const SamplerOptions& options, const RenderOptions& render)
{
    return same_options(half.options, options) && same_render(half.render, render);
}

// The dynamic texture built on the device changes frame without a reload (set_texture_frame); on the host
// a new frame is a new chain.
bool same_texture(const TextureSource& a, const TextureSource& b)
{
    return a.name_or_path == b.name_or_path && a.procedural_size == b.procedural_size && a.color == b.color &&
           a.build == b.build && (rebuilt_on_device(a) || a.texture_frame == b.texture_frame);
}

SamplerOptions truth_options(const SamplerOptions& a) { return truth_half(ViewHalf{a}).options; }

// The halves' render options: the debug view, where the half's filter has one (not the ground truth or none;
// the error view is the composition's).
RenderOptions half_render(const ViewState& s, const std::string& view, const SamplerOptions& half)
{
    RenderOptions r = s.render;
    const bool viewable = half.filter != Filter::ground_truth && half.filter != Filter::none;
    r.view = view == "error" || !viewable ? DebugView::color : parse_view(view);
    return r;
}

bool needs_sat(const ViewState& s) { return needs_sat(s.a.options.filter) || (s.b && needs_sat(s.b->options.filter)); }

} // namespace

namespace {

// The render options the scene allows: the mesh scene is rasterized, ray differentials need a ray-cast scene.
// Once a texture is shown, options the scene refuses fall back to the fragment stage and fine derivatives,
// with a message.
RenderOptions allowed_render(Viewer& v, const ViewState& next)
{
    try {
        return make_render_options(next.scene, next.render.stage, next.render.gradients);
    } catch (const Error& e) {
        if (v.images.chain.levels.empty())
            throw;
        v.controls.message = std::string(e.what()) + ": fragment stage, fine derivatives instead";
        return make_render_options(next.scene, Stage::fragment, Gradients::fine);
    }
}

// The texture `next` names, loaded when it is another one (first: none yet). Throws before anything changes.
void apply_texture(Viewer& v, const ViewState& next, bool first)
{
    if (rebuilt_on_device(next.texture) && needs_sat(next))
        throw Error("the dynamic texture is rebuilt on the device every frame, without a summed-area table: sat "
                    "filters need a static texture (--build cpu, or another texture)");
    if (first || !same_texture(next.texture, v.state.texture)) {
        DeviceLimits limits = device_limits(v.context.info);
        // The dynamic texture's host chain (its frame now) gives the sizes and the footprint; the device makes
        // every frame's texels itself.
        MipChain chain = load_texture(next.texture, {needs_sat(next), &limits});
        v.images.build = next.texture.build;
        if (rebuilt_on_device(next.texture))
            set_dynamic_texture(v.images, std::move(chain));
        else
            set_texture(v.images, std::move(chain));
        v.state.texture = next.texture;
        scene_changed(v);
    } else if (rebuilt_on_device(next.texture)) {
        v.state.texture.texture_frame = next.texture.texture_frame; // built before the next frame renders
    }
}

// Each half (A, B or the ground truth beside A, the truth behind the error view) with `next`'s options; a
// half whose options changed starts over with new renderers.
void apply_halves(Viewer& v, const ViewState& next, bool first)
{
    SceneImages& im = v.images;
    const RenderOptions a_render = half_render(next, next.view, next.a.options);
    if (first || !same_half(im.a, next.a.options, a_render))
        set_half_options(im, im.a, next.a.options, a_render);
    std::optional<SamplerOptions> b;
    if (v.controls.truth)
        b = truth_options(next.a.options);
    else if (next.b)
        b = next.b->options;
    im.has_b = b.has_value();
    if (b && !same_half(im.b, *b, half_render(next, next.view, *b)))
        set_half_options(im, im.b, *b, half_render(next, next.view, *b));
    im.wants_truth = next.view == "error";
    const SamplerOptions truth = truth_options(next.a.options);
    if (im.wants_truth && (first || !same_half(im.truth, truth, half_render(next, "color", truth))))
        set_half_options(im, im.truth, truth, half_render(next, "color", truth));
}

} // namespace

void apply_state(Viewer& v, const ViewState& requested)
{
    ViewState next = requested;
    next.render = allowed_render(v, next);
    const bool first = v.images.chain.levels.empty();
    if (!is_dynamic_texture(next.texture))
        next.texture.texture_frame = 0; // only the dynamic texture has frames
    apply_texture(v, next, first);
    const bool scene_moved = next.scene != v.state.scene || next.frame != v.state.frame || first;
    apply_halves(v, next, first);
    const TextureSource texture = v.state.texture; // the one loaded
    const int width = v.state.width, height = v.state.height;
    v.state = next;
    v.state.texture = texture;
    v.state.width = width;
    v.state.height = height;
    if (v.controls.truth) // what the screenshot's second line renders
        v.state.b = ViewHalf{v.images.b.options};
    v.stats.fetches_measured = false;
    if (scene_moved)
        scene_changed(v);
    if (v.window)
        set_window_title(*v.window, view_title(v));
}

namespace {

// The window and what draws into it, each registered in `teardown` as it is made.
void open_window(Viewer& v, Cleanup& teardown)
{
    v.window = create_window(v.options.state.width, v.options.state.height, view_title(v));
    teardown.add([&v] { destroy_window(v.window); });
    v.surface = create_window_surface(v.context, *v.window);
    teardown.add([&v] { vkDestroySurfaceKHR(v.context.instance, v.surface, nullptr); });
    check_present_support(v.context, v.surface);
    int width = 0, height = 0;
    framebuffer_size(*v.window, width, height);
    teardown.add([&v] { destroy_swapchain(v.context, v.swapchain); }); // also a half-made one
    create_swapchain(v.context, v.surface, uint32_t(std::max(width, 2)), uint32_t(std::max(height, 2)), v.swapchain);
    create_compose_pass(v.context, v.swapchain.render_pass, v.compose, teardown);
    create_imgui_layer(v.context, *v.window, v.swapchain, teardown);
    create_frame_objects(v, teardown);
    teardown.add([&v] { wait_idle_before_destroy(v.context); }); // first: nothing above still in use
}

// A screenshot asked for with a key or a button, perhaps many times: never over a file already there.
void take_pending_screenshot(Viewer& v)
{
    if (v.controls.pending_screenshot.empty())
        return;
    const std::string path = unused_screenshot_path(v.controls.pending_screenshot);
    v.controls.pending_screenshot.clear();
    const std::string problem = problem_of([&] { screenshot(v, path, false); });
    v.controls.message = problem.empty() ? "wrote " + path : problem;
}

// Frames until the window closes, the person quits or the script ends.
void run_frames(Viewer& v)
{
    ScriptRun script;
    FrameLog log(v.options.frame_log);
    auto last = std::chrono::steady_clock::now();
    while (!v.quit && !should_close(*v.window)) {
        const bool scripted = !v.options.script.empty();
        const bool idle = !scripted && !moving_now(v) && images_complete(v);
        if (idle)
            wait_events(0.05); // nothing changes until an event: the idle viewer sleeps
        else
            poll_events();
        take_dropped_files(v);
        auto now = std::chrono::steady_clock::now();
        handle_input(v, std::chrono::duration<double>(now - last).count());
        last = now;
        if (scripted && !run_script_step(v, script))
            break;
        if (v.quit)
            break;
        if (draw_frame(v, v.controls.ui)) {
            if (v.controls.animate) {
                ++v.state.frame;
                scene_changed(v);
            }
            if (texture_animates(v)) // rebuilt on the device before the next frame's renders
                advance_texture_frame(v);
            log.add(v);
        } else {
            wait_events(0.02); // minimised: nothing to draw until the window comes back
        }
        take_pending_screenshot(v);
    }
    TF_VK(vkDeviceWaitIdle(v.context.device)); // the last frame done (checked here; the teardown's wait reports)
    log.write();
}

// Everything between opening the display and tearing it all down again.
void view_until_closed(const ViewOptions& options)
{
    init_window_system(); // no display: one sentence, before any work
    Viewer v;
    v.options = options;
    Cleanup teardown; // each of the viewer's objects undone, in reverse, however this is left
    teardown.add([] { terminate_window_system(); });
    ContextOptions device = options.device;
    device.instance_extensions = window_instance_extensions();
    device.swapchain = true;
    v.context = create_context(device);
    teardown.add([&] { destroy_context(v.context); });
    v.state.width = v.scene_width = options.state.width;
    v.state.height = v.scene_height = options.state.height;
    v.images.context = &v.context;
    teardown.add([&] { destroy_scene_images(v.images); });
    apply_state(v, options.state); // the texture is checked and loaded before the window opens
    open_window(v, teardown);
    run_frames(v);
}

} // namespace

int run_viewer(const ViewOptions& options)
{
    view_until_closed(options);
    // After the teardown, so that a message from destroying the window's objects counts too.
    if (validation_message_count() > 0)
        throw Error("view: the Vulkan validation layers reported " + std::to_string(validation_message_count()) +
                    " message(s) (above)");
    return 0;
}

} // namespace tf
