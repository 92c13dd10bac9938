// gpu_render: the scene through the harness shaders, in three ways that share everything but the pipeline:
// a full-screen triangle whose fragment shader ray-casts (fragment), a compute shader whose invocations form
// 2x2 quads (compute), and the triangles rasterized from a vertex buffer (mesh).
#include "harness/config.h"
#include "texture/error.h"
#include "vulkan/render.h"
#include <algorithm>
#include <chrono>
#include <cstring>

#include "mesh_frag.h"
#include "mesh_vert.h"
#include "render_comp.h"
#include "render_frag.h"
#include "render_vert.h"

namespace tf {

namespace {

const VkFormat color_format = VK_FORMAT_R32G32B32A32_SFLOAT;
const VkFormat depth_format = VK_FORMAT_D32_SFLOAT;

int gradients_id(Gradients gradients)
{
    return gradients == Gradients::coarse ? HARNESS_GRADIENTS_COARSE
           : gradients == Gradients::ray  ? HARNESS_GRADIENTS_RAY
                                          : HARNESS_GRADIENTS_FINE;
}

// A device-local 2D image with a view, destroyed by `cleanup`.
VkImageView create_attachment(const VulkanContext& context, VkFormat format, VkImageUsageFlags usage,
                              VkImageAspectFlags aspect, uint32_t width, uint32_t height, VkImage& image,
                              Cleanup& cleanup)
{
    VkDevice device = context.device;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {width, height, 1};
    info.mipLevels = info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    TF_VK(vkCreateImage(device, &info, nullptr, &image));
    VkImage created = image;
    cleanup.add([=] { vkDestroyImage(device, created, nullptr); });
    VkMemoryRequirements requirements{};
    vkGetImageMemoryRequirements(device, image, &requirements);
    VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    allocate.allocationSize = requirements.size;
    allocate.memoryTypeIndex = find_memory_type(context, requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VkDeviceMemory memory = VK_NULL_HANDLE;
    TF_VK(vkAllocateMemory(device, &allocate, nullptr, &memory));
    cleanup.add([=] { vkFreeMemory(device, memory, nullptr); });
    TF_VK(vkBindImageMemory(device, image, memory, 0));
    VkImageViewCreateInfo view_info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view_info.image = image;
    view_info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view_info.format = format;
    view_info.subresourceRange = {aspect, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    TF_VK(vkCreateImageView(device, &view_info, nullptr, &view));
    cleanup.add([=] { vkDestroyImageView(device, view, nullptr); });
    return view;
}

void create_pass_resources(const VulkanContext& context, const GpuTexture& texture, const SceneParams& scene,
                           const SamplerOptions& options, VkShaderStageFlags stages, VkShaderStageFlags push_stages,
                           bool pixel_buffer, PassResources& pass, Cleanup& cleanup)
{
    VkDevice device = context.device;
    pass.uniforms = create_host_buffer(context, sizeof(SceneParams), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    cleanup.add([&] { destroy_buffer(context, pass.uniforms); });
    std::memcpy(pass.uniforms.mapped, &scene, sizeof(SceneParams));
    if (pixel_buffer) {
        VkDeviceSize bytes = VkDeviceSize(scene.kind_size.y) * VkDeviceSize(scene.kind_size.z) * sizeof(glm::vec4);
        pass.pixels = create_host_buffer(context, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        cleanup.add([&] { destroy_buffer(context, pass.pixels); });
    }
    create_pass_samplers(context, texture, options, pass.samplers, cleanup);

    std::vector<VkDescriptorSetLayoutBinding> bindings = texture_bindings(stages);
    bindings.push_back({HARNESS_BINDING_SCENE, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, stages, nullptr});
    if (pixel_buffer)
        bindings.push_back({HARNESS_BINDING_RESULTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, stages, nullptr});
    pass.set_layout = create_set_layout(context, bindings);
    VkDescriptorSetLayout set_layout = pass.set_layout;
    cleanup.add([=] { vkDestroyDescriptorSetLayout(device, set_layout, nullptr); });
    pass.pipeline_layout = create_pipeline_layout(context, set_layout, push_stages);
    VkPipelineLayout pipeline_layout = pass.pipeline_layout;
    cleanup.add([=] { vkDestroyPipelineLayout(device, pipeline_layout, nullptr); });

    pass.descriptors = allocate_descriptor_set(context, set_layout);
    VkDescriptorPool pool = pass.descriptors.pool;
    cleanup.add([=] { vkDestroyDescriptorPool(device, pool, nullptr); });
    pass.uniform_info = {pass.uniforms.buffer, 0, sizeof(SceneParams)};
    pass.pixel_info = {pass.pixels.buffer, 0, VK_WHOLE_SIZE};
    std::vector<VkWriteDescriptorSet> writes;
    write_textures(writes, pass.descriptors.set, pass.samplers);
    writes.push_back(write_buffer(pass.descriptors.set, HARNESS_BINDING_SCENE, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &pass.uniform_info));
    if (pixel_buffer)
        writes.push_back(write_buffer(pass.descriptors.set, HARNESS_BINDING_RESULTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &pass.pixel_info));
    vkUpdateDescriptorSets(device, uint32_t(writes.size()), writes.data(), 0, nullptr);
}

VkMemoryBarrier host_read_barrier(VkAccessFlags source)
{
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = source;
    barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    return barrier;
}

Image copy_out(const Buffer& buffer, int width, int height)
{
    Image out = make_image(width, height);
    std::memcpy(out.texels.data(), buffer.mapped, out.texels.size() * sizeof(glm::vec4));
    return out;
}


struct MeshVertex {
    float position[3];
    float uv[2];
};

void check_compute_quads(const VulkanContext& context)
{
    if (!context.info.quad_ops_compute)
        throw Error(context.info.name + " has no subgroup quad operations in compute shaders: use --stage fragment");
    if (context.info.subgroup_size % 4 != 0 || (HARNESS_RENDER_TILE * HARNESS_RENDER_TILE) % context.info.subgroup_size != 0)
        throw Error("the compute render lays 2x2 quads over subgroups of " +
                    std::to_string(context.info.subgroup_size) + " invocations, which it cannot do");
}

// The graphics pipeline: the full-screen triangle (ray-cast scenes) or the mesh's triangles, depth-tested.
VkPipeline create_graphics_pipeline(const VulkanContext& context, const GpuRenderer& r, Filter filter, Cleanup& cleanup)
{
    VkDevice device = context.device;
    VkShaderModule vert = r.mesh ? create_shader_module(context, mesh_vert, sizeof(mesh_vert))
                                 : create_shader_module(context, render_vert, sizeof(render_vert));
    cleanup.add([=] { vkDestroyShaderModule(device, vert, nullptr); });
    VkShaderModule frag = r.mesh ? create_shader_module(context, mesh_frag, sizeof(mesh_frag))
                                 : create_shader_module(context, render_frag, sizeof(render_frag));
    cleanup.add([=] { vkDestroyShaderModule(device, frag, nullptr); });

    VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                                 {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = vert;
    stages[0].pName = "main";
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = frag;
    stages[1].pName = "main";
    FilterSpecialization specialization;
    stages[1].pSpecializationInfo = filter_specialization(filter, specialization);
    VkVertexInputBindingDescription binding{0, sizeof(MeshVertex), VK_VERTEX_INPUT_RATE_VERTEX};
    VkVertexInputAttributeDescription attributes[2] = {
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, uint32_t(offsetof(MeshVertex, position))},
        {1, 0, VK_FORMAT_R32G32_SFLOAT, uint32_t(offsetof(MeshVertex, uv))}};
    VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    if (r.mesh) {
        vertex_input.vertexBindingDescriptionCount = 1;
        vertex_input.pVertexBindingDescriptions = &binding;
        vertex_input.vertexAttributeDescriptionCount = 2;
        vertex_input.pVertexAttributeDescriptions = attributes;
    }
    VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkViewport viewport{0.0f, 0.0f, float(r.width), float(r.height), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, {r.width, r.height}};
    VkPipelineViewportStateCreateInfo viewport_state{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport_state.viewportCount = 1;
    viewport_state.pViewports = &viewport;
    viewport_state.scissorCount = 1;
    viewport_state.pScissors = &scissor;
    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = VK_CULL_MODE_NONE;
    raster.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo depth_state{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depth_state.depthTestEnable = depth_state.depthWriteEnable = r.mesh ? VK_TRUE : VK_FALSE;
    depth_state.depthCompareOp = VK_COMPARE_OP_LESS;
    VkPipelineColorBlendAttachmentState blend_attachment{};
    blend_attachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                      VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = 1;
    blend.pAttachments = &blend_attachment;
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachmentFormats = &color_format;
    rendering.depthAttachmentFormat = r.mesh ? depth_format : VK_FORMAT_UNDEFINED;
    VkGraphicsPipelineCreateInfo pipeline_info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    pipeline_info.pNext = &rendering;
    pipeline_info.stageCount = 2;
    pipeline_info.pStages = stages;
    pipeline_info.pVertexInputState = &vertex_input;
    pipeline_info.pInputAssemblyState = &assembly;
    pipeline_info.pViewportState = &viewport_state;
    pipeline_info.pRasterizationState = &raster;
    pipeline_info.pMultisampleState = &multisample;
    pipeline_info.pDepthStencilState = &depth_state;
    pipeline_info.pColorBlendState = &blend;
    pipeline_info.layout = r.pass.pipeline_layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    TF_VK(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &pipeline_info, nullptr, &pipeline));
    cleanup.add([=] { vkDestroyPipeline(device, pipeline, nullptr); });
    return pipeline;
}

// One frame: the draw (into the colour target, which ends in TRANSFER_SRC layout) or the dispatch (into
// the pixel buffer). `timestamps` (or null) bracket the work itself, not the layout changes around it.
void record_frame(const GpuRenderer& r, VkCommandBuffer cb, VkQueryPool timestamps, uint32_t query)
{
    auto stamp = [&](VkPipelineStageFlagBits stage, uint32_t index) {
        if (timestamps != VK_NULL_HANDLE)
            vkCmdWriteTimestamp(cb, stage, timestamps, index);
    };
    if (r.compute) {
        vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, r.pipeline);
        vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, r.pass.pipeline_layout, 0, 1,
                                &r.pass.descriptors.set, 0, nullptr);
        vkCmdPushConstants(cb, r.pass.pipeline_layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(r.push), &r.push);
        // The previous frame's writes to the pixel buffer come first (write after write).
        VkMemoryBarrier previous{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        previous.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
        previous.dstAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
        vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1,
                             &previous, 0, nullptr, 0, nullptr);
        stamp(VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, query);
        vkCmdDispatch(cb, (r.width + HARNESS_RENDER_TILE - 1) / HARNESS_RENDER_TILE, (r.height + HARNESS_RENDER_TILE - 1) / HARNESS_RENDER_TILE, 1);
        stamp(VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, query + 1);
        return;
    }
    // UNDEFINED: the previous frame's content is not needed (the whole target is redrawn or cleared).
    image_barrier(cb, r.target, 1, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                  VK_ACCESS_TRANSFER_READ_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                  VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                  VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT);
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = r.target_view;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    // The full-screen triangle covers every pixel; the mesh leaves the background where it has none.
    color.loadOp = r.mesh ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.clearValue.color = r.background;
    VkRenderingAttachmentInfo depth_attachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth_attachment.imageView = r.depth_view;
    depth_attachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth_attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth_attachment.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depth_attachment.clearValue.depthStencil = {1.0f, 0};
    if (r.mesh) {
        VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
        barrier.srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
        barrier.dstAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
        barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        barrier.newLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
        barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.image = r.depth;
        barrier.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
        vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT, VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT,
                             0, 0, nullptr, 0, nullptr, 1, &barrier);
    }
    VkRect2D area{{0, 0}, {r.width, r.height}};
    VkRenderingInfo rendering_info{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering_info.renderArea = area;
    rendering_info.layerCount = 1;
    rendering_info.colorAttachmentCount = 1;
    rendering_info.pColorAttachments = &color;
    rendering_info.pDepthAttachment = r.mesh ? &depth_attachment : nullptr;
    stamp(VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, query);
    vkCmdBeginRendering(cb, &rendering_info);
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, r.pipeline);
    vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, r.pass.pipeline_layout, 0, 1, &r.pass.descriptors.set,
                            0, nullptr);
    vkCmdPushConstants(cb, r.pass.pipeline_layout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(r.push), &r.push);
    if (r.mesh) {
        VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cb, 0, 1, &r.vertices.buffer, &offset);
    }
    vkCmdDraw(cb, r.vertex_count, 1, 0, 0);
    vkCmdEndRendering(cb);
    stamp(VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, query + 1);
    image_barrier(cb, r.target, 1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                  VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT,
                  VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
}

// After record_frame: the frame into host-visible memory.
void record_readback(const GpuRenderer& r, VkCommandBuffer cb)
{
    if (r.compute) {
        VkMemoryBarrier host = host_read_barrier(VK_ACCESS_SHADER_WRITE_BIT);
        vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &host, 0,
                             nullptr, 0, nullptr);
        return;
    }
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {r.width, r.height, 1};
    vkCmdCopyImageToBuffer(cb, r.target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, r.readback.buffer, 1, &copy);
    VkMemoryBarrier host = host_read_barrier(VK_ACCESS_TRANSFER_WRITE_BIT);
    vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &host, 0, nullptr, 0,
                         nullptr);
}

// One submit and wait a frame, timed on the host. A frame slower than `slow_ms` ends the warm-up and cuts
// the timed frames to three: a pathological case (lavapipe's hw-aniso on some scenes takes seconds a frame)
// must not hold the whole benchmark up.
std::vector<double> time_frames_on_host(const GpuRenderer& r, int warmup, int frames)
{
    const double slow_ms = 250.0;
    std::vector<double> ms;
    for (int f = 0; f < warmup + frames && int(ms.size()) < frames; ++f) {
        auto start = std::chrono::steady_clock::now();
        submit_and_wait(*r.context, [&](VkCommandBuffer cb) { record_frame(r, cb, VK_NULL_HANDLE, 0); });
        double elapsed = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (f >= warmup)
            ms.push_back(elapsed);
        if (elapsed > slow_ms) {
            warmup = std::min(warmup, f + 1);
            frames = std::min(frames, 3);
        }
    }
    return ms;
}

} // namespace

