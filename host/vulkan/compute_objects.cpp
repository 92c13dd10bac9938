// The plain Vulkan objects of the GPU builds' compute passes (compute_objects.h).
#include "vulkan/compute_objects.h"

namespace tf {

VkDescriptorSetLayout create_set_layout(const VulkanContext& context,
                                        const std::vector<VkDescriptorSetLayoutBinding>& bindings, Cleanup& cleanup)
{
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = uint32_t(bindings.size());
    info.pBindings = bindings.data();
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    TF_VK(vkCreateDescriptorSetLayout(context.device, &info, nullptr, &layout));
    VkDevice device = context.device;
    cleanup.add([=] { vkDestroyDescriptorSetLayout(device, layout, nullptr); });
    return layout;
}

VkPipelineLayout create_push_layout(const VulkanContext& context, VkDescriptorSetLayout set_layout,
                                    uint32_t push_bytes, Cleanup& cleanup)
{
    VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, push_bytes};
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = 1;
    info.pSetLayouts = &set_layout;
    info.pushConstantRangeCount = 1;
    info.pPushConstantRanges = &range;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    TF_VK(vkCreatePipelineLayout(context.device, &info, nullptr, &layout));
    VkDevice device = context.device;
    cleanup.add([=] { vkDestroyPipelineLayout(device, layout, nullptr); });
    return layout;
}

VkDescriptorSet allocate_set(const VulkanContext& context, VkDescriptorSetLayout layout,
                             const std::vector<VkDescriptorPoolSize>& sizes, VkDescriptorPool& pool, Cleanup& cleanup)
{
    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = 1;
    pool_info.poolSizeCount = uint32_t(sizes.size());
    pool_info.pPoolSizes = sizes.data();
    TF_VK(vkCreateDescriptorPool(context.device, &pool_info, nullptr, &pool));
    VkDevice device = context.device;
    VkDescriptorPool created = pool;
    cleanup.add([=] { vkDestroyDescriptorPool(device, created, nullptr); }); // frees the set too
    VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocate.descriptorPool = pool;
    allocate.descriptorSetCount = 1;
    allocate.pSetLayouts = &layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    TF_VK(vkAllocateDescriptorSets(context.device, &allocate, &set));
    return set;
}

VkImageView create_level_view(const VulkanContext& context, VkImage image, VkFormat format, uint32_t level,
                              Cleanup& cleanup)
{
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = image;
    info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    info.format = format;
    info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, level, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    TF_VK(vkCreateImageView(context.device, &info, nullptr, &view));
    VkDevice device = context.device;
    cleanup.add([=] { vkDestroyImageView(device, view, nullptr); });
    return view;
}

} // namespace tf
