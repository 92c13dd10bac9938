#pragma once
// How the benchmark times a GpuRenderer's frames.
#include "vulkan/render.h"
#include <string>
#include <vector>

namespace tf {

// timestamps: GPU timestamps written before and after each frame's draw or dispatch, all frames in one
// submit (real GPUs). wall_clock: one submit and wait a frame, timed on the host: lavapipe writes
// timestamps when it records a command, not when its threads finish the work (they read 0.3 ms for a
// 30 ms frame), so on CPU devices only the wall clock measures anything.
enum class FrameTimer { timestamps, wall_clock };
FrameTimer parse_frame_timer(const std::string& name); // "timestamps", "wall-clock"
std::string to_string(FrameTimer timer);

// The time of `frames` frames after `warmup` untimed ones, in milliseconds each. Throws tf::Error when
// timestamps are asked for and the queue has none. The wall clock cuts a pathologically slow case short
// (see vulkan/frame_timer.cpp): it may return fewer than `frames` times, never none.
std::vector<double> time_frames(GpuRenderer& renderer, int warmup, int frames, FrameTimer timer);

// time_frames for several renderers that are compared with each other (a scene's baseline and filters). The wall
// clock takes their frames in turn, one of each a round after each one's warm-up, so that whatever else the
// machine does at a moment (another process, a frequency step) falls on all of them alike instead of on the one
// being timed then; timestamps (a GPU's own clock) time each renderer's frames in one submit, as time_frames.
// Result i is renderers[i]'s times.
std::vector<std::vector<double>> time_frames_interleaved(const std::vector<GpuRenderer*>& renderers, int warmup,
                                                         int frames, FrameTimer timer);

} // namespace tf
