// `sample`: point lookups through the compute harness (sample.comp.glsl), one invocation or one subgroup
// a lookup, colours and per-lookup stats read back.
#include "vulkan/backend.h"
#include "vulkan/sample_pass.h"
#include "harness/config.h"
#include "texture/error.h"
#include "vulkan/harness_shaders.h"
#include "vulkan/pass.h"
#include "vulkan/pipeline.h"
#include "vulkan/readback.h"
#include <algorithm>
#include <cstdint>
#include <cstring>

namespace tf {

std::vector<glm::vec4> gpu_sample(const VulkanContext& context, const GpuTexture& texture,
                                  const std::vector<Lookup>& lookups, const SamplerOptions& options,
                                  std::vector<LookupStats>* stats,
                                  const std::function<void(VkCommandBuffer)>& prelude)
{
    return gpu_sample_with_shader(context, texture, lookups, options,
                                  harness_shader(HarnessShader::sample_comp, texture.format), stats, prelude);
}

std::vector<glm::vec4> gpu_sample_with_shader(const VulkanContext& context, const GpuTexture& texture,
                                              const std::vector<Lookup>& lookups, const SamplerOptions& options,
                                              ShaderCode shader, std::vector<LookupStats>* stats,
                                              const std::function<void(VkCommandBuffer)>& prelude)
{
    return run_sample_pass(
        context, lookups, options, stats, shader,
        [&](const std::vector<PassBuffer>& buffers, Cleanup& cleanup) {
            return create_pass(context, texture, options, VK_SHADER_STAGE_COMPUTE_BIT, VK_SHADER_STAGE_COMPUTE_BIT,
                               buffers, cleanup);
        },
        [&](PushConstants& push) {
            std::copy(&texture.sat_offset.x, &texture.sat_offset.x + 4, push.sat_offset);
            std::copy(&texture.sat_scale.x, &texture.sat_scale.x + 4, push.sat_scale);
        },
        prelude);
}

std::vector<glm::vec4> run_sample_pass(const VulkanContext& context, const std::vector<Lookup>& lookups,
                                       const SamplerOptions& options, std::vector<LookupStats>* stats,
                                       ShaderCode code, const MakeSamplePass& make_pass,
                                       const std::function<void(PushConstants&)>& adjust_push,
                                       const std::function<void(VkCommandBuffer)>& prelude)
{
    if (lookups.empty()) { // as the reference backend: no lookups, no results (and no zero-sized buffers)
        if (stats)
            stats->clear();
        return {};
    }
    // hw-* lookups take a whole subgroup each, laid out as 2x2 quads (see sample.comp.glsl).
    const bool quads = HARNESS_SAMPLE_IN_QUADS(int(options.filter));
    const uint32_t subgroup = context.info.subgroup_size;
    if (quads && (subgroup == 0 || subgroup % 4 != 0 || HARNESS_SAMPLE_LOCAL_SIZE % subgroup != 0))
        throw Error("sample --filter " + to_string(options.filter) + " gives each lookup a subgroup of 2x2 quads, "
                    "which subgroups of " + std::to_string(subgroup) + " invocations on " + context.info.name +
                    " cannot hold");
    const uint64_t invocations = uint64_t(lookups.size()) * (quads ? subgroup : 1);
    const uint64_t groups = (invocations + HARNESS_SAMPLE_LOCAL_SIZE - 1) / HARNESS_SAMPLE_LOCAL_SIZE;
    const uint32_t groups_x = uint32_t(std::min<uint64_t>(groups, 65535)); // maxComputeWorkGroupCount >= 65535
    const uint64_t groups_y = (groups + groups_x - 1) / groups_x;
    if (groups_y > 65535 || groups * HARNESS_SAMPLE_LOCAL_SIZE > UINT32_MAX) // invocation indices are 32-bit
        throw Error(std::to_string(lookups.size()) + " lookups are more than one sample pass can run");
    Cleanup cleanup;
    const uint32_t count = uint32_t(lookups.size());
    auto storage = [&](VkDeviceSize bytes) {
        Buffer buffer = create_host_buffer(context, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        cleanup.add([&context, buffer]() mutable { destroy_buffer(context, buffer); });
        return buffer;
    };
    const Buffer input = storage(VkDeviceSize(count) * sizeof(LookupRecord));
    const Buffer output = storage(VkDeviceSize(count) * sizeof(glm::vec4));
    const Buffer counts = storage(VkDeviceSize(count) * sizeof(LookupStats));
    LookupRecord* in = static_cast<LookupRecord*>(input.mapped);
    for (uint32_t i = 0; i < count; ++i) {
        const Lookup& l = lookups[i];
        in[i] = {float(l.u), float(l.v), float(l.dudx), float(l.dvdx), float(l.dudy), float(l.dvdy)};
    }

    const Pass pass = make_pass({{HARNESS_BINDING_LOOKUPS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, input.buffer},
                                 {HARNESS_BINDING_RESULTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, output.buffer},
                                 {HARNESS_BINDING_STATS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, counts.buffer}},
                                cleanup);
    const VkPipeline pipeline = create_compute_pipeline(context, code, pass.pipeline_layout, filter_variant(options), cleanup);
    PushConstants push = make_push_constants(options, count, glm::vec4(0.0f), glm::vec4(0.0f));
    adjust_push(push);
    // --stochastic --accumulate N: one dispatch a frame (each its own random numbers), the mean summed in
    // double as gpu_render's; the stats are the first frame's (every frame reads one texel or tap a lookup).
    const int frames = options.stochastic ? options.accumulate : 1;
    std::vector<glm::dvec4> sum(frames > 1 ? count : 0, glm::dvec4(0.0));
    std::vector<glm::vec4> results(count);
    for (int f = 0; f < frames; ++f) {
        push.stochastic = stochastic_push(options, options.stochastic_first + uint32_t(f));
        submit_and_wait(context, [&](VkCommandBuffer cb) {
            if (prelude && f == 0)
                prelude(cb);
            bind_pass(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline, pass, push);
            vkCmdDispatch(cb, groups_x, uint32_t(groups_y), 1);
            record_host_read(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT);
        });
        std::memcpy(results.data(), output.mapped, results.size() * sizeof(glm::vec4));
        if (stats && f == 0) {
            stats->resize(count);
            std::memcpy(stats->data(), counts.mapped, stats->size() * sizeof(LookupStats));
        }
        for (size_t i = 0; i < sum.size(); ++i)
            sum[i] += glm::dvec4(results[i]);
    }
    for (size_t i = 0; i < sum.size(); ++i)
        results[i] = glm::vec4(sum[i] / double(frames));
    return results;
}

} // namespace tf