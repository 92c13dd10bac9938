#pragma once
// Timing recorded work: a frame's GPU time by timestamps or by the host's wall clock, and the time of any
// recorded commands.
#include "vulkan/device.h"
#include "vulkan/render.h"
#include <functional>
#include <string>
#include <vector>

namespace tf {

// How the benchmark times a GpuRenderer's frames.
// timestamps: GPU timestamps written before and after each frame's draw or dispatch, all frames in one
// submit (real GPUs). wall_clock: one submit and wait a frame, timed on the host: lavapipe writes
// timestamps when it records a command, not when its threads finish the work (they read 0.3 ms for a
// 30 ms frame), so on CPU devices only the wall clock measures anything. cpu_time: as the wall clock, but the
// process's CPU time (every thread's) a frame: on a CPU device that is the frame's work, which other processes
// on the machine do not inflate as they do its wall time (they took 2x on a loaded 2-core machine); it counts
// the driver's own overhead too, and nothing done outside the process.
enum class FrameTimer { timestamps, wall_clock, cpu_time };
FrameTimer parse_frame_timer(const std::string& name); // "timestamps", "wall-clock", "cpu-time"
std::string to_string(FrameTimer timer);

// The host's clock for a timer other than timestamps, in milliseconds from an arbitrary origin: the steady clock
// (wall_clock) or the process's CPU time (cpu_time).
double host_clock_ms(FrameTimer timer);

// The time of `frames` frames after `warmup` untimed ones, in milliseconds each. Throws tf::Error when
// timestamps are asked for and the queue has none. The wall clock cuts a pathologically slow case short
// (see timing.cpp): it may return fewer than `frames` times, never none.
std::vector<double> time_frames(GpuRenderer& renderer, int warmup, int frames, FrameTimer timer);

// time_frames for several renderers that are compared with each other (a scene's baseline and filters). The wall
// clock takes their frames in turn, one of each a round after each one's warm-up, so that whatever else the
// machine does at a moment (another process, a frequency step) falls on all of them alike instead of on the one
// being timed then; timestamps (a GPU's own clock) time each renderer's frames in one submit, as time_frames.
// Result i is renderers[i]'s times.
std::vector<std::vector<double>> time_frames_interleaved(const std::vector<GpuRenderer*>& renderers, int warmup,
                                                         int frames, FrameTimer timer);

// The time of recorded commands (a GPU build, a copy, a frame): each repeat its own submission, timed by GPU
// timestamps around the commands (real GPUs) or by the host around submit-and-wait (CPU devices: lavapipe
// writes timestamps when it records, not when its threads finish; see FrameTimer above).
// Milliseconds of each of `repeats` timed runs of `record`, after `warmup` untimed ones. Throws tf::Error
// when timestamps are asked for and the queue has none.
std::vector<double> time_commands(const VulkanContext& context, const std::function<void(VkCommandBuffer)>& record,
                                  int warmup, int repeats, FrameTimer timer);

double median(std::vector<double> values); // of at least one value

} // namespace tf
