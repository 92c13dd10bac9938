#include "vulkan/readback.h"
#include "vulkan/barriers.h"
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

Image read_pixels(const Buffer& buffer, int width, int height)
{
    Image out = make_image(width, height);
    std::memcpy(out.texels.data(), buffer.mapped, out.texels.size() * sizeof(glm::vec4));
    return out;
}

} // namespace tf
