// The viewer's lifetime: checks, window, device, the loop (input, script, dropped files, screenshots),
// teardown. Each frame is drawn by frame.cpp; state changes go through viewer_state.cpp.
#include "view/viewer.h"
#include "texture/error.h"
#include "view/frame_log.h"
#include "vulkan/device.h"
#include <algorithm>

namespace tf {

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
