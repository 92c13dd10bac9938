#pragma once
// texfilter bench --gpu-build: the device's MIP and SAT builds beside the host's and beside a plain copy of
// the same bytes on each (vkCmdCopyBufferToImage on the device, memcpy on the host), in one run, for each
// side; and the dynamic texture, generated, rebuilt and filtered in one submission a frame, beside the same
// frame with a static texture. A benchmark: printed, never asserted on.
#include "core/memory_budget.h"
#include "vulkan/device.h"
#include "vulkan/timing.h"
#include <string>
#include <vector>

namespace tf {

struct BuildTimes {
    double bytes = 0;                 // read + written by one build (the yardstick's traffic)
    double gpu_ms = 0, device_copy_ms = 0; // median; the copy moves bytes / 2 (it reads and writes them)
    double cpu_ms = 0, memcpy_ms = 0;
};

struct GpuBuildRow {
    int side = 0, levels = 0, passes = 0;
    BuildTimes mip;
    bool sat = false; // sides up to 4096
    BuildTimes table;
    std::string skipped; // why this side did not run (device memory), empty when it did
};

struct DynamicRow {
    int side = 0, width = 0, height = 0;
    double frame_ms = 0;  // generate + build + render (plane, trilinear), one submission
    double static_ms = 0; // the same render of a texture built once
};

struct GpuBuildBench {
    std::string device, driver, date;
    FrameTimer timer = FrameTimer::wall_clock;
    int repeats = 0;
    std::vector<GpuBuildRow> rows;
    DynamicRow dynamic;
};

// Refuses, before anything is built, a run whose sides (or the dynamic texture's) cannot fit: one of its
// images over the device's maxMemoryAllocationSize, all of them over its heap, or the host memory a side
// holds at once (level 0, a copy of it built into a chain, the table, the memcpy yardstick's two buffers,
// staging, and the device's memory on a CPU device) over `budget`. Every side is checked before the first runs.
void check_gpu_build_bench(const std::vector<int>& sides, int dynamic_side, const DeviceLimits& device,
                           uint64_t budget);

GpuBuildBench run_gpu_build_bench(const VulkanContext& context, const std::vector<int>& sides, int repeats,
                                  FrameTimer timer, int dynamic_side);
std::string format_gpu_build_bench(const GpuBuildBench& bench);

} // namespace tf
