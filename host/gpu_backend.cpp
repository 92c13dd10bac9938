#include "gpu_backend.h"
#include "../shaders/harness/config.h"
#include "error.h"
#include "sat.h"
#include "vk_resources.h"
#include <cstring>
#include <functional>

#include "render_frag.h"
#include "render_vert.h"
#include "sample_comp.h"

namespace tf {

namespace {

// Destroys what a function created, in reverse order, however it leaves (return or exception).
struct Cleanup {
    std::vector<std::function<void()>> steps;
    ~Cleanup()
    {
        for (auto it = steps.rbegin(); it != steps.rend(); ++it)
            (*it)();
    }
    void add(std::function<void()> step) { steps.push_back(std::move(step)); }
};

VkDescriptorSetLayout create_set_layout(const VulkanContext& context, const std::vector<VkDescriptorSetLayoutBinding>& bindings)
{
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = uint32_t(bindings.size());
    info.pBindings = bindings.data();
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    TF_VK(vkCreateDescriptorSetLayout(context.device, &info, nullptr, &layout));
    return layout;
}

// The three textures every harness shader declares: the MIP chain and the two SAT words.
std::vector<VkDescriptorSetLayoutBinding> texture_bindings(VkShaderStageFlags stage)
{
    return {{TF_BINDING_TEXTURE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stage, nullptr},
            {TF_BINDING_SAT_LOW, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stage, nullptr},
            {TF_BINDING_SAT_HIGH, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stage, nullptr}};
}

// Samplers for one pass: the filter's (see create_sampler) and a nearest one for the integer SAT.
struct PassSamplers {
    VkSampler texture = VK_NULL_HANDLE, table = VK_NULL_HANDLE;
    VkDescriptorImageInfo infos[3];
};

void create_pass_samplers(const VulkanContext& context, const GpuTexture& texture, const SamplerOptions& options,
                          PassSamplers& samplers, Cleanup& cleanup)
{
    VkDevice device = context.device;
    samplers.texture = create_sampler(context, options, texture.levels);
    VkSampler texture_sampler = samplers.texture;
    cleanup.add([=] { vkDestroySampler(device, texture_sampler, nullptr); });
    SamplerOptions nearest;
    nearest.filter = Filter::hw_nearest;
    samplers.table = create_sampler(context, nearest, 1);
    VkSampler table_sampler = samplers.table;
    cleanup.add([=] { vkDestroySampler(device, table_sampler, nullptr); });
    samplers.infos[0] = {samplers.texture, texture.chain.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    samplers.infos[1] = {samplers.table, texture.sat_low.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    samplers.infos[2] = {samplers.table, texture.sat_high.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
}

VkPipelineLayout create_pipeline_layout(const VulkanContext& context, VkDescriptorSetLayout set_layout,
                                        VkShaderStageFlags push_stages)
{
    VkPushConstantRange range{push_stages, 0, sizeof(PushConstants)};
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = 1;
    info.pSetLayouts = &set_layout;
    info.pushConstantRangeCount = 1;
    info.pPushConstantRanges = &range;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    TF_VK(vkCreatePipelineLayout(context.device, &info, nullptr, &layout));
    return layout;
}

VkWriteDescriptorSet write_texture(VkDescriptorSet set, uint32_t binding, const VkDescriptorImageInfo* image)
{
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    w.pImageInfo = image;
    return w;
}

void destroy_image(const VulkanContext& context, GpuImage& image)
{
    if (image.view)
        vkDestroyImageView(context.device, image.view, nullptr);
    if (image.image)
        vkDestroyImage(context.device, image.image, nullptr);
    if (image.memory)
        vkFreeMemory(context.device, image.memory, nullptr);
    image = GpuImage{};
}

VkWriteDescriptorSet write_buffer(VkDescriptorSet set, uint32_t binding, VkDescriptorType type,
                                  const VkDescriptorBufferInfo* buffer)
{
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = type;
    w.pBufferInfo = buffer;
    return w;
}

// A device-local sampled image with `levels` levels, filled from tightly packed level data.
GpuImage upload_image(const VulkanContext& context, VkFormat format, const std::vector<VkExtent2D>& extents,
                      const std::vector<const void*>& data, const std::vector<size_t>& bytes)
{
    VkDevice device = context.device;
    GpuImage g;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {extents[0].width, extents[0].height, 1};
    info.mipLevels = uint32_t(extents.size());
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    try {
        TF_VK(vkCreateImage(device, &info, nullptr, &g.image));
        VkMemoryRequirements requirements{};
        vkGetImageMemoryRequirements(device, g.image, &requirements);
        VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        allocate.allocationSize = requirements.size;
        allocate.memoryTypeIndex =
            find_memory_type(context, requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        if (vkAllocateMemory(device, &allocate, nullptr, &g.memory) != VK_SUCCESS)
            throw Error("out of device memory for a " + std::to_string(extents[0].width) + "x" +
                        std::to_string(extents[0].height) + " texture on " + context.info.name);
        TF_VK(vkBindImageMemory(device, g.image, g.memory, 0));

        VkDeviceSize total = 0;
        for (size_t b : bytes)
            total += b;
        Buffer staging = create_host_buffer(context, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        Cleanup cleanup;
        cleanup.add([&] { destroy_buffer(context, staging); });
        std::vector<VkBufferImageCopy> copies;
        VkDeviceSize offset = 0;
        for (size_t l = 0; l < extents.size(); ++l) {
            std::memcpy(static_cast<char*>(staging.mapped) + offset, data[l], bytes[l]);
            VkBufferImageCopy copy{};
            copy.bufferOffset = offset;
            copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, uint32_t(l), 0, 1};
            copy.imageExtent = {extents[l].width, extents[l].height, 1};
            copies.push_back(copy);
            offset += bytes[l];
        }
        uint32_t levels = uint32_t(extents.size());
        submit_and_wait(context, [&](VkCommandBuffer cb) {
            image_barrier(cb, g.image, levels, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
                          VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                          VK_PIPELINE_STAGE_TRANSFER_BIT);
            vkCmdCopyBufferToImage(cb, staging.buffer, g.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                   uint32_t(copies.size()), copies.data());
            image_barrier(cb, g.image, levels, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
                          VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                          VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
        });

        VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        view.image = g.image;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = format;
        view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, levels, 0, 1};
        TF_VK(vkCreateImageView(device, &view, nullptr, &g.view));
    } catch (...) {
        destroy_image(context, g);
        throw;
    }
    return g;
}

} // namespace

bool needs_sat(Filter filter) { return filter == Filter::sat || filter == Filter::sat_assembly; }

GpuTexture upload_texture(const VulkanContext& context, const MipChain& chain, bool with_sat)
{
    const Image& base = chain.levels.at(0);
    uint32_t limit = context.info.max_image_dimension_2d;
    if (uint32_t(base.width) > limit || uint32_t(base.height) > limit)
        throw Error("texture " + std::to_string(base.width) + "x" + std::to_string(base.height) +
                    " exceeds the device limit maxImageDimension2D = " + std::to_string(limit));
    if (with_sat && (uint32_t(base.width) + 1 > limit || uint32_t(base.height) + 1 > limit))
        throw Error("the summed-area table of a " + std::to_string(base.width) + "x" + std::to_string(base.height) +
                    " texture needs one more texel a side than maxImageDimension2D = " + std::to_string(limit));
    GpuTexture t;
    t.width = base.width;
    t.height = base.height;
    t.levels = int(chain.levels.size());
    try {
        std::vector<VkExtent2D> extents;
        std::vector<const void*> data;
        std::vector<size_t> bytes;
        for (const Image& level : chain.levels) {
            extents.push_back({uint32_t(level.width), uint32_t(level.height)});
            data.push_back(level.texels.data());
            bytes.push_back(level.texels.size() * sizeof(glm::vec4));
        }
        t.chain = upload_image(context, VK_FORMAT_R32G32B32A32_SFLOAT, extents, data, bytes);

        SatTable sat;
        if (with_sat) {
            sat = build_sat(base);
        } else { // a 1x1 zero table keeps the descriptor set valid for every filter
            sat.low.assign(4, 0u);
            sat.high.assign(1, 0u);
        }
        VkExtent2D sat_extent{uint32_t(sat.width + 1), uint32_t(sat.height + 1)};
        if (!with_sat)
            sat_extent = {1, 1};
        t.sat_scale = sat.scale;
        t.sat_low = upload_image(context, VK_FORMAT_R32G32B32A32_UINT, {sat_extent}, {sat.low.data()},
                                 {sat.low.size() * sizeof(uint32_t)});
        t.sat_high = upload_image(context, VK_FORMAT_R32_UINT, {sat_extent}, {sat.high.data()},
                                  {sat.high.size() * sizeof(uint32_t)});
    } catch (...) {
        destroy_texture(context, t);
        throw;
    }
    return t;
}

void destroy_texture(const VulkanContext& context, GpuTexture& texture)
{
    destroy_image(context, texture.chain);
    destroy_image(context, texture.sat_low);
    destroy_image(context, texture.sat_high);
    texture = GpuTexture{};
}

Image gpu_render(const VulkanContext& context, const GpuTexture& texture, const SceneParams& scene,
                 const SamplerOptions& options)
{
    const uint32_t width = uint32_t(scene.kind_size.y), height = uint32_t(scene.kind_size.z);
    const VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT;
    VkDevice device = context.device;
    Cleanup cleanup;

    // Colour target.
    VkImageCreateInfo target_info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    target_info.imageType = VK_IMAGE_TYPE_2D;
    target_info.format = format;
    target_info.extent = {width, height, 1};
    target_info.mipLevels = target_info.arrayLayers = 1;
    target_info.samples = VK_SAMPLE_COUNT_1_BIT;
    target_info.tiling = VK_IMAGE_TILING_OPTIMAL;
    target_info.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    VkImage target = VK_NULL_HANDLE;
    TF_VK(vkCreateImage(device, &target_info, nullptr, &target));
    cleanup.add([=] { vkDestroyImage(device, target, nullptr); });
    VkMemoryRequirements requirements{};
    vkGetImageMemoryRequirements(device, target, &requirements);
    VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    allocate.allocationSize = requirements.size;
    allocate.memoryTypeIndex = find_memory_type(context, requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VkDeviceMemory target_memory = VK_NULL_HANDLE;
    TF_VK(vkAllocateMemory(device, &allocate, nullptr, &target_memory));
    cleanup.add([=] { vkFreeMemory(device, target_memory, nullptr); });
    TF_VK(vkBindImageMemory(device, target, target_memory, 0));
    VkImageViewCreateInfo view_info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view_info.image = target;
    view_info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view_info.format = format;
    view_info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView target_view = VK_NULL_HANDLE;
    TF_VK(vkCreateImageView(device, &view_info, nullptr, &target_view));
    cleanup.add([=] { vkDestroyImageView(device, target_view, nullptr); });

    Buffer readback = create_host_buffer(context, VkDeviceSize(width) * height * sizeof(glm::vec4),
                                         VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    cleanup.add([&] { destroy_buffer(context, readback); });
    Buffer uniforms = create_host_buffer(context, sizeof(SceneParams), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    cleanup.add([&] { destroy_buffer(context, uniforms); });
    std::memcpy(uniforms.mapped, &scene, sizeof(SceneParams));

    PassSamplers samplers;
    create_pass_samplers(context, texture, options, samplers, cleanup);

    std::vector<VkDescriptorSetLayoutBinding> bindings = texture_bindings(VK_SHADER_STAGE_FRAGMENT_BIT);
    bindings.push_back({TF_BINDING_SCENE, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
    VkDescriptorSetLayout set_layout = create_set_layout(context, bindings);
    cleanup.add([=] { vkDestroyDescriptorSetLayout(device, set_layout, nullptr); });
    VkPipelineLayout pipeline_layout = create_pipeline_layout(context, set_layout, VK_SHADER_STAGE_FRAGMENT_BIT);
    cleanup.add([=] { vkDestroyPipelineLayout(device, pipeline_layout, nullptr); });

    VkShaderModule vert = create_shader_module(context, tf_spirv_render_vert, sizeof(tf_spirv_render_vert));
    cleanup.add([=] { vkDestroyShaderModule(device, vert, nullptr); });
    VkShaderModule frag = create_shader_module(context, tf_spirv_render_frag, sizeof(tf_spirv_render_frag));
    cleanup.add([=] { vkDestroyShaderModule(device, frag, nullptr); });

    VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                                 {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = vert;
    stages[0].pName = "main";
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = frag;
    stages[1].pName = "main";
    VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkViewport viewport{0.0f, 0.0f, float(width), float(height), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, {width, height}};
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
    VkPipelineColorBlendAttachmentState blend_attachment{};
    blend_attachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                      VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = 1;
    blend.pAttachments = &blend_attachment;
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachmentFormats = &format;
    VkGraphicsPipelineCreateInfo pipeline_info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    pipeline_info.pNext = &rendering;
    pipeline_info.stageCount = 2;
    pipeline_info.pStages = stages;
    pipeline_info.pVertexInputState = &vertex_input;
    pipeline_info.pInputAssemblyState = &assembly;
    pipeline_info.pViewportState = &viewport_state;
    pipeline_info.pRasterizationState = &raster;
    pipeline_info.pMultisampleState = &multisample;
    pipeline_info.pColorBlendState = &blend;
    pipeline_info.layout = pipeline_layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    TF_VK(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &pipeline_info, nullptr, &pipeline));
    cleanup.add([=] { vkDestroyPipeline(device, pipeline, nullptr); });

    DescriptorSet descriptors = allocate_descriptor_set(context, set_layout);
    cleanup.add([=] { vkDestroyDescriptorPool(device, descriptors.pool, nullptr); });
    VkDescriptorBufferInfo uniform_info{uniforms.buffer, 0, sizeof(SceneParams)};
    VkWriteDescriptorSet writes[] = {
        write_texture(descriptors.set, TF_BINDING_TEXTURE, &samplers.infos[0]),
        write_texture(descriptors.set, TF_BINDING_SAT_LOW, &samplers.infos[1]),
        write_texture(descriptors.set, TF_BINDING_SAT_HIGH, &samplers.infos[2]),
        write_buffer(descriptors.set, TF_BINDING_SCENE, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &uniform_info)};
    vkUpdateDescriptorSets(device, 4, writes, 0, nullptr);

    PushConstants push = make_push_constants(options, 0, texture.sat_scale);
    submit_and_wait(context, [&](VkCommandBuffer cb) {
        image_barrier(cb, target, 1, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, 0,
                      VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                      VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT);
        VkRenderingAttachmentInfo attachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        attachment.imageView = target_view;
        attachment.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        attachment.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE; // the triangle covers every pixel
        attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        VkRenderingInfo rendering_info{VK_STRUCTURE_TYPE_RENDERING_INFO};
        rendering_info.renderArea = scissor;
        rendering_info.layerCount = 1;
        rendering_info.colorAttachmentCount = 1;
        rendering_info.pColorAttachments = &attachment;
        vkCmdBeginRendering(cb, &rendering_info);
        vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
        vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_layout, 0, 1, &descriptors.set, 0, nullptr);
        vkCmdPushConstants(cb, pipeline_layout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(push), &push);
        vkCmdDraw(cb, 3, 1, 0, 0);
        vkCmdEndRendering(cb);
        image_barrier(cb, target, 1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                      VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT,
                      VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        copy.imageExtent = {width, height, 1};
        vkCmdCopyImageToBuffer(cb, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1, &copy);
        VkMemoryBarrier host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &host, 0, nullptr,
                             0, nullptr);
    });

    Image out = make_image(int(width), int(height));
    std::memcpy(out.texels.data(), readback.mapped, out.texels.size() * sizeof(glm::vec4));
    return out;
}

std::vector<glm::vec4> gpu_sample(const VulkanContext& context, const GpuTexture& texture,
                                  const std::vector<Lookup>& lookups, const SamplerOptions& options,
                                  std::vector<LookupStats>* stats)
{
    VkDevice device = context.device;
    Cleanup cleanup;
    const uint32_t count = uint32_t(lookups.size());
    Buffer input = create_host_buffer(context, VkDeviceSize(count) * 6 * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    cleanup.add([&] { destroy_buffer(context, input); });
    Buffer output = create_host_buffer(context, VkDeviceSize(count) * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    cleanup.add([&] { destroy_buffer(context, output); });
    Buffer counts = create_host_buffer(context, VkDeviceSize(count) * sizeof(LookupStats), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    cleanup.add([&] { destroy_buffer(context, counts); });
    float* in = static_cast<float*>(input.mapped);
    for (uint32_t i = 0; i < count; ++i) {
        const Lookup& l = lookups[i];
        const double values[6] = {l.u, l.v, l.dudx, l.dvdx, l.dudy, l.dvdy};
        for (int k = 0; k < 6; ++k)
            in[6 * i + k] = float(values[k]);
    }

    PassSamplers samplers;
    create_pass_samplers(context, texture, options, samplers, cleanup);
    std::vector<VkDescriptorSetLayoutBinding> bindings = texture_bindings(VK_SHADER_STAGE_COMPUTE_BIT);
    for (uint32_t binding : {TF_BINDING_LOOKUPS, TF_BINDING_RESULTS, TF_BINDING_STATS})
        bindings.push_back({binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
    VkDescriptorSetLayout set_layout = create_set_layout(context, bindings);
    cleanup.add([=] { vkDestroyDescriptorSetLayout(device, set_layout, nullptr); });
    VkPipelineLayout pipeline_layout = create_pipeline_layout(context, set_layout, VK_SHADER_STAGE_COMPUTE_BIT);
    cleanup.add([=] { vkDestroyPipelineLayout(device, pipeline_layout, nullptr); });
    VkShaderModule module = create_shader_module(context, tf_spirv_sample_comp, sizeof(tf_spirv_sample_comp));
    cleanup.add([=] { vkDestroyShaderModule(device, module, nullptr); });
    VkComputePipelineCreateInfo pipeline_info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    pipeline_info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    pipeline_info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipeline_info.stage.module = module;
    pipeline_info.stage.pName = "main";
    pipeline_info.layout = pipeline_layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    TF_VK(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &pipeline_info, nullptr, &pipeline));
    cleanup.add([=] { vkDestroyPipeline(device, pipeline, nullptr); });

    DescriptorSet descriptors = allocate_descriptor_set(context, set_layout);
    cleanup.add([=] { vkDestroyDescriptorPool(device, descriptors.pool, nullptr); });
    VkDescriptorBufferInfo in_info{input.buffer, 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo out_info{output.buffer, 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo stats_info{counts.buffer, 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet writes[] = {
        write_texture(descriptors.set, TF_BINDING_TEXTURE, &samplers.infos[0]),
        write_texture(descriptors.set, TF_BINDING_SAT_LOW, &samplers.infos[1]),
        write_texture(descriptors.set, TF_BINDING_SAT_HIGH, &samplers.infos[2]),
        write_buffer(descriptors.set, TF_BINDING_LOOKUPS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &in_info),
        write_buffer(descriptors.set, TF_BINDING_RESULTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &out_info),
        write_buffer(descriptors.set, TF_BINDING_STATS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &stats_info)};
    vkUpdateDescriptorSets(device, 6, writes, 0, nullptr);

    PushConstants push = make_push_constants(options, count, texture.sat_scale);
    submit_and_wait(context, [&](VkCommandBuffer cb) {
        vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
        vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout, 0, 1, &descriptors.set, 0, nullptr);
        vkCmdPushConstants(cb, pipeline_layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
        vkCmdDispatch(cb, (count + TF_SAMPLE_LOCAL_SIZE - 1) / TF_SAMPLE_LOCAL_SIZE, 1, 1);
        VkMemoryBarrier host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        host.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
        host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &host, 0,
                             nullptr, 0, nullptr);
    });
    std::vector<glm::vec4> results(count);
    std::memcpy(results.data(), output.mapped, results.size() * sizeof(glm::vec4));
    if (stats) {
        stats->resize(count);
        std::memcpy(stats->data(), counts.mapped, stats->size() * sizeof(LookupStats));
    }
    return results;
}

} // namespace tf
