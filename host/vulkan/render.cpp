// gpu_render: the scene through the harness shaders, in three kinds (vulkan/render_pipeline.h) that share
// the pass and differ in the pipeline and in where the frame lands: the colour target (fragment, mesh) or
// a pixel buffer (compute).
#include "vulkan/render.h"
#include "harness/config.h"
#include "texture/error.h"
#include "vulkan/frame.h"
#include "vulkan/mesh.h"
#include "vulkan/readback.h"
#include <cstring>
#include <vector>

namespace tf {

namespace {

RenderKind render_kind(const SamplerOptions& options, const RenderOptions& render)
{
    if (render.stage == Stage::compute)
        return RenderKind::compute;
    // Ground truth supersamples by ray casting: the mesh through its ray-cast twin.
    return render.rasterize && options.filter != Filter::ground_truth ? RenderKind::mesh : RenderKind::fragment;
}

} // namespace

FilterVariant render_variant(const SamplerOptions& options, const RenderOptions& render, int scene_kind)
{
    FilterVariant variant = filter_variant(options);
    variant.scene = scene_kind;
    variant.view = int(render.view); // shader_interface.h checks the values
    variant.gradients = int(render.gradients);
    variant.lookups = render.lookups;
    variant.minimal = render.minimal;
    return variant;
}

std::unique_ptr<GpuRenderer> create_renderer(const VulkanContext& context, const GpuTexture& texture,
                                             const SceneParams& scene, const SamplerOptions& options,
                                             const RenderOptions& render, RenderPipelineCache* cache)
{
    check_view(options.filter, render.view);
    auto renderer = std::make_unique<GpuRenderer>();
    GpuRenderer& r = *renderer;
    Cleanup& cleanup = r.cleanup;
    r.context = &context;
    r.kind = render_kind(options, render);
    check_render_kind(context, r.kind);
    r.width = uint32_t(scene.kind_size.y);
    r.height = uint32_t(scene.kind_size.z);
    r.background = {{scene.background.r, scene.background.g, scene.background.b, scene.background.a}};
    r.push = make_push_constants(options, 0, texture.sat_offset, texture.sat_scale);

    r.uniforms = create_host_buffer(context, sizeof(SceneParams), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    cleanup.add([&context, &r] { destroy_buffer(context, r.uniforms); });
    std::memcpy(r.uniforms.mapped, &scene, sizeof(SceneParams));
    std::vector<PassBuffer> buffers = {
        {HARNESS_BINDING_SCENE, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, r.uniforms.buffer, sizeof(SceneParams)}};

    VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    VkShaderStageFlags push_stages = VK_SHADER_STAGE_FRAGMENT_BIT;
    if (r.kind == RenderKind::compute) {
        stages = push_stages = VK_SHADER_STAGE_COMPUTE_BIT;
        const VkDeviceSize bytes = VkDeviceSize(r.width) * r.height * sizeof(glm::vec4);
        r.pixels = create_device_buffer(context, bytes,
                                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        cleanup.add([&context, &r] { destroy_buffer(context, r.pixels); });
        r.pixels_readback = create_host_buffer(context, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
        cleanup.add([&context, &r] { destroy_buffer(context, r.pixels_readback); });
        buffers.push_back({HARNESS_BINDING_RESULTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, r.pixels.buffer});
    } else {
        r.targets = create_render_targets(context, r.width, r.height, r.kind == RenderKind::mesh, cleanup);
    }
    if (r.kind == RenderKind::mesh) {
        r.vertex_count = mesh_vertex_count(scene);
        r.vertices = create_mesh_vertices(context, scene, cleanup);
    }
    r.pass = create_pass(context, texture, options, stages, push_stages, buffers, cleanup);
    r.scene_kind = scene.kind_size.x;
    const FilterVariant variant = render_variant(options, render, r.scene_kind);
    r.pipeline = cache ? cached_render_pipeline(context, *cache, r.kind, r.pass.pipeline_layout, variant, r.width,
                                                r.height, texture.format)
                       : create_render_pipeline(context, r.kind, r.pass.pipeline_layout, variant, r.width, r.height,
                                                cleanup, texture.format);
    return renderer;
}

Image render_frame(GpuRenderer& r, const SceneParams& scene)
{
    if (uint32_t(scene.kind_size.y) != r.width || uint32_t(scene.kind_size.z) != r.height)
        throw Error("render_frame: the scene's size changed since the renderer was made");
    if (scene.kind_size.x != r.scene_kind)
        throw Error("render_frame: the scene's kind changed since the renderer was made (its pipeline casts one kind)");
    std::memcpy(r.uniforms.mapped, &scene, sizeof(SceneParams)); // no frame in flight: submits wait
    submit_and_wait(*r.context, [&](VkCommandBuffer cb) {
        record_frame(r, cb, VK_NULL_HANDLE, 0);
        record_frame_readback(r, cb);
    });
    return read_pixels(r.kind == RenderKind::compute ? r.pixels_readback : r.targets.readback, int(r.width),
                       int(r.height));
}

Image gpu_render(const VulkanContext& context, const GpuTexture& texture, const SceneParams& scene,
                 const SamplerOptions& options, const RenderOptions& render, RenderPipelineCache* cache)
{
    return render_accumulated(*create_renderer(context, texture, scene, options, render, cache), scene, options);
}

Image render_accumulated(GpuRenderer& renderer, const SceneParams& scene, const SamplerOptions& options)
{
    if (!options.stochastic || options.accumulate <= 1)
        return render_frame(renderer, scene);
    // --stochastic --accumulate N: the mean of N frames, each with its own random numbers (summed in double).
    std::vector<glm::dvec4> sum(size_t(renderer.width) * renderer.height, glm::dvec4(0.0));
    Image frame;
    for (int f = 0; f < options.accumulate; ++f) {
        renderer.push.stochastic = stochastic_push(options, options.stochastic_first + uint32_t(f));
        frame = render_frame(renderer, scene);
        for (size_t i = 0; i < sum.size(); ++i)
            sum[i] += glm::dvec4(frame.texels[i]);
    }
    for (size_t i = 0; i < sum.size(); ++i)
        frame.texels[i] = glm::vec4(sum[i] / double(options.accumulate));
    return frame;
}

} // namespace tf
