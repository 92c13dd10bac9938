#pragma once
// The time of recorded commands (a GPU build, a copy, a frame): each repeat its own submission, timed by GPU
// timestamps around the commands (real GPUs) or by the host around submit-and-wait (CPU devices: lavapipe
// writes timestamps when it records, not when its threads finish; see frame_timer.h).
#include "vulkan/context.h"
#include "vulkan/frame_timer.h"
#include <functional>
#include <vector>

namespace tf {

// Milliseconds of each of `repeats` timed runs of `record`, after `warmup` untimed ones. Throws tf::Error
// when timestamps are asked for and the queue has none.
std::vector<double> time_commands(const VulkanContext& context, const std::function<void(VkCommandBuffer)>& record,
                                  int warmup, int repeats, FrameTimer timer);

double median(std::vector<double> values); // of at least one value

} // namespace tf
