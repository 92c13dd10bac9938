#include "vulkan/readback.h"
#include "vulkan/barriers.h"
#include "vulkan/cleanup.h"
#include "vulkan/resources.h"
#include <cstring>

namespace tf {

void record_host_read(VkCommandBuffer cb, VkPipelineStageFlags stage, VkAccessFlags access)
{
    memory_barrier(cb, access, VK_ACCESS_HOST_READ_BIT, stage, VK_PIPELINE_STAGE_HOST_BIT);
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
        VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
        barrier.srcAccessMask = writes;
        barrier.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
        barrier.oldLayout = layout;
        barrier.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.image = image;
        barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, level, 1, 0, 1};
        vkCmdPipelineBarrier(cb, stages, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1, &barrier);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
        copy.imageExtent = {width, height, 1};
        vkCmdCopyImageToBuffer(cb, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.buffer, 1, &copy);
        barrier.srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
        barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
        barrier.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        barrier.newLayout = layout;
        vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, stages, 0, 0, nullptr, 0, nullptr, 1, &barrier);
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

} // namespace tf
