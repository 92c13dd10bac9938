// One-shot command buffers: record, submit, wait, free.
#include "vulkan/context.h"

namespace tf {

VkCommandBuffer begin_one_shot(const VulkanContext& context)
{
    VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocate.commandPool = context.command_pool;
    allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocate.commandBufferCount = 1;
    VkCommandBuffer command_buffer = VK_NULL_HANDLE;
    TF_VK(vkAllocateCommandBuffers(context.device, &allocate, &command_buffer));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VkResult result = vkBeginCommandBuffer(command_buffer, &begin);
    if (result != VK_SUCCESS)
        free_one_shot(context, command_buffer);
    TF_VK(result);
    return command_buffer;
}

void end_one_shot(const VulkanContext& context, VkCommandBuffer command_buffer)
{
    TF_VK(vkEndCommandBuffer(command_buffer));
    VkDevice device = context.device;
    Cleanup cleanup;
    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence = VK_NULL_HANDLE;
    TF_VK(vkCreateFence(device, &fence_info, nullptr, &fence));
    cleanup.add([=] { vkDestroyFence(device, fence, nullptr); });
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &command_buffer;
    TF_VK(vkQueueSubmit(context.queue, 1, &submit, fence));
    TF_VK(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX));
}

void free_one_shot(const VulkanContext& context, VkCommandBuffer command_buffer)
{
    vkFreeCommandBuffers(context.device, context.command_pool, 1, &command_buffer);
}

} // namespace tf
