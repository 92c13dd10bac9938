#include "view/scene_images.h"
#include "reference/scene_cast.h"
#include "vulkan/device.h"
#include <algorithm>
#include <chrono>

namespace tf {

namespace {

bool half_needs_sat(const HalfImage& h) { return needs_sat(h.options.filter); }

void start_over(HalfImage& half)
{
    half.shown = nullptr;
    half.complete = false;
    half.samples_done = 0;
    half.sum.clear();
}

GpuRenderer& renderer_for(SceneImages& images, HalfImage& half, const SceneParams& scene, bool* created = nullptr)
{
    // By kind and size: a renderer's pipeline casts one scene kind (HARNESS_SPEC_SCENE).
    auto key = std::make_tuple(int(scene.kind_size.x), int(scene.kind_size.y), int(scene.kind_size.z));
    auto found = half.renderers.find(key);
    if (created)
        *created = found == half.renderers.end();
    if (found != half.renderers.end())
        return *found->second;
    if (half.renderers.size() >= 6) { // full size and the previews' sizes (1/2 .. 1/16), a window resize or two
        half.shown = nullptr;
        half.renderers.clear();
    }
    auto made = create_renderer(*images.context, bound_texture(images), scene, half.options, half.render);
    return *half.renderers.emplace(key, std::move(made)).first->second;
}

SceneParams scaled_scene(const SceneParams& scene, int scale)
{
    if (scale <= 1)
        return scene;
    // The same camera at a fraction of the pixels: the scene's rays depend on the pixel's position relative
    // to the image, so only the size changes. Even sides: derivatives come from 2x2 quads.
    SceneParams s = scene;
    s.kind_size.y = std::max(2, (scene.kind_size.y / scale) & ~1);
    s.kind_size.z = std::max(2, (scene.kind_size.z / scale) & ~1);
    return s;
}

void destroy_dynamic(SceneImages& images)
{
    if (images.dynamic)
        destroy_dynamic_texture(*images.context, *images.dynamic);
    images.dynamic.reset();
    images.dynamic_frame = -1;
}

} // namespace

bool same_options(const SamplerOptions& a, const SamplerOptions& b)
{
    return a.filter == b.filter && a.wrap == b.wrap && a.lod_bias == b.lod_bias && a.lod_min == b.lod_min &&
           a.lod_max == b.lod_max && a.aniso == b.aniso && a.band == b.band && a.probes == b.probes &&
           a.aniso_shape == b.aniso_shape && a.taps == b.taps && a.alpha == b.alpha && a.max_aniso == b.max_aniso &&
           a.boxes == b.boxes && a.pixel_filter == b.pixel_filter && a.truth_side == b.truth_side;
}

bool same_render(const RenderOptions& a, const RenderOptions& b)
{
    return a.stage == b.stage && a.gradients == b.gradients && a.rasterize == b.rasterize && a.view == b.view;
}

int samples_per_pixel(const SamplerOptions& options)
{
    return options.filter == Filter::ground_truth ? options.truth_side * options.truth_side : 1;
}

const GpuTexture& bound_texture(const SceneImages& images)
{
    return images.dynamic ? images.dynamic->build.texture : images.texture;
}

void destroy_scene_images(SceneImages& images)
{
    for (HalfImage* h : {&images.a, &images.b, &images.truth, &images.stats})
        h->renderers.clear();
    destroy_texture(*images.context, images.texture);
    destroy_dynamic(images);
    images.texture_has_sat = false;
}

void set_dynamic_texture(SceneImages& images, MipChain chain)
{
    // First: a failure keeps the old one.
    DynamicTexture made = create_dynamic_texture(*images.context, chain.levels[0].width);
    for (HalfImage* h : {&images.a, &images.b, &images.truth, &images.stats}) {
        h->renderers.clear(); // their descriptor sets name the old images
        start_over(*h);
    }
    destroy_texture(*images.context, images.texture);
    destroy_dynamic(images);
    images.dynamic = made;
    images.texture_has_sat = false;
    images.chain = std::move(chain);
}

bool set_texture_frame(SceneImages& images, int frame)
{
    if (!images.dynamic || images.dynamic_frame == frame)
        return false;
    const auto start = std::chrono::steady_clock::now();
    // Its own submission, before the halves' renders of this frame (render_frame submits on the same queue):
    // the build's last barrier makes the chain visible to their fragment and compute reads, and its first
    // orders the last frame's reads before level 0 is rewritten.
    submit_and_wait(*images.context, [&](VkCommandBuffer cb) { record_dynamic_frame(cb, *images.dynamic, frame); });
    images.dynamic_frame = frame;
    images.dynamic_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    restart(images);
    return true;
}

void set_texture(SceneImages& images, MipChain chain)
{
    const bool sat = half_needs_sat(images.a) || (images.has_b && half_needs_sat(images.b));
    // First: a failure keeps the old one.
    GpuTexture uploaded = upload_texture(*images.context, chain, sat, TextureFormat::rgba32f, images.build);
    for (HalfImage* h : {&images.a, &images.b, &images.truth, &images.stats}) {
        h->renderers.clear(); // their descriptor sets name the old images
        start_over(*h);
    }
    destroy_texture(*images.context, images.texture);
    destroy_dynamic(images);
    images.texture = uploaded;
    images.texture_has_sat = sat;
    images.chain = std::move(chain);
}

void set_half_options(SceneImages& images, HalfImage& half, const SamplerOptions& options, const RenderOptions& render)
{
    half.options = options;
    half.render = render;
    start_over(half);
    half.renderers.clear();
    if (needs_sat(options.filter) && !images.texture_has_sat && !images.dynamic) { // apply_state refuses sat there
        MipChain chain = images.chain;
        set_texture(images, std::move(chain));
    }
}

void restart(SceneImages& images)
{
    for (HalfImage* h : {&images.a, &images.b, &images.truth})
        start_over(*h);
}

bool step_half(SceneImages& images, HalfImage& half, const SceneParams& full_scene, int scale, int truth_samples)
{
    if (half.complete && scale <= 1)
        return false;
    const SceneParams scene = scaled_scene(full_scene, scale);
    const int total = samples_per_pixel(half.options);
    bool created = false;
    GpuRenderer& renderer = renderer_for(images, half, scene, &created);
    half.last_was_first = created;
    const auto start = std::chrono::steady_clock::now();
    if (half.options.filter != Filter::ground_truth || scale > 1) {
        // A preview of the ground truth is its first sample alone: the pattern's, noisy, cheap.
        renderer.push.truth_first = 0;
        renderer.push.truth_count = scale > 1 ? 1 : 0;
        // A preview pixel keeps a full-size pixel's footprint: the LOD seen while moving is the real one, and
        // filters whose cost grows with the footprint (EWA, sat, aniso) cost what they cost at full size.
        renderer.push.gradient_scale = 1.0f / float(scale);
        half.image = render_frame(renderer, scene);
        half.shown = renderer.kind == RenderKind::compute ? nullptr : &renderer;
        half.complete = scale <= 1 && half.options.filter != Filter::ground_truth;
        half.samples_done = 0;
        half.sum.clear();
    } else {
        const int count = std::clamp(truth_samples, 1, total - half.samples_done);
        renderer.push.truth_first = half.samples_done;
        renderer.push.truth_count = count;
        Image chunk = render_frame(renderer, scene);
        if (half.sum.size() != chunk.texels.size())
            half.sum.assign(chunk.texels.size(), glm::dvec4(0.0));
        for (size_t i = 0; i < chunk.texels.size(); ++i)
            half.sum[i] += glm::dvec4(chunk.texels[i]) * double(count);
        half.samples_done += count;
        half.image = chunk;
        half.shown = nullptr; // the mean of several renders lives on the host only
        for (size_t i = 0; i < chunk.texels.size(); ++i)
            half.image.texels[i] = glm::vec4(half.sum[i] / double(half.samples_done));
        half.complete = half.samples_done >= total;
    }
    half.last_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return true;
}

bool warm_preview(SceneImages& images, HalfImage& half, const SceneParams& full_scene, int scale)
{
    if (scale <= 1)
        return false;
    const SceneParams scene = scaled_scene(full_scene, scale);
    bool created = false;
    GpuRenderer& renderer = renderer_for(images, half, scene, &created);
    if (created) {
        renderer.push.truth_first = 0;
        renderer.push.truth_count = 1; // a ground truth's preview is its first sample
        renderer.push.gradient_scale = 1.0f / float(scale);
        render_frame(renderer, scene);
    }
    return created;
}

double fetches_per_pixel(SceneImages& images, const HalfImage& half, const SceneParams& full_scene)
{
    const Filter f = half.options.filter;
    if (f == Filter::ground_truth || f == Filter::none)
        return -1.0;
    RenderOptions render = half.render;
    render.view = DebugView::data;
    HalfImage& stats = images.stats; // its renderers kept while the options stay: a pipeline takes ~1 s to make
    if (!same_options(stats.options, half.options) || !same_render(stats.render, render))
        stats.renderers.clear();
    stats.options = half.options;
    stats.render = render;
    const SceneParams scene = scaled_scene(full_scene, 4);
    GpuRenderer& renderer = renderer_for(images, stats, scene);
    renderer.push.gradient_scale = 0.25f; // each pixel's footprint a full-size pixel's: its fetches are theirs
    const Image data = render_frame(renderer, scene);
    double sum = 0.0;
    int covered = 0;
    for (int y = 0; y < data.height; ++y)
        for (int x = 0; x < data.width; ++x)
            if (reference_hit(scene, x + 0.5, y + 0.5).hit) {
                sum += data.at(x, y).b;
                ++covered;
            }
    return covered ? sum / covered : 0.0;
}

} // namespace tf