std::unique_ptr<GpuRenderer> create_renderer(const VulkanContext& context, const GpuTexture& texture,
                                             const SceneParams& scene, const SamplerOptions& options,
                                             const RenderOptions& render)
{
    auto r = std::make_unique<GpuRenderer>();
    GpuRenderer& out = *r;
    Cleanup& cleanup = out.cleanup;
    out.context = &context;
    out.compute = render.stage == Stage::compute;
    // Ground truth supersamples by ray casting: the mesh through its ray-cast twin.
    out.mesh = render.rasterize && options.filter != Filter::ground_truth;
    out.width = uint32_t(scene.kind_size.y);
    out.height = uint32_t(scene.kind_size.z);
    out.background = {{scene.background.r, scene.background.g, scene.background.b, scene.background.a}};
    out.push = make_push_constants(options, 0, texture.sat_offset, texture.sat_scale, gradients_id(render.gradients));

    if (out.compute) {
        check_compute_quads(context);
        create_pass_resources(context, texture, scene, options, VK_SHADER_STAGE_COMPUTE_BIT,
                              VK_SHADER_STAGE_COMPUTE_BIT, true, out.pass, cleanup);
        out.pipeline = create_compute_pipeline(context, render_comp, sizeof(render_comp),
                                               out.pass.pipeline_layout, options.filter, cleanup);
        return r;
    }
    out.target_view = create_attachment(context, color_format,
                                        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                        VK_IMAGE_ASPECT_COLOR_BIT, out.width, out.height, out.target, cleanup);
    if (out.mesh)
        out.depth_view = create_attachment(context, depth_format, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                           VK_IMAGE_ASPECT_DEPTH_BIT, out.width, out.height, out.depth, cleanup);
    out.readback = create_host_buffer(context, VkDeviceSize(out.width) * out.height * sizeof(glm::vec4),
                                      VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    cleanup.add([&context, &out] { destroy_buffer(context, out.readback); });
    if (out.mesh) {
        out.vertex_count = uint32_t(3 * scene.kind_size.w);
        out.vertices = create_host_buffer(context, out.vertex_count * sizeof(MeshVertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        cleanup.add([&context, &out] { destroy_buffer(context, out.vertices); });
        MeshVertex* v = static_cast<MeshVertex*>(out.vertices.mapped);
        for (uint32_t i = 0; i < out.vertex_count; ++i)
            v[i] = {{scene.positions[i].x, scene.positions[i].y, scene.positions[i].z}, {scene.uvs[i].x, scene.uvs[i].y}};
    }
    create_pass_resources(context, texture, scene, options, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
                          VK_SHADER_STAGE_FRAGMENT_BIT, false, out.pass, cleanup);
    out.pipeline = create_graphics_pipeline(context, out, options.filter, cleanup);
    return r;
}

Image render_frame(GpuRenderer& r, const SceneParams& scene)
{
    if (uint32_t(scene.kind_size.y) != r.width || uint32_t(scene.kind_size.z) != r.height)
        throw Error("render_frame: the scene's size changed since the renderer was made");
    std::memcpy(r.pass.uniforms.mapped, &scene, sizeof(SceneParams)); // no frame in flight: submits wait
    submit_and_wait(*r.context, [&](VkCommandBuffer cb) {
        record_frame(r, cb, VK_NULL_HANDLE, 0);
        record_readback(r, cb);
    });
    return copy_out(r.compute ? r.pass.pixels : r.readback, int(r.width), int(r.height));
}

std::vector<double> time_frames(GpuRenderer& r, int warmup, int frames, FrameTimer timer)
{
    const VulkanContext& context = *r.context;
    if (warmup < 0 || frames < 1)
        throw Error("time_frames: need at least one timed frame");
    if (timer == FrameTimer::wall_clock)
        return time_frames_on_host(r, warmup, frames);
    if (context.info.timestamp_valid_bits == 0 || context.info.timestamp_period_ns <= 0.0f)
        throw Error(context.info.name + " has no timestamps on its graphics and compute queue: use the wall-clock timer");
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = uint32_t(2 * frames);
    VkQueryPool pool = VK_NULL_HANDLE;
    TF_VK(vkCreateQueryPool(context.device, &info, nullptr, &pool));
    struct Release {
        VkDevice device;
        VkQueryPool pool;
        ~Release() { vkDestroyQueryPool(device, pool, nullptr); }
    } release{context.device, pool};

    submit_and_wait(context, [&](VkCommandBuffer cb) {
        vkCmdResetQueryPool(cb, pool, 0, info.queryCount);
        for (int f = 0; f < warmup + frames; ++f)
            record_frame(r, cb, f < warmup ? VK_NULL_HANDLE : pool, uint32_t(2 * (f - warmup)));
    });
    std::vector<uint64_t> ticks(info.queryCount);
    TF_VK(vkGetQueryPoolResults(context.device, pool, 0, info.queryCount, ticks.size() * sizeof(uint64_t), ticks.data(),
                                sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    const uint64_t mask = context.info.timestamp_valid_bits >= 64 ? ~0ull : (1ull << context.info.timestamp_valid_bits) - 1;
    std::vector<double> ms(static_cast<size_t>(frames));
    for (int f = 0; f < frames; ++f) {
        uint64_t elapsed = (ticks[size_t(2 * f + 1)] - ticks[size_t(2 * f)]) & mask; // wraps within valid bits
        ms[size_t(f)] = double(elapsed) * double(context.info.timestamp_period_ns) * 1e-6;
    }
    return ms;
}

FrameTimer parse_frame_timer(const std::string& name)
{
    if (name == "timestamps")
        return FrameTimer::timestamps;
    if (name == "wall-clock")
        return FrameTimer::wall_clock;
    throw Error("unknown timer '" + name + "' (expected timestamps or wall-clock)");
}

std::string to_string(FrameTimer timer) { return timer == FrameTimer::timestamps ? "timestamps" : "wall-clock"; }

Image gpu_render(const VulkanContext& context, const GpuTexture& texture, const SceneParams& scene,
                 const SamplerOptions& options, const RenderOptions& render)
{
    std::unique_ptr<GpuRenderer> renderer = create_renderer(context, texture, scene, options, render);
    return render_frame(*renderer, scene);
}

} // namespace tf
