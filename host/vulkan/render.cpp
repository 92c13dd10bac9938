#include "vulkan/render.h"
#include "core/analytic_texture.h"
#include "harness/config.h"
#include "texture/error.h"
#include "vulkan/cleanup.h"
#include "vulkan/memory.h"
#include "vulkan/pipelines.h"
#include <cstddef>
#include <cstring>
#include <glm/vec4.hpp>
#include <map>
#include <vector>

namespace tf {

RenderTargets create_render_targets(const VulkanContext& context, uint32_t width, uint32_t height, bool with_depth,
                                    Cleanup& cleanup)
{
    RenderTargets t;
    t.width = width;
    t.height = height;
    GpuImage color = t.color = create_image(context, render_color_format, width, height, 1,
                                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                            VK_IMAGE_ASPECT_COLOR_BIT);
    cleanup.add([&context, color]() mutable { destroy_image(context, color); });
    if (with_depth) {
        GpuImage depth = t.depth = create_image(context, render_depth_format, width, height, 1,
                                                VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT);
        cleanup.add([&context, depth]() mutable { destroy_image(context, depth); });
    }
    Buffer readback = t.readback = create_host_buffer(context, VkDeviceSize(width) * height * sizeof(glm::vec4),
                                                      VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    cleanup.add([&context, readback]() mutable { destroy_buffer(context, readback); });
    return t;
}

// The color target while the pass draws into it.
constexpr BarrierScope color_attachment{VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                                        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};

void record_targets_for_drawing(VkCommandBuffer cb, const RenderTargets& targets)
{
    // UNDEFINED: the previous frame's content is not needed (the whole target is redrawn or cleared).
    image_barrier(cb, {.image = targets.color.image,
                       .from = {VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                                VK_ACCESS_TRANSFER_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED},
                       .to = color_attachment});
    if (targets.depth.image)
        image_barrier(cb, {.image = targets.depth.image,
                           .from = {VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                                    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED},
                           .to = {VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT,
                                  VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
                                  VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL},
                           .aspect = VK_IMAGE_ASPECT_DEPTH_BIT});
}

void record_begin_rendering(VkCommandBuffer cb, const RenderTargets& targets, const VkClearColorValue* background)
{
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = targets.color.view;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = background ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    if (background)
        color.clearValue.color = *background;
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth.imageView = targets.depth.view;
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depth.clearValue.depthStencil = {1.0f, 0};
    VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
    info.renderArea = {{0, 0}, {targets.width, targets.height}};
    info.layerCount = 1;
    info.colorAttachmentCount = 1;
    info.pColorAttachments = &color;
    info.pDepthAttachment = targets.depth.view ? &depth : nullptr;
    vkCmdBeginRendering(cb, &info);
}

void record_targets_for_readback(VkCommandBuffer cb, const RenderTargets& targets)
{
    image_barrier(cb, {.image = targets.color.image, .from = color_attachment, .to = scope::transfer_src});
}

void record_host_read(VkCommandBuffer cb, VkPipelineStageFlags stage, VkAccessFlags access)
{
    memory_barrier(cb, {stage, access},
                       {VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT});
}

void record_target_readback(VkCommandBuffer cb, const RenderTargets& targets)
{
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {targets.width, targets.height, 1};
    vkCmdCopyImageToBuffer(cb, targets.color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, targets.readback.buffer, 1,
                           &copy);
    record_host_read(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
}

std::vector<unsigned char> read_image_level(const VulkanContext& context, VkImage image, uint32_t level,
                                            uint32_t width, uint32_t height, size_t texel_bytes, VkImageLayout layout)
{
    const size_t bytes = size_t(width) * size_t(height) * texel_bytes;
    Buffer buffer = create_host_buffer(context, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    Cleanup cleanup;
    cleanup.add([&] { destroy_buffer(context, buffer); });
    const VkAccessFlags writes = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    const VkPipelineStageFlags stages = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
    submit_and_wait(context, [&](VkCommandBuffer cb) {
        image_barrier(cb, {.image = image, .from = {stages, writes, layout}, .to = scope::transfer_src,
                           .base_level = level});
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
        copy.imageExtent = {width, height, 1};
        vkCmdCopyImageToBuffer(cb, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.buffer, 1, &copy);
        image_barrier(cb, {.image = image, .from = scope::transfer_src,
                           .to = {stages, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT, layout},
                           .base_level = level});
        record_host_read(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    });
    std::vector<unsigned char> out(bytes);
    std::memcpy(out.data(), buffer.mapped, bytes);
    return out;
}

Image read_pixels(const Buffer& buffer, int width, int height)
{
    Image out = make_image(width, height);
    std::memcpy(out.texels.data(), buffer.mapped, out.texels.size() * sizeof(glm::vec4));
    return out;
}

namespace {

VkPipelineLayout create_pipeline_layout(const VulkanContext& context, VkDescriptorSetLayout set_layout,
                                        VkShaderStageFlags push_stages, Cleanup& cleanup)
{
    VkPushConstantRange range{push_stages, 0, sizeof(PushConstants)};
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = 1;
    info.pSetLayouts = &set_layout;
    info.pushConstantRangeCount = 1;
    info.pPushConstantRanges = &range;
    VkDevice device = context.device;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    TF_VK(vkCreatePipelineLayout(device, &info, nullptr, &layout));
    cleanup.add([=] { vkDestroyPipelineLayout(device, layout, nullptr); });
    return layout;
}

// A pool sized for exactly one set of `bindings`, and that set.
VkDescriptorSet allocate_set(const VulkanContext& context, VkDescriptorSetLayout layout,
                             const std::vector<VkDescriptorSetLayoutBinding>& bindings, VkDescriptorPool& pool,
                             Cleanup& cleanup)
{
    std::map<VkDescriptorType, uint32_t> counts;
    for (const VkDescriptorSetLayoutBinding& b : bindings)
        counts[b.descriptorType] += b.descriptorCount;
    std::vector<VkDescriptorPoolSize> sizes;
    for (auto [type, count] : counts)
        sizes.push_back({type, count});
    return allocate_set(context, layout, sizes, pool, cleanup);
}

VkWriteDescriptorSet write_descriptor(VkDescriptorSet set, uint32_t binding, VkDescriptorType type)
{
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = type;
    return w;
}

} // namespace

Pass create_pass(const VulkanContext& context, const GpuTexture& texture, const SamplerOptions& options,
                 VkShaderStageFlags stages, VkShaderStageFlags push_stages, const std::vector<PassBuffer>& buffers,
                 Cleanup& cleanup)
{
    const PassSamplers samplers = create_pass_samplers(context, texture, options, cleanup);
    const uint32_t texture_bindings[3] = {HARNESS_BINDING_TEXTURE, HARNESS_BINDING_SAT_LOW, HARNESS_BINDING_SAT_HIGH};
    std::vector<PassImages> images;
    for (int i = 0; i < 3; ++i)
        images.push_back({texture_bindings[i], VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, {samplers.infos[i]}});
    Pass pass = create_pass_with_images(context, images, stages, push_stages, buffers, cleanup);
    pass.samplers = samplers;
    return pass;
}

Pass create_pass_with_images(const VulkanContext& context, const std::vector<PassImages>& images,
                             VkShaderStageFlags stages, VkShaderStageFlags push_stages,
                             const std::vector<PassBuffer>& buffers, Cleanup& cleanup)
{
    Pass pass;
    pass.push_stages = push_stages;
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (const PassImages& i : images)
        bindings.push_back({i.binding, i.type, uint32_t(i.infos.size()), stages, nullptr});
    for (const PassBuffer& b : buffers)
        bindings.push_back({b.binding, b.type, 1, stages, nullptr});
    pass.set_layout = create_set_layout(context, bindings, cleanup);
    pass.pipeline_layout = create_pipeline_layout(context, pass.set_layout, push_stages, cleanup);
    pass.set = allocate_set(context, pass.set_layout, bindings, pass.pool, cleanup);

    std::vector<VkDescriptorBufferInfo> buffer_infos;
    for (const PassBuffer& b : buffers)
        buffer_infos.push_back({b.buffer, 0, b.range});
    std::vector<VkWriteDescriptorSet> writes;
    for (const PassImages& i : images) {
        writes.push_back(write_descriptor(pass.set, i.binding, i.type));
        writes.back().descriptorCount = uint32_t(i.infos.size());
        writes.back().pImageInfo = i.infos.data();
    }
    for (size_t i = 0; i < buffers.size(); ++i) {
        writes.push_back(write_descriptor(pass.set, buffers[i].binding, buffers[i].type));
        writes.back().pBufferInfo = &buffer_infos[i];
    }
    vkUpdateDescriptorSets(context.device, uint32_t(writes.size()), writes.data(), 0, nullptr);
    return pass;
}

void bind_pass(VkCommandBuffer command_buffer, VkPipelineBindPoint bind_point, VkPipeline pipeline, const Pass& pass,
               const PushConstants& push)
{
    vkCmdBindPipeline(command_buffer, bind_point, pipeline);
    vkCmdBindDescriptorSets(command_buffer, bind_point, pass.pipeline_layout, 0, 1, &pass.set, 0, nullptr);
    vkCmdPushConstants(command_buffer, pass.pipeline_layout, pass.push_stages, 0, sizeof(push), &push);
}

PushConstants make_push_constants(const SamplerOptions& options, uint32_t count, glm::vec4 sat_offset,
                                  glm::vec4 sat_scale)
{
    // Ground truth: the range resolved and checked here (a range past the grid is refused, naming it); the
    // shader clamps it again, so whatever reaches it stays bounded.
    const bool ground_truth = options.filter == Filter::ground_truth;
    const TruthRange truth = ground_truth ? truth_range(options) : TruthRange{};
    // --truth analytic: the function the shader integrates (analytic_texture.glsl); the texels otherwise.
    check_analytic_truth(options);
    const bool analytic = ground_truth && options.truth == Truth::analytic;
    PushConstants push{int32_t(options.wrap), options.lod_bias, options.lod_min, options.lod_max,
                       count, options.band, options.probes, int32_t(options.aniso_shape), int32_t(options.taps),
                       options.alpha, options.max_aniso, options.boxes, 0,
                       options.truth_side, int32_t(options.pixel_filter), 0,
                       {sat_offset.x, sat_offset.y, sat_offset.z, sat_offset.w},
                       {sat_scale.x, sat_scale.y, sat_scale.z, sat_scale.w},
                       truth.first, truth.count, 1.0f, 0};
    push.truth_analytic = int32_t(analytic ? options.analytic : AnalyticKind::none);
    check_stochastic(options);
    push.stochastic = stochastic_push(options, options.stochastic_first); // gpu_render steps it a frame at a time
    return push;
}

uint32_t mesh_vertex_count(const SceneParams& scene) { return uint32_t(3 * scene.kind_size.w); }

Buffer create_mesh_vertices(const VulkanContext& context, const SceneParams& scene, Cleanup& cleanup)
{
    const uint32_t count = mesh_vertex_count(scene);
    Buffer vertices = create_host_buffer(context, count * sizeof(MeshVertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    cleanup.add([&context, vertices]() mutable { destroy_buffer(context, vertices); });
    MeshVertex* v = static_cast<MeshVertex*>(vertices.mapped);
    for (uint32_t i = 0; i < count; ++i)
        v[i] = {{scene.positions[i].x, scene.positions[i].y, scene.positions[i].z}, {scene.uvs[i].x, scene.uvs[i].y}};
    return vertices;
}

void check_render_kind(const VulkanContext& context, RenderKind kind)
{
    if (kind != RenderKind::compute)
        return;
    if (!context.info.quad_ops_compute)
        throw Error(context.info.name + " has no subgroup quad operations in compute shaders: use --stage fragment");
    if (context.info.subgroup_size % 4 != 0 || (HARNESS_RENDER_TILE * HARNESS_RENDER_TILE) % context.info.subgroup_size != 0)
        throw Error("the compute render lays 2x2 quads over subgroups of " +
                    std::to_string(context.info.subgroup_size) + " invocations, which it cannot do");
}

VkPipeline create_render_pipeline(const VulkanContext& context, RenderKind kind, VkPipelineLayout layout,
                                  FilterVariant filter, uint32_t width, uint32_t height, Cleanup& cleanup,
                                  TextureFormat format)
{
    if (filter.minimal != MinimalPass::none && kind != RenderKind::compute)
        throw Error("the bench's minimal pass is a compute shader: it needs --stage compute");
    if (kind == RenderKind::compute) {
        const HarnessShader shader = filter.minimal == MinimalPass::no_texture  ? HarnessShader::minimal_comp
                                     : filter.minimal == MinimalPass::trilinear ? HarnessShader::minimal_trilinear_comp
                                                                                : HarnessShader::render_comp;
        return create_compute_pipeline(context, harness_shader(shader, format), layout, filter, cleanup);
    }

    GraphicsPipelineDesc desc;
    desc.color_format = render_color_format;
    desc.width = width;
    desc.height = height;
    if (kind == RenderKind::fragment) {
        desc.vertex = harness_shader(HarnessShader::render_vert, format);
        desc.fragment = harness_shader(HarnessShader::render_frag, format);
        return create_graphics_pipeline(context, desc, layout, filter, cleanup);
    }
    VkVertexInputBindingDescription binding{0, sizeof(MeshVertex), VK_VERTEX_INPUT_RATE_VERTEX};
    VkVertexInputAttributeDescription attributes[2] = {
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, uint32_t(offsetof(MeshVertex, position))},
        {1, 0, VK_FORMAT_R32G32_SFLOAT, uint32_t(offsetof(MeshVertex, uv))}};
    VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertex_input.vertexBindingDescriptionCount = 1;
    vertex_input.pVertexBindingDescriptions = &binding;
    vertex_input.vertexAttributeDescriptionCount = 2;
    vertex_input.pVertexAttributeDescriptions = attributes;
    desc.vertex = harness_shader(HarnessShader::mesh_vert, format);
    desc.fragment = harness_shader(HarnessShader::mesh_frag, format);
    desc.vertex_input = &vertex_input;
    desc.depth_format = render_depth_format;
    return create_graphics_pipeline(context, desc, layout, filter, cleanup);
}

VkPipeline cached_render_pipeline(const VulkanContext& context, RenderPipelineCache& cache, RenderKind kind,
                                  VkPipelineLayout layout, FilterVariant filter, uint32_t width, uint32_t height,
                                  TextureFormat format)
{
    const bool integer = format_info(format).integer;
    const bool sized = kind != RenderKind::compute; // graphics pipelines fix their viewport
    for (const RenderPipelineCache::Entry& e : cache.entries)
        if (e.kind == kind && e.filter == filter && e.integer == integer &&
            (!sized || (e.width == width && e.height == height)))
            return e.pipeline;
    const VkPipeline pipeline = create_render_pipeline(context, kind, layout, filter, width, height, cache.cleanup, format);
    cache.entries.push_back({kind, filter, width, height, integer, pipeline});
    return pipeline;
}

namespace {

void record_dispatch(const GpuRenderer& r, VkCommandBuffer cb, VkQueryPool timestamps, uint32_t query)
{
    bind_pass(cb, VK_PIPELINE_BIND_POINT_COMPUTE, r.pipeline, r.pass, r.push);
    // The previous frame's writes to the pixel buffer come first (write after write).
    memory_barrier(cb, {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT},
                       {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT});
    if (timestamps)
        vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timestamps, query);
    vkCmdDispatch(cb, (r.width + HARNESS_RENDER_TILE - 1) / HARNESS_RENDER_TILE, (r.height + HARNESS_RENDER_TILE - 1) / HARNESS_RENDER_TILE, 1);
    if (timestamps)
        vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps, query + 1);
}

void record_draw(const GpuRenderer& r, VkCommandBuffer cb, VkQueryPool timestamps, uint32_t query)
{
    const bool mesh = r.kind == RenderKind::mesh;
    record_targets_for_drawing(cb, r.targets);
    if (timestamps)
        vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timestamps, query);
    // The full-screen triangle covers every pixel; the mesh leaves the background where it has none.
    record_begin_rendering(cb, r.targets, mesh ? &r.background : nullptr);
    bind_pass(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, r.pipeline, r.pass, r.push);
    if (mesh) {
        VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cb, 0, 1, &r.vertices.buffer, &offset);
    }
    vkCmdDraw(cb, r.vertex_count, 1, 0, 0);
    vkCmdEndRendering(cb);
    if (timestamps)
        vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps, query + 1);
    record_targets_for_readback(cb, r.targets);
}

} // namespace

void record_frame(const GpuRenderer& r, VkCommandBuffer cb, VkQueryPool timestamps, uint32_t query)
{
    if (r.kind == RenderKind::compute)
        record_dispatch(r, cb, timestamps, query);
    else
        record_draw(r, cb, timestamps, query);
}

void record_frame_readback(const GpuRenderer& r, VkCommandBuffer cb)
{
    if (r.kind == RenderKind::compute) {
        memory_barrier(cb, {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT},
                           {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT});
        const VkBufferCopy copy{0, 0, r.pixels.size};
        vkCmdCopyBuffer(cb, r.pixels.buffer, r.pixels_readback.buffer, 1, &copy);
        record_host_read(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    } else
        record_target_readback(cb, r.targets);
}

// gpu_render: the scene through the harness shaders, in three kinds (RenderKind) that share
// the pass and differ in the pipeline and in where the frame lands: the colour target (fragment, mesh) or
// a pixel buffer (compute).
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
