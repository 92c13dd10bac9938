#include "view/compose.h"
#include "vulkan/pipelines.h"
#include <cstring>

#include "compose_frag.h"
#include "render_vert.h" // the harness's full-screen triangle

namespace tf {

namespace {

void write_image_descriptors(ComposePass& p)
{
    VkDescriptorBufferInfo infos[3];
    VkWriteDescriptorSet writes[3];
    for (uint32_t i = 0; i < 3; ++i) {
        infos[i] = {p.images[i].buffer, 0, VK_WHOLE_SIZE};
        writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[i].dstSet = p.set;
        writes[i].dstBinding = i;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        writes[i].pBufferInfo = &infos[i];
    }
    vkUpdateDescriptorSets(p.context->device, 3, writes, 0, nullptr);
}

} // namespace

void create_compose_pass(const VulkanContext& context, VkRenderPass render_pass, ComposePass& p, Cleanup& cleanup)
{
    VkDevice device = context.device;
    p.context = &context;
    VkDescriptorSetLayoutBinding bindings[3];
    for (uint32_t i = 0; i < 3; ++i)
        bindings[i] = {i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set_info.bindingCount = 3;
    set_info.pBindings = bindings;
    TF_VK(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &p.set_layout));
    cleanup.add([device, l = p.set_layout] { vkDestroyDescriptorSetLayout(device, l, nullptr); });

    VkPushConstantRange range{VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(ComposeParams)};
    VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout_info.setLayoutCount = 1;
    layout_info.pSetLayouts = &p.set_layout;
    layout_info.pushConstantRangeCount = 1;
    layout_info.pPushConstantRanges = &range;
    TF_VK(vkCreatePipelineLayout(device, &layout_info, nullptr, &p.layout));
    cleanup.add([device, l = p.layout] { vkDestroyPipelineLayout(device, l, nullptr); });

    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 3};
    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = 1;
    pool_info.poolSizeCount = 1;
    pool_info.pPoolSizes = &size;
    TF_VK(vkCreateDescriptorPool(device, &pool_info, nullptr, &p.pool));
    cleanup.add([device, l = p.pool] { vkDestroyDescriptorPool(device, l, nullptr); });
    VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocate.descriptorPool = p.pool;
    allocate.descriptorSetCount = 1;
    allocate.pSetLayouts = &p.set_layout;
    TF_VK(vkAllocateDescriptorSets(device, &allocate, &p.set));

    GraphicsPipelineDesc desc;
    desc.vertex = {render_vert, sizeof(render_vert)};
    desc.fragment = {compose_frag, sizeof(compose_frag)};
    desc.render_pass = render_pass; // viewport and scissor: dynamic
    p.pipeline = create_graphics_pipeline(context, desc, p.layout, Filter::nearest, cleanup);

    for (Buffer& b : p.images) { // one pixel each until the viewer fills them
        b = create_host_buffer(context, sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        cleanup.add([&context, &b] { destroy_buffer(context, b); }); // the buffer set_compose_image left
    }
    write_image_descriptors(p);
}

void set_compose_image(ComposePass& p, ComposeImage which, const Image& image)
{
    Buffer& b = p.images[int(which)];
    const VkDeviceSize bytes = VkDeviceSize(image.width) * image.height * sizeof(glm::vec4);
    if (bytes > b.size) {
        TF_VK(vkDeviceWaitIdle(p.context->device)); // the last frame may still read the old buffer
        Buffer grown = create_host_buffer(*p.context, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        destroy_buffer(*p.context, b);
        b = grown;
        write_image_descriptors(p);
    }
    std::memcpy(b.mapped, image.texels.data(), bytes);
}

void record_compose(VkCommandBuffer cb, const ComposePass& p, VkExtent2D extent, const ComposeParams& params)
{
    VkViewport viewport{0.0f, 0.0f, float(extent.width), float(extent.height), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, extent};
    vkCmdSetViewport(cb, 0, 1, &viewport);
    vkCmdSetScissor(cb, 0, 1, &scissor);
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, p.pipeline);
    vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, p.layout, 0, 1, &p.set, 0, nullptr);
    vkCmdPushConstants(cb, p.layout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(ComposeParams), &params);
    vkCmdDraw(cb, 3, 1, 0, 0);
}

} // namespace tf
