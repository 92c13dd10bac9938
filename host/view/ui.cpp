// The viewer's panels: every option of `texfilter render` as a widget, for filter A and filter B; the HUD;
// the split divider, the loupe's frame and the footprint of the pixel under the cursor drawn over the image.
#include "view/viewer.h"
#include "reference/footprint.h"
#include "texture/error.h"
#include <imgui.h>
#include <cmath>
#include <cstdio>

namespace tf {

namespace {

template <typename Enum>
bool enum_combo(const char* label, Enum& value, int first, int last, std::string (*name)(Enum))
{
    bool changed = false;
    if (ImGui::BeginCombo(label, name(value).c_str())) {
        for (int i = first; i <= last; ++i) {
            Enum e = Enum(i);
            if (ImGui::Selectable(name(e).c_str(), e == value)) {
                value = e;
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

std::string filter_name(Filter f) { return to_string(f); }
std::string wrap_name(Wrap w) { return to_string(w); }
std::string shape_name(AnisoShape s) { return to_string(s); }
std::string taps_name(Taps t) { return to_string(t); }
std::string reconstruction_name(Reconstruction r) { return to_string(r); }
std::string pixel_filter_name(PixelFilter p) { return to_string(p); }
std::string scene_name(SceneKind s) { return to_string(s); }
std::string stage_name(Stage s) { return to_string(s); }
std::string gradients_name(Gradients g) { return to_string(g); }

// The options the chosen filter reads, with the CLI's ranges. Returns true when one changed.
bool filter_widgets(const char* id, SamplerOptions& o)
{
    ImGui::PushID(id);
    bool c = enum_combo("filter", o.filter, HARNESS_FILTER_NEAREST, HARNESS_FILTER_CATMULL_ROM, filter_name);
    c |= enum_combo("wrap", o.wrap, HARNESS_WRAP_REPEAT, HARNESS_WRAP_MIRROR, wrap_name);
    const Filter f = o.filter;
    if (f != Filter::ground_truth && f != Filter::none) {
        c |= ImGui::SliderFloat("LOD bias", &o.lod_bias, -16.0f, 16.0f);
        c |= ImGui::SliderFloat("LOD min", &o.lod_min, 0.0f, 16.0f);
        c |= ImGui::SliderFloat("LOD max", &o.lod_max, 0.0f, 1000.0f, "%.1f", ImGuiSliderFlags_Logarithmic);
        if (o.lod_min > o.lod_max)
            o.lod_max = o.lod_min;
    }
    if (f == Filter::brilinear)
        c |= ImGui::SliderFloat("band", &o.band, 0.0f, 1.0f);
    if (f == Filter::hw_aniso)
        c |= ImGui::SliderInt("max anisotropy", &o.aniso, 1, 16);
    if (f == Filter::aniso) {
        c |= ImGui::SliderInt("probes", &o.probes, 1, 16);
        c |= enum_combo("shape", o.aniso_shape, HARNESS_ANISO_GPU, HARNESS_ANISO_FELINE, shape_name);
    }
    if (takes_magnify(f))
        c |= enum_combo("magnify", o.magnify, HARNESS_RECONSTRUCT_BILINEAR, HARNESS_RECONSTRUCT_CATMULL_ROM,
                        reconstruction_name);
    if (takes_taps(f))
        c |= enum_combo("taps", o.taps, HARNESS_TAPS_MANUAL, HARNESS_TAPS_HARDWARE, taps_name);
    if (f == Filter::ewa) {
        c |= ImGui::SliderFloat("alpha", &o.alpha, 0.05f, 16.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
        c |= ImGui::SliderFloat("max aniso", &o.max_aniso, 1.0f, 64.0f, "%.1f", ImGuiSliderFlags_Logarithmic);
    }
    if (f == Filter::sat_assembly)
        c |= ImGui::SliderInt("boxes", &o.boxes, 1, 16);
    if (f == Filter::ground_truth) {
        c |= enum_combo("pixel filter", o.pixel_filter, HARNESS_PIXEL_FILTER_BOX, HARNESS_PIXEL_FILTER_GAUSSIAN,
                        pixel_filter_name);
        c |= ImGui::SliderInt("spp side", &o.truth_side, 1, max_ground_truth_side);
    }
    ImGui::PopID();
    return c;
}

void hud(Viewer& v)
{
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - 10.0f, 10.0f), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.6f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;
    if (ImGui::Begin("hud", nullptr, flags)) {
        ImGui::Text("frame %.1f ms  scene %.1f ms", v.stats.frame_ms, v.stats.render_ms);
        if (v.stats.preview_scale > 1)
            ImGui::Text("moving: preview at 1/%d size", v.stats.preview_scale);
        else if (images_complete(v))
            ImGui::Text("full resolution %dx%d", v.scene_width, v.scene_height);
        else
            ImGui::Text("refining %dx%d", v.scene_width, v.scene_height);
        const HalfImage* gt = v.images.has_b && v.images.b.options.filter == Filter::ground_truth ? &v.images.b
                              : v.images.wants_truth                                              ? &v.images.truth
                                                                                                  : nullptr;
        if (gt)
            ImGui::Text("ground truth %d / %d samples", gt->samples_done, samples_per_pixel(gt->options));
        if (v.stats.fetches_measured && v.stats.fetches_per_pixel >= 0)
            ImGui::Text("A: %.1f texel fetches + hardware lookups a pixel", v.stats.fetches_per_pixel);
        ImGui::Text("%s", v.context.info.name.c_str());
        ImGui::Text("%s %s", v.context.info.driver_name.c_str(), v.context.info.driver_info.c_str());
        ImGui::Text("frame %d of the camera path%s", v.state.frame, v.controls.animate ? " (animating)" : "");
        if (v.images.dynamic)
            ImGui::Text("texture frame %d%s, rebuilt on the device: %.1f ms", v.state.texture.texture_frame,
                        texture_animates(v) ? " (animating)" : "", v.images.dynamic_ms);
    }
    ImGui::End();
}

// The pixel's footprint under `half`'s filter (the ellipse it integrates, and the aniso probes) mapped from uv back to
// the window through the inverse of the pixel's uv Jacobian, magnified with the loupe when it is under it.
void draw_footprint(Viewer& v, const HalfImage& half, glm::ivec2 pixel)
{
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= v.scene_width || pixel.y >= v.scene_height)
        return;
    const Filter filter = half.options.filter;
    if (filter == Filter::ground_truth || filter == Filter::none)
        return;
    PixelFootprint f = pixel_footprint(current_scene(v), v.images.chain, half.options, half.render, pixel);
    if (!f.hit)
        return;
    const glm::dmat2 j(f.duv_dx, f.duv_dy); // columns: uv per window pixel in x and in y
    if (!std::isfinite(glm::determinant(j)) || std::abs(glm::determinant(j)) < 1e-30)
        return;
    const glm::dmat2 inverse = glm::inverse(j);
    glm::dvec2 centre = glm::dvec2(pixel) + 0.5;
    double zoom = 1.0;
    if (v.controls.loupe && glm::all(glm::lessThan(glm::abs(glm::ivec2(pixel) - v.controls.loupe_center),
                                                   glm::ivec2(v.controls.loupe_radius)))) {
        zoom = v.controls.loupe_zoom;
        centre = glm::dvec2(v.controls.loupe_center) + (centre - glm::dvec2(v.controls.loupe_center)) * zoom;
    }
    auto to_window = [&](glm::dvec2 uv_offset) {
        glm::dvec2 p = centre + inverse * uv_offset * zoom;
        return ImVec2(float(p.x), float(p.y));
    };
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    constexpr int segments = 64;
    ImVec2 points[segments];
    for (int i = 0; i < segments; ++i) {
        const double t = 6.283185307179586 * i / segments;
        points[i] = to_window(f.major * std::cos(t) + f.minor * std::sin(t));
    }
    draw->AddPolyline(points, segments, IM_COL32(255, 255, 0, 230), ImDrawFlags_Closed, 1.5f);
    for (const glm::dvec2& probe : f.probes)
        draw->AddCircleFilled(to_window(probe - f.uv), 2.5f, IM_COL32(0, 255, 255, 230));
    ImGui::BeginTooltip();
    ImGui::Text("pixel %d,%d  uv %.5f, %.5f", pixel.x, pixel.y, f.uv.x, f.uv.y);
    ImGui::Text("LOD %.3f  anisotropy %.2f", f.lod, f.anisotropy);
    ImGui::EndTooltip();
}

void overlays(Viewer& v)
{
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    const ImGuiIO& io = ImGui::GetIO();
    if (v.images.has_b) { // the divider, dragged with the left button when the UI does not want the mouse
        float x = v.state.divider * float(v.scene_width);
        if (!io.WantCaptureMouse && ImGui::IsMouseDragging(ImGuiMouseButton_Left) && std::abs(io.MouseClickedPos[0].x - x) < 8.0f)
            v.state.divider = std::clamp(io.MousePos.x / float(std::max(1, v.scene_width)), 0.0f, 1.0f);
        x = v.state.divider * float(v.scene_width);
        draw->AddLine(ImVec2(x, 0.0f), ImVec2(x, float(v.scene_height)), IM_COL32(255, 255, 255, 200), 1.0f);
    }
    if (v.controls.loupe) {
        if (!io.WantCaptureMouse && v.controls.cursor.x < 0)
            v.controls.loupe_center = {int(io.MousePos.x), int(io.MousePos.y)};
        const glm::ivec2 c = v.controls.loupe_center;
        const float r = float(v.controls.loupe_radius);
        draw->AddRect(ImVec2(float(c.x) - r, float(c.y) - r), ImVec2(float(c.x) + r, float(c.y) + r),
                      IM_COL32(255, 255, 255, 220));
    }
    if (v.controls.footprint) {
        glm::ivec2 pixel = v.controls.cursor;
        if (pixel.x < 0 && !io.WantCaptureMouse) {
            pixel = {int(io.MousePos.x), int(io.MousePos.y)};
            if (v.controls.loupe) // under the loupe: the magnified pixel
                pixel = v.controls.loupe_center +
                        glm::ivec2(glm::floor(glm::vec2(pixel - v.controls.loupe_center) / float(v.controls.loupe_zoom) + 0.5f));
        }
        const bool in_b = v.images.has_b && pixel.x >= int(std::lround(v.state.divider * float(v.scene_width)));
        if (pixel.x >= 0)
            draw_footprint(v, in_b ? v.images.b : v.images.a, pixel); // the filter of the half under it
    }
}

} // namespace

namespace {

// The texture: its name or path, its size, its frame (the dynamic texture), and the last problem.
bool texture_widgets(Viewer& v, ViewState& next)
{
    bool changed = false;
    // The field is filled with the loaded texture whenever that changes (load, a drop, a script).
    char* texture = v.controls.texture_field.data();
    if (v.controls.texture_shown != v.state.texture.name_or_path) {
        std::snprintf(texture, v.controls.texture_field.size(), "%s", v.state.texture.name_or_path.c_str());
        v.controls.texture_shown = v.state.texture.name_or_path;
    }
    ImGui::InputText("texture", texture, v.controls.texture_field.size());
    ImGui::SliderInt("texture size", &next.texture.procedural_size, 1, 4096, "%d", ImGuiSliderFlags_Logarithmic);
    if (ImGui::Button("load") || next.texture.procedural_size != v.state.texture.procedural_size) {
        next.texture.name_or_path = texture;
        changed = true;
    }
    ImGui::SameLine();
    ImGui::TextDisabled("(or drop an image file on the window)");
    if (is_dynamic_texture(v.state.texture)) { // its frame; with --build gpu it animates, rebuilt on the device
        if (rebuilt_on_device(v.state.texture))
            ImGui::Checkbox("animate the texture (T)", &v.controls.texture_animate);
        int frame = next.texture.texture_frame;
        if (ImGui::InputInt("texture frame", &frame) && frame != next.texture.texture_frame) {
            next.texture.texture_frame = std::clamp(frame, 0, max_texture_frame);
            v.controls.texture_animate = false; // a frame chosen is a frame to look at
            changed = true;
        }
    }
    if (!v.controls.message.empty())
        ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", v.controls.message.c_str());
    return changed;
}

// How the scene is rendered and shown: stage, derivatives, debug view.
bool render_widgets(Viewer& v, ViewState& next)
{
    bool changed = false;
    changed |= enum_combo("stage", next.render.stage, 0, 1, stage_name);
    changed |= enum_combo("derivatives", next.render.gradients, HARNESS_GRADIENTS_FINE, HARNESS_GRADIENTS_CONE,
                          gradients_name);
    const char* views[] = {"color", "lod", "anisotropy", "fetches", "error"};
    if (ImGui::BeginCombo("view", next.view.c_str())) {
        for (const char* name : views)
            if (ImGui::Selectable(name, next.view == name)) {
                next.view = name;
                changed = true;
            }
        ImGui::EndCombo();
    }
    if (next.view == "error")
        ImGui::SliderFloat("error scale", &v.controls.error_max, 0.001f, 1.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
    return changed;
}

// Filter A, and B beside it: another filter or the ground truth.
bool halves_widgets(Viewer& v, ViewState& next)
{
    bool changed = false;
    if (ImGui::CollapsingHeader("filter A", ImGuiTreeNodeFlags_DefaultOpen))
        changed |= filter_widgets("a", next.a.options);
    bool compare = next.b.has_value() && !v.controls.truth;
    if (ImGui::Checkbox("compare with B", &compare)) {
        v.controls.truth = false;
        if (compare)
            next.b = next.b.value_or(ViewHalf{next.a.options});
        else
            next.b.reset();
        changed = true;
    }
    ImGui::SameLine();
    if (ImGui::Checkbox("ground truth", &v.controls.truth)) {
        if (!v.controls.truth)
            next.b.reset();
        changed = true;
    }
    if (compare && next.b && ImGui::CollapsingHeader("filter B", ImGuiTreeNodeFlags_DefaultOpen))
        changed |= filter_widgets("b", next.b->options);
    return changed;
}

// The camera, the loupe and the footprint overlay.
bool camera_widgets(Viewer& v, ViewState& next)
{
    bool changed = false;
    if (ImGui::CollapsingHeader("camera", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::Checkbox("orbit (else fly)", &v.controls.orbit);
        ImGui::SameLine();
        if (ImGui::Button("reset")) {
            v.controls.camera_set = false;
            next.frame = 0;
            changed = true;
            scene_changed(v);
        }
        ImGui::Checkbox("animate along the camera path", &v.controls.animate);
        ImGui::TextDisabled("WASD/QE fly, drag: turn (orbit), wheel: forward");
        ImGui::Checkbox("loupe", &v.controls.loupe);
        ImGui::SameLine();
        ImGui::SliderInt("zoom", &v.controls.loupe_zoom, 2, 32);
        ImGui::Checkbox("footprint under the cursor", &v.controls.footprint);
    }
    return changed;
}

void screenshot_widgets(Viewer& v)
{
    char* shot = v.controls.screenshot_field.data();
    ImGui::InputText("##shot", shot, v.controls.screenshot_field.size());
    ImGui::SameLine();
    if (ImGui::Button("screenshot")) {
        v.controls.pending_screenshot = shot; // taken between frames, not inside this one
    }
}

} // namespace

void build_ui(Viewer& v)
{
    hud(v);
    overlays(v);
    ViewState next = v.state;
    bool changed = false;
    ImGui::SetNextWindowPos(ImVec2(10.0f, 10.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(330.0f, 0.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    if (ImGui::Begin("texfilter")) {
        changed |= enum_combo("scene", next.scene, 0, int(SceneKind::mesh), scene_name);
        changed |= texture_widgets(v, next);
        changed |= render_widgets(v, next);
        changed |= halves_widgets(v, next);
        changed |= camera_widgets(v, next);
        screenshot_widgets(v);
    }
    ImGui::End();
    if (changed) {
        const std::string problem = problem_of([&] { apply_state(v, next); });
        if (!problem.empty())
            v.controls.message = problem;
    }
}

} // namespace tf
