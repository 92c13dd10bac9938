// The viewer's lifetime: checks, window, device, loop, teardown; and a new state applied.
#include "view/viewer.h"
#include "io/texture_source.h"
#include "texture/error.h"
#include "vulkan/device.h"
#include "view/frame_log.h"
#include <cstdio>

namespace tf {

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

void apply_state(Viewer& v, const ViewState& requested)
{
    SceneImages& im = v.images;
    ViewState next = requested;
    try { // the mesh scene is rasterized; ray differentials need a ray-cast scene
        next.render = make_render_options(next.scene, next.render.stage, next.render.gradients);
    } catch (const Error& e) {
        if (im.chain.levels.empty())
            throw;
        next.render = make_render_options(next.scene, Stage::fragment, Gradients::fine);
        v.controls.message = std::string(e.what()) + ": fragment stage, fine derivatives instead";
    }
    const bool first = im.chain.levels.empty();
    if (!is_dynamic_texture(next.texture))
        next.texture.texture_frame = 0; // only the dynamic texture has frames
    if (rebuilt_on_device(next.texture) && needs_sat(next)) // the previous state stays
        throw Error("the dynamic texture is rebuilt on the device every frame, without a summed-area table: sat "
                    "filters need a static texture (--build cpu, or another texture)");
    if (first || !same_texture(next.texture, v.state.texture)) {
        DeviceLimits limits = device_limits(v.context.info);
        // The dynamic texture's host chain (its frame now) gives the sizes and the footprint; the device makes
        // every frame's texels itself. A texture that fails throws here: the previous one stays.
        MipChain chain = load_texture(next.texture, {needs_sat(next), &limits});
        im.build = next.texture.build;
        if (rebuilt_on_device(next.texture))
            set_dynamic_texture(im, std::move(chain));
        else
            set_texture(im, std::move(chain));
        v.state.texture = next.texture;
        scene_changed(v);
    } else if (rebuilt_on_device(next.texture)) {
        v.state.texture.texture_frame = next.texture.texture_frame; // built before the next frame renders
    }
    const bool scene_moved = next.scene != v.state.scene || next.frame != v.state.frame || first;
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
    const TextureSource texture = v.state.texture; // the one loaded
    const int width = v.state.width, height = v.state.height;
    v.state = next;
    v.state.texture = texture;
    v.state.width = width;
    v.state.height = height;
    if (v.controls.truth) { // what the screenshot's second line renders
        v.state.b = ViewHalf{im.b.options};
    }
    v.stats.fetches_measured = false;
    if (scene_moved)
        scene_changed(v);
    if (v.window)
        set_window_title(*v.window, view_title(v));
}

namespace {

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

    v.window = create_window(options.state.width, options.state.height, view_title(v));
    teardown.add([&] { destroy_window(v.window); });
    v.surface = create_window_surface(v.context, *v.window);
    teardown.add([&] { vkDestroySurfaceKHR(v.context.instance, v.surface, nullptr); });
    check_present_support(v.context, v.surface);
    int width = 0, height = 0;
    framebuffer_size(*v.window, width, height);
    teardown.add([&] { destroy_swapchain(v.context, v.swapchain); }); // also a half-made one
    create_swapchain(v.context, v.surface, uint32_t(std::max(width, 2)), uint32_t(std::max(height, 2)), v.swapchain);
    create_compose_pass(v.context, v.swapchain.render_pass, v.compose, teardown);
    create_imgui_layer(v.context, *v.window, v.swapchain, teardown);
    create_frame_objects(v, teardown);
    teardown.add([&] { wait_idle_before_destroy(v.context); }); // first: nothing above still in use

    ScriptRun script;
    FrameLog log(options.frame_log);
    auto last = std::chrono::steady_clock::now();
    while (!v.quit && !should_close(*v.window)) {
        const bool scripted = !options.script.empty();
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
        if (!v.controls.pending_screenshot.empty()) {
            // Asked for with a key or a button, perhaps many times: never over a file already there.
            const std::string path = unused_screenshot_path(v.controls.pending_screenshot);
            v.controls.pending_screenshot.clear();
            try {
                screenshot(v, path, false);
                v.controls.message = "wrote " + path;
            } catch (const Error& e) {
                v.controls.message = e.what();
            }
        }
    }
    TF_VK(vkDeviceWaitIdle(v.context.device)); // the last frame done (checked here; the teardown's wait reports)
    log.write();
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
