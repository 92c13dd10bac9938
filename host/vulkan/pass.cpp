#include "vulkan/pass.h"
#include "harness/config.h"

namespace tf {

VkDescriptorSetLayout create_set_layout(const VulkanContext& context, const std::vector<VkDescriptorSetLayoutBinding>& bindings)
{
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = uint32_t(bindings.size());
    info.pBindings = bindings.data();
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    TF_VK(vkCreateDescriptorSetLayout(context.device, &info, nullptr, &layout));
    return layout;
}

std::vector<VkDescriptorSetLayoutBinding> texture_bindings(VkShaderStageFlags stage)
{
    return {{HARNESS_BINDING_TEXTURE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stage, nullptr},
            {HARNESS_BINDING_SAT_LOW, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stage, nullptr},
            {HARNESS_BINDING_SAT_HIGH, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stage, nullptr}};
}

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

VkPipeline create_compute_pipeline(const VulkanContext& context, const uint32_t* code, size_t size_bytes,
                                   VkPipelineLayout layout, Filter filter, Cleanup& cleanup)
{
    VkDevice device = context.device;
    VkShaderModule module = create_shader_module(context, code, size_bytes);
    cleanup.add([=] { vkDestroyShaderModule(device, module, nullptr); });
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module;
    info.stage.pName = "main";
    FilterSpecialization specialization;
    info.stage.pSpecializationInfo = filter_specialization(filter, specialization);
    info.layout = layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    TF_VK(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    cleanup.add([=] { vkDestroyPipeline(device, pipeline, nullptr); });
    return pipeline;
}

void write_textures(std::vector<VkWriteDescriptorSet>& writes, VkDescriptorSet set, const PassSamplers& samplers)
{
    writes.push_back(write_texture(set, HARNESS_BINDING_TEXTURE, &samplers.infos[0]));
    writes.push_back(write_texture(set, HARNESS_BINDING_SAT_LOW, &samplers.infos[1]));
    writes.push_back(write_texture(set, HARNESS_BINDING_SAT_HIGH, &samplers.infos[2]));
}

} // namespace tf
