#include "vulkan/timing.h"
#include "texture/error.h"
#include "vulkan/render.h"
#include <algorithm>
#include <chrono>
#include <ctime>

namespace tf {

namespace {

// One submit and wait a frame, timed on the host. A frame slower than `slow_ms` ends the warm-up and cuts
// the timed frames to three: a pathological case (lavapipe's hw-aniso on some scenes takes seconds a frame)
// must not hold the whole benchmark up. The first frame does not count as slow: lavapipe compiles a
// pipeline's shaders at its first draw (0.5-4 s), which cut every such filter to three timed frames.
constexpr double slow_ms = 250.0;

double host_frame_ms(const GpuRenderer& r, FrameTimer timer)
{
    const double start = host_clock_ms(timer);
    submit_and_wait(*r.context, [&](VkCommandBuffer cb) { record_frame(r, cb, VK_NULL_HANDLE, 0); });
    return host_clock_ms(timer) - start;
}

// The wall clock's rounds: each renderer warms up alone (the slow-frame rule cuts its warm-up), then one frame
// of each a round; a renderer with a slow frame stops after three timed ones. With several renderers each timed
// frame follows an untimed one of the same renderer: a frame right after another renderer's found the caches
// full of that one's texture and tables, and which one came before decided up to 10 % of a ratio (hw-trilinear
// after the SAT's frame was slower than after the baseline's). Timed so, a frame costs what it costs in a
// run of its own frames, as in a renderer's steady state, while the rounds still share the machine's drift.
std::vector<std::vector<double>> time_on_host_in_turn(const std::vector<GpuRenderer*>& renderers, int warmup,
                                                      int frames, FrameTimer timer)
{
    std::vector<int> limit(renderers.size(), frames);
    for (size_t i = 0; i < renderers.size(); ++i)
        for (int f = 0; f < warmup; ++f)
            if (double elapsed = host_frame_ms(*renderers[i], timer); f > 0 && elapsed > slow_ms) {
                limit[i] = std::min(frames, 3);
                break;
            }
    std::vector<std::vector<double>> ms(renderers.size());
    for (int round = 0; round < frames; ++round)
        for (size_t i = 0; i < renderers.size(); ++i) {
            if (int(ms[i].size()) >= limit[i])
                continue;
            if (renderers.size() > 1 && limit[i] == frames) // not for a renderer cut short for being slow
                host_frame_ms(*renderers[i], timer);
            ms[i].push_back(host_frame_ms(*renderers[i], timer));
            const bool first_frame = warmup == 0 && ms[i].size() == 1; // the compile's, as in the warm-up
            if (!first_frame && ms[i].back() > slow_ms)
                limit[i] = std::min(limit[i], std::max(3, int(ms[i].size())));
        }
    return ms;
}

// A pool of `count` timestamps, destroyed by `cleanup`. Throws where the queue writes none.
VkQueryPool create_timestamp_pool(const VulkanContext& context, uint32_t count, Cleanup& cleanup)
{
    if (context.info.timestamp_valid_bits == 0 || context.info.timestamp_period_ns <= 0.0f)
        throw Error(context.info.name + " has no timestamps on its graphics and compute queue: use the wall-clock timer");
    VkDevice device = context.device;
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = count;
    VkQueryPool pool = VK_NULL_HANDLE;
    TF_VK(vkCreateQueryPool(device, &info, nullptr, &pool));
    cleanup.add([=] { vkDestroyQueryPool(device, pool, nullptr); });
    return pool;
}

// The bits of a timestamp the queue writes.
uint64_t timestamp_mask(const VulkanContext& context)
{
    return context.info.timestamp_valid_bits >= 64 ? ~0ull : (1ull << context.info.timestamp_valid_bits) - 1;
}

// All frames in one submit, each bracketed by two timestamps.
std::vector<double> time_with_timestamps(const GpuRenderer& r, int warmup, int frames)
{
    const VulkanContext& context = *r.context;
    VkDevice device = context.device;
    Cleanup cleanup;
    const uint32_t count = uint32_t(2 * frames);
    const VkQueryPool pool = create_timestamp_pool(context, count, cleanup);

    submit_and_wait(context, [&](VkCommandBuffer cb) {
        vkCmdResetQueryPool(cb, pool, 0, count);
        for (int f = 0; f < warmup + frames; ++f)
            record_frame(r, cb, f < warmup ? VK_NULL_HANDLE : pool, uint32_t(2 * (f - warmup)));
    });
    std::vector<uint64_t> ticks(count);
    TF_VK(vkGetQueryPoolResults(device, pool, 0, count, ticks.size() * sizeof(uint64_t), ticks.data(),
                                sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    const uint64_t mask = timestamp_mask(context);
    std::vector<double> ms(static_cast<size_t>(frames));
    for (int f = 0; f < frames; ++f) {
        uint64_t elapsed = (ticks[size_t(2 * f + 1)] - ticks[size_t(2 * f)]) & mask; // wraps within valid bits
        ms[size_t(f)] = double(elapsed) * double(context.info.timestamp_period_ns) * 1e-6;
    }
    return ms;
}

} // namespace

double host_clock_ms(FrameTimer timer)
{
    if (timer == FrameTimer::cpu_time) {
        timespec t{};
        if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t) != 0)
            throw Error("the cpu-time timer: the process's CPU clock cannot be read");
        return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
    }
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::vector<double> time_frames(GpuRenderer& r, int warmup, int frames, FrameTimer timer)
{
    return time_frames_interleaved({&r}, warmup, frames, timer)[0];
}

std::vector<std::vector<double>> time_frames_interleaved(const std::vector<GpuRenderer*>& renderers, int warmup,
                                                         int frames, FrameTimer timer)
{
    if (warmup < 0 || frames < 1)
        throw Error("time_frames: need at least one timed frame");
    if (timer != FrameTimer::timestamps)
        return time_on_host_in_turn(renderers, warmup, frames, timer);
    std::vector<std::vector<double>> ms;
    for (GpuRenderer* r : renderers)
        ms.push_back(time_with_timestamps(*r, warmup, frames));
    return ms;
}

FrameTimer parse_frame_timer(const std::string& name)
{
    if (name == "timestamps")
        return FrameTimer::timestamps;
    if (name == "wall-clock")
        return FrameTimer::wall_clock;
    if (name == "cpu-time")
        return FrameTimer::cpu_time;
    throw Error("unknown timer '" + name + "' (expected timestamps, wall-clock or cpu-time)");
}

std::string to_string(FrameTimer timer)
{
    return timer == FrameTimer::timestamps ? "timestamps" : timer == FrameTimer::wall_clock ? "wall-clock" : "cpu-time";
}

std::vector<double> time_commands(const VulkanContext& context, const std::function<void(VkCommandBuffer)>& record,
                                  int warmup, int repeats, FrameTimer timer)
{
    if (warmup < 0 || repeats < 1)
        throw Error("time_commands: need at least one timed run");
    for (int w = 0; w < warmup; ++w)
        submit_and_wait(context, record);
    std::vector<double> ms;
    if (timer != FrameTimer::timestamps) {
        for (int r = 0; r < repeats; ++r) {
            const double start = host_clock_ms(timer);
            submit_and_wait(context, record);
            ms.push_back(host_clock_ms(timer) - start);
        }
        return ms;
    }
    VkDevice device = context.device;
    Cleanup cleanup;
    const VkQueryPool pool = create_timestamp_pool(context, 2, cleanup);
    const uint64_t mask = timestamp_mask(context);
    for (int r = 0; r < repeats; ++r) {
        submit_and_wait(context, [&](VkCommandBuffer cb) {
            vkCmdResetQueryPool(cb, pool, 0, 2);
            vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, pool, 0);
            record(cb);
            vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool, 1);
        });
        uint64_t ticks[2] = {};
        TF_VK(vkGetQueryPoolResults(device, pool, 0, 2, sizeof ticks, ticks, sizeof(uint64_t),
                                    VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
        ms.push_back(double((ticks[1] - ticks[0]) & mask) * double(context.info.timestamp_period_ns) * 1e-6);
    }
    return ms;
}

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values.at(values.size() / 2);
}

} // namespace tf
