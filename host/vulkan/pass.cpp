#include "vulkan/pass.h"
#include "core/analytic_texture.h"
#include "harness/config.h"
#include <map>

namespace tf {

namespace {

VkDescriptorSetLayout create_set_layout(const VulkanContext& context,
                                        const std::vector<VkDescriptorSetLayoutBinding>& bindings, Cleanup& cleanup)
{
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = uint32_t(bindings.size());
    info.pBindings = bindings.data();
    VkDevice device = context.device;
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    TF_VK(vkCreateDescriptorSetLayout(device, &info, nullptr, &layout));
    cleanup.add([=] { vkDestroyDescriptorSetLayout(device, layout, nullptr); });
    return layout;
}

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
    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = 1;
    pool_info.poolSizeCount = uint32_t(sizes.size());
    pool_info.pPoolSizes = sizes.data();
    VkDevice device = context.device;
    TF_VK(vkCreateDescriptorPool(device, &pool_info, nullptr, &pool));
    VkDescriptorPool created = pool;
    cleanup.add([=] { vkDestroyDescriptorPool(device, created, nullptr); }); // frees the set too
    VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocate.descriptorPool = pool;
    allocate.descriptorSetCount = 1;
    allocate.pSetLayouts = &layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    TF_VK(vkAllocateDescriptorSets(device, &allocate, &set));
    return set;
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

} // namespace tf
