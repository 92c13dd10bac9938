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
        image_barrier(cb, image, 1, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, writes, VK_ACCESS_TRANSFER_READ_BIT,
                      stages, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_IMAGE_ASPECT_COLOR_BIT, 1, level);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
        copy.imageExtent = {width, height, 1};
        vkCmdCopyImageToBuffer(cb, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.buffer, 1, &copy);
        image_barrier(cb, image, 1, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout, VK_ACCESS_TRANSFER_READ_BIT,
                      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, stages,
                      VK_IMAGE_ASPECT_COLOR_BIT, 1, level);
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
