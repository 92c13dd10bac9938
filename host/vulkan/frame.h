#pragma once
// The commands of one frame of a GpuRenderer, shared by render_frame and the frame timers.
#include "vulkan/render.h"

namespace tf {

// The dispatch (into the pixel buffer) or the draw (into the colour target, which ends in TRANSFER_SRC
// layout). `timestamps` (or null) bracket the work itself, not the layout changes around it, at queries
// `query` and `query + 1`.
void record_frame(const GpuRenderer& renderer, VkCommandBuffer command_buffer, VkQueryPool timestamps,
                  uint32_t query);

// After record_frame: the frame in host-visible memory (the pixel buffer or the targets' readback buffer).
void record_frame_readback(const GpuRenderer& renderer, VkCommandBuffer command_buffer);

} // namespace tf
