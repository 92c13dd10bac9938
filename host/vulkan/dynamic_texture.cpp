// The dynamic texture: its generator pipeline and each frame's commands.
#include "vulkan/dynamic_texture.h"
#include "texture/error.h"
#include "vulkan/barriers.h"
#include "vulkan/pipeline.h"

#include "dynamic_texture_comp.h"

namespace tf {

namespace {

struct GeneratorPush {
    int32_t size, frame;
};

} // namespace

DynamicTexture create_dynamic_texture(const VulkanContext& context, int size)
{
    DynamicTexture d;
    d.size = size;
    d.build = prepare_gpu_build(context, nullptr, size, size, false, TextureFormat::rgba32f);
    Cleanup on_failure;
    on_failure.add([&] { destroy_dynamic_texture(context, d); });
    d.objects = std::make_shared<Cleanup>();
    Cleanup& objects = *d.objects;
    VkDevice device = context.device;
    const VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set_info.bindingCount = 1;
    set_info.pBindings = &binding;
    TF_VK(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &d.set_layout));
    objects.add([device, layout = d.set_layout] { vkDestroyDescriptorSetLayout(device, layout, nullptr); });
    const VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(GeneratorPush)};
    VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout_info.setLayoutCount = 1;
    layout_info.pSetLayouts = &d.set_layout;
    layout_info.pushConstantRangeCount = 1;
    layout_info.pPushConstantRanges = &range;
    TF_VK(vkCreatePipelineLayout(device, &layout_info, nullptr, &d.layout));
    objects.add([device, layout = d.layout] { vkDestroyPipelineLayout(device, layout, nullptr); });
    d.pipeline = create_compute_pipeline(context, {dynamic_texture_comp, sizeof(dynamic_texture_comp)}, d.layout,
                                         Filter::nearest, objects);
    const VkDescriptorPoolSize pool_size{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1};
    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = 1;
    pool_info.poolSizeCount = 1;
    pool_info.pPoolSizes = &pool_size;
    TF_VK(vkCreateDescriptorPool(device, &pool_info, nullptr, &d.pool));
    objects.add([device, pool = d.pool] { vkDestroyDescriptorPool(device, pool, nullptr); });
    VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocate.descriptorPool = d.pool;
    allocate.descriptorSetCount = 1;
    allocate.pSetLayouts = &d.set_layout;
    TF_VK(vkAllocateDescriptorSets(device, &allocate, &d.set));
    const VkDescriptorImageInfo image{VK_NULL_HANDLE, d.build.mip.level_views[0], VK_IMAGE_LAYOUT_GENERAL};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = d.set;
    write.dstBinding = 0;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    write.pImageInfo = &image;
    vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
    on_failure.dismiss();
    return d;
}

void record_dynamic_frame(VkCommandBuffer cb, DynamicTexture& d, int frame)
{
    const uint32_t levels = uint32_t(d.build.texture.levels);
    // The last frame's reads (fragment or compute) before this frame's writes; the first frame discards.
    image_barrier(cb, d.build.built.image, levels,
                  d.first ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                  d.first ? 0 : VK_ACCESS_SHADER_READ_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT,
                  d.first ? VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT
                          : VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                  VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, d.pipeline);
    vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, d.layout, 0, 1, &d.set, 0, nullptr);
    const GeneratorPush push{d.size, frame};
    vkCmdPushConstants(cb, d.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdDispatch(cb, uint32_t(d.size + 15) / 16, uint32_t(d.size + 15) / 16, 1);
    record_gpu_build(cb, d.build, d.first ? Level0::written_first : Level0::written);
    d.first = false;
}

void destroy_dynamic_texture(const VulkanContext& context, DynamicTexture& d)
{
    d.objects.reset();
    destroy_gpu_build(context, d.build);
    d = DynamicTexture{};
}

} // namespace tf
