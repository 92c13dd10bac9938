// The viewer's state: a new state applied (texture, halves, what they render), the scene and camera as they
// stand, and the queries the frame, the UI and the input read. Below the frame and the handlers: it calls
// none of them.
#include "view/viewer.h"
#include "io/texture_source.h"
#include "texture/error.h"

namespace tf {

namespace {

// A preview while the camera has moved within this long, so a drag renders at the preview's rate.
constexpr std::chrono::milliseconds settle_time{250};

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

} // namespace tf
