#pragma once
// What the viewer shows, rendered: filter A's and B's images of the current scene and the ground truth
// accumulating behind the error view, through the same renderer as `texfilter render` (vulkan/render.h:
// create_renderer, render_frame). A half renders at a fraction of the size while the camera moves (a preview,
// so the UI stays interactive on a CPU rasterizer) and at full size when it rests. A half whose filter is
// ground-truth, and the truth itself, accumulate their samples a chunk a frame, in the sample pattern of
// `--filter ground-truth`, so that the finished image is that render's.
//
// The dynamic texture with --build gpu (`--texture dynamic`): a DynamicTexture the halves' renderers bind,
// regenerated and rebuilt on the device for each new texture frame (set_texture_frame) in a submission before
// the halves render that frame; no summed-area table (sat filters need a static texture).
#include "scene/scene.h"
#include "texture/mip.h"
#include "vulkan/render.h"
#include "vulkan/gpu_build.h"
#include "vulkan/textures.h"
#include <map>
#include <memory>
#include <optional>
#include <tuple>

namespace tf {

struct HalfImage {
    SamplerOptions options;
    RenderOptions render;
    std::map<std::tuple<int, int, int>, std::unique_ptr<GpuRenderer>> renderers; // by kind and size: full, previews
    Image image;             // what the half shows now
    bool complete = false;   // full size, every ground-truth sample in
    int samples_done = 0;    // ground truth: samples accumulated into `sum`
    std::vector<glm::dvec4> sum;
    double last_ms = 0;      // the last render's wall time
    bool last_was_first = false; // ... and it was its renderer's first: on lavapipe that one also compiles (JIT)
    // The renderer whose colour target (RGBA32F, TRANSFER_SRC layout) holds `image` exactly, so that the
    // window can blit it; null for the compute stage (a buffer) and an accumulated ground truth.
    const GpuRenderer* shown = nullptr;
};

struct SceneImages {
    const VulkanContext* context = nullptr;
    MipChain chain;      // the host's chain (the CPU side: the truth's texels, the loupe)
    TextureBuild build = TextureBuild::cpu; // --build: gpu uploads level 0 and the device builds the rest
    GpuTexture texture;  // a static texture (none while `dynamic` is)
    std::optional<DynamicTexture> dynamic; // --texture dynamic --build gpu: level 0 made and built on the device
    int dynamic_frame = -1; // the frame `dynamic` holds; -1: none yet
    double dynamic_ms = 0;  // its last rebuild's wall time (submission and wait)
    bool texture_has_sat = false;
    HalfImage a, b, truth;
    HalfImage stats; // fetches_per_pixel's renders
    bool has_b = false, wants_truth = false;
};

void destroy_scene_images(SceneImages& images);
// Replaces the texture (uploads with a summed-area table when a half needs one); the halves start over.
void set_texture(SceneImages& images, MipChain chain);
// Replaces the texture by a DynamicTexture of side `chain`'s (the host's frame: sizes, the footprint); its
// frame is built by the first set_texture_frame. The halves start over.
void set_dynamic_texture(SceneImages& images, MipChain chain);
// The dynamic texture at `frame`: when it holds another, level 0 is regenerated and the chain rebuilt on the
// device (one submission, waited for) and every half starts over. Returns true when it rebuilt; false
// without a dynamic texture.
bool set_texture_frame(SceneImages& images, int frame);
// What the halves' renderers bind: the dynamic texture's, or the static one.
const GpuTexture& bound_texture(const SceneImages& images);

// New filter options for a half: its renderers go, it starts over.
void set_half_options(SceneImages& images, HalfImage& half, const SamplerOptions& options, const RenderOptions& render);
// The scene changed (camera, frame, size): every half starts over, renderers kept.
void restart(SceneImages& images);

// One step of `half` towards complete, at `scale` (1: full size, k: width/k x height/k, even sides) for
// `scene` (full size). A ground-truth half adds up to `truth_samples` samples a step. Returns true when the
// half's image changed.
bool step_half(SceneImages& images, HalfImage& half, const SceneParams& scene, int scale, int truth_samples);

int samples_per_pixel(const SamplerOptions& options); // ground truth: side^2; others 1

// Field by field (the ground truth's sample range, the viewer's progress, left out): whether a half must start
// over with new renderers.
bool same_options(const SamplerOptions& a, const SamplerOptions& b);
bool same_render(const RenderOptions& a, const RenderOptions& b);

// Makes (and draws once, discarding the frame) `half`'s renderer at `scale`, if it has none: a first draw
// compiles the shader on lavapipe (a second or more), which then happens at rest rather than at the first
// move. Returns true when it did.
bool warm_preview(SceneImages& images, HalfImage& half, const SceneParams& scene, int scale);

// `half`'s texel fetches and hardware lookups per covered pixel (the HUD's figure): its `data` view (B = the
// pixel's count) rendered at 1/4 of the size with full-size footprints (a sample of the full frame's pixels),
// averaged over the pixels the scene's surface covers. -1 for the
// ground truth and none.
double fetches_per_pixel(SceneImages& images, const HalfImage& half, const SceneParams& scene);

} // namespace tf
