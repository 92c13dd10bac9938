#include "vulkan/command_timer.h"
#include "texture/error.h"
#include <algorithm>

namespace tf {

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
    if (context.info.timestamp_valid_bits == 0 || context.info.timestamp_period_ns <= 0.0f)
        throw Error(context.info.name + " has no timestamps on its graphics and compute queue: use the wall-clock timer");
    VkDevice device = context.device;
    Cleanup cleanup;
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = 2;
    VkQueryPool pool = VK_NULL_HANDLE;
    TF_VK(vkCreateQueryPool(device, &info, nullptr, &pool));
    cleanup.add([=] { vkDestroyQueryPool(device, pool, nullptr); });
    const uint64_t mask = context.info.timestamp_valid_bits >= 64 ? ~0ull : (1ull << context.info.timestamp_valid_bits) - 1;
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
