#pragma once
// Results back to the host: the barrier that makes a pass's writes visible to it, the colour target's
// copy into its host buffer, and the pixels out of a mapped buffer.
#include "texture/image.h"
#include "vulkan/render_targets.h"
#include <vector>

namespace tf {

// After the commands (at `stage`, with `access`) that wrote host-visible memory: those writes made
// visible to the host once the submit has completed.
void record_host_read(VkCommandBuffer command_buffer, VkPipelineStageFlags stage, VkAccessFlags access);

// After record_targets_for_readback: the colour target into targets.readback, visible to the host.
void record_target_readback(VkCommandBuffer command_buffer, const RenderTargets& targets);

// One level of a colour image back to the host: width x height texels of texel_bytes each, tightly packed.
// The image is in `layout` before and after (its last writes, at any shader or transfer stage, are
// waited for). Submits and waits. For `texfilter build` and the tests of the GPU builds.
std::vector<unsigned char> read_image_level(const VulkanContext& context, VkImage image, uint32_t level,
                                            uint32_t width, uint32_t height, size_t texel_bytes, VkImageLayout layout);

// width x height RGBA32F texels from a mapped buffer (once the submit that wrote it has completed).
Image read_pixels(const Buffer& buffer, int width, int height);

} // namespace tf
