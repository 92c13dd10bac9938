// `sample`: point lookups through the compute harness (sample.comp.glsl), one invocation or one subgroup
// a lookup, colours and per-lookup stats read back.
#include "vulkan/backend.h"
#include "harness/config.h"
#include "texture/error.h"
#include "vulkan/pass.h"
#include <algorithm>
#include <cstdint>
#include <cstring>

#include "sample_comp.h"

namespace tf {

std::vector<glm::vec4> gpu_sample(const VulkanContext& context, const GpuTexture& texture,
                                  const std::vector<Lookup>& lookups, const SamplerOptions& options,
                                  std::vector<LookupStats>* stats)
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
    VkDevice device = context.device;
    Cleanup cleanup;
    const uint32_t count = uint32_t(lookups.size());
    Buffer input = create_host_buffer(context, VkDeviceSize(count) * sizeof(LookupRecord), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    cleanup.add([&] { destroy_buffer(context, input); });
    Buffer output = create_host_buffer(context, VkDeviceSize(count) * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    cleanup.add([&] { destroy_buffer(context, output); });
    Buffer counts = create_host_buffer(context, VkDeviceSize(count) * sizeof(LookupStats), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    cleanup.add([&] { destroy_buffer(context, counts); });
    LookupRecord* in = static_cast<LookupRecord*>(input.mapped);
    for (uint32_t i = 0; i < count; ++i) {
        const Lookup& l = lookups[i];
        in[i] = {float(l.u), float(l.v), float(l.dudx), float(l.dvdx), float(l.dudy), float(l.dvdy)};
    }

    PassSamplers samplers;
    create_pass_samplers(context, texture, options, samplers, cleanup);
    std::vector<VkDescriptorSetLayoutBinding> bindings = texture_bindings(VK_SHADER_STAGE_COMPUTE_BIT);
    for (uint32_t binding : {HARNESS_BINDING_LOOKUPS, HARNESS_BINDING_RESULTS, HARNESS_BINDING_STATS})
        bindings.push_back({binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
    VkDescriptorSetLayout set_layout = create_set_layout(context, bindings);
    cleanup.add([=] { vkDestroyDescriptorSetLayout(device, set_layout, nullptr); });
    VkPipelineLayout pipeline_layout = create_pipeline_layout(context, set_layout, VK_SHADER_STAGE_COMPUTE_BIT);
    cleanup.add([=] { vkDestroyPipelineLayout(device, pipeline_layout, nullptr); });
    VkPipeline pipeline = create_compute_pipeline(context, sample_comp, sizeof(sample_comp),
                                                  pipeline_layout, options.filter, cleanup);

    DescriptorSet descriptors = allocate_descriptor_set(context, set_layout);
    cleanup.add([=] { vkDestroyDescriptorPool(device, descriptors.pool, nullptr); });
    VkDescriptorBufferInfo in_info{input.buffer, 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo out_info{output.buffer, 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo stats_info{counts.buffer, 0, VK_WHOLE_SIZE};
    std::vector<VkWriteDescriptorSet> writes;
    write_textures(writes, descriptors.set, samplers);
    writes.push_back(write_buffer(descriptors.set, HARNESS_BINDING_LOOKUPS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &in_info));
    writes.push_back(write_buffer(descriptors.set, HARNESS_BINDING_RESULTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &out_info));
    writes.push_back(write_buffer(descriptors.set, HARNESS_BINDING_STATS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &stats_info));
    vkUpdateDescriptorSets(device, uint32_t(writes.size()), writes.data(), 0, nullptr);

    PushConstants push = make_push_constants(options, count, texture.sat_offset, texture.sat_scale, HARNESS_GRADIENTS_FINE);
    submit_and_wait(context, [&](VkCommandBuffer cb) {
        vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
        vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout, 0, 1, &descriptors.set, 0, nullptr);
        vkCmdPushConstants(cb, pipeline_layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
        vkCmdDispatch(cb, groups_x, uint32_t(groups_y), 1);
        VkMemoryBarrier host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        host.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
        host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &host, 0,
                             nullptr, 0, nullptr);
    });
    std::vector<glm::vec4> results(count);
    std::memcpy(results.data(), output.mapped, results.size() * sizeof(glm::vec4));
    if (stats) {
        stats->resize(count);
        std::memcpy(stats->data(), counts.mapped, stats->size() * sizeof(LookupStats));
    }
    return results;
}

} // namespace tf