#include "vulkan/sample.h"
#include "core/texel_sources.h"
#include "harness/config.h"
#include "texture/error.h"
#include "vulkan/backend.h"
#include "vulkan/pipelines.h"
#include "vulkan/render.h"
#include "vulkan/textures.h"
#include <algorithm>
#include <cstdint>
#include <cstring>

namespace tf {

// `sample`: point lookups through the compute harness (sample.comp.glsl), one invocation or one subgroup
// a lookup, colours and per-lookup stats read back.
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

namespace {

// The work groups of `count` lookups: hw-* lookups take a whole subgroup each, laid out as 2x2 quads (see
// sample.comp.glsl). Throws where the device's subgroups cannot hold the quads or one pass cannot run them.
VkExtent2D sample_groups(const VulkanContext& context, const SamplerOptions& options, size_t count)
{
    const bool quads = HARNESS_SAMPLE_IN_QUADS(int(options.filter));
    const uint32_t subgroup = context.info.subgroup_size;
    if (quads && (subgroup == 0 || subgroup % 4 != 0 || HARNESS_SAMPLE_LOCAL_SIZE % subgroup != 0))
        throw Error("sample --filter " + to_string(options.filter) + " gives each lookup a subgroup of 2x2 quads, "
                    "which subgroups of " + std::to_string(subgroup) + " invocations on " + context.info.name +
                    " cannot hold");
    const uint64_t invocations = uint64_t(count) * (quads ? subgroup : 1);
    const uint64_t groups = (invocations + HARNESS_SAMPLE_LOCAL_SIZE - 1) / HARNESS_SAMPLE_LOCAL_SIZE;
    const uint32_t groups_x = uint32_t(std::min<uint64_t>(groups, 65535)); // maxComputeWorkGroupCount >= 65535
    const uint64_t groups_y = (groups + groups_x - 1) / groups_x;
    if (groups_y > 65535 || groups * HARNESS_SAMPLE_LOCAL_SIZE > UINT32_MAX) // invocation indices are 32-bit
        throw Error(std::to_string(count) + " lookups are more than one sample pass can run");
    return {groups_x, uint32_t(groups_y)};
}

} // namespace

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
    const VkExtent2D groups = sample_groups(context, options, lookups.size());
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
            vkCmdDispatch(cb, groups.width, groups.height, 1);
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

namespace {

// The filter's sampler (hw-* state, or trilinear with the wrap mode for hardware taps), as for the combined
// kind; shadow adds the depth comparison (Vulkan compares each texel before filtering).
VkSampler resource_sampler(const VulkanContext& context, const GpuResources& resources, const SamplerOptions& options,
                           const ResourceOptions& resource, Cleanup& cleanup)
{
    VkDevice device = context.device;
    VkSamplerCreateInfo info = sampler_create_info(context, options, resources.levels);
    if (resource.resource == Resource::shadow) {
        info.compareEnable = VK_TRUE;
        info.compareOp = VkCompareOp(resource.compare);
        // The manual filters only texelFetch the depth image; a nearest sampler keeps them free of the
        // linear-filter feature depth formats need not have.
        if (!uses_hardware_lookups(options)) {
            info.magFilter = info.minFilter = VK_FILTER_NEAREST;
            info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
        }
    }
    VkSampler sampler = VK_NULL_HANDLE;
    TF_VK(vkCreateSampler(device, &info, nullptr, &sampler));
    cleanup.add([=] { vkDestroySampler(device, sampler, nullptr); });
    return sampler;
}

// What the kind binds at HARNESS_BINDING_TEXTURE: one image, or the bindless array.
std::vector<VkDescriptorImageInfo> resource_textures(const GpuResources& resources, const HarnessVariant& variant,
                                                    const ResourceOptions& resource, VkSampler sampler)
{
    const VkImageLayout read = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    const VkSampler texture_sampler = variant.separate_sampler ? VK_NULL_HANDLE : sampler;
    std::vector<VkDescriptorImageInfo> textures;
    switch (resource.resource) {
    case Resource::combined:
    case Resource::separate: textures.push_back({texture_sampler, resources.base.chain.view, read}); break;
    case Resource::array:
    case Resource::separate_array: textures.push_back({texture_sampler, resources.layered.view, read}); break;
    case Resource::bindless:
        textures.push_back({texture_sampler, resources.base.chain.view, read});
        for (const GpuTexture& t : resources.textures)
            textures.push_back({texture_sampler, t.chain.view, read});
        break;
    case Resource::shadow: textures.push_back({texture_sampler, resources.depth.view, read}); break;
    case Resource::atlas:
    case Resource::virtual_texture: textures.push_back({texture_sampler, resources.base.chain.view, read}); break;
    }
    if (textures.size() != variant.texture_count)
        throw Error("--resource " + to_string(resource.resource) + ": the shader binds " +
                    std::to_string(variant.texture_count) + " textures, the resource holds " +
                    std::to_string(textures.size()));
    return textures;
}

} // namespace

Pass create_resource_pass(const VulkanContext& context, const GpuResources& resources, const HarnessVariant& variant,
                          const SamplerOptions& options, const ResourceOptions& resource, VkShaderStageFlags stages,
                          const std::vector<PassBuffer>& buffers, Cleanup& cleanup)
{
    const VkSampler sampler = resource_sampler(context, resources, options, resource, cleanup);
    // The SAT placeholders (1x1 zeros) with the base texture's own pass samplers.
    const PassSamplers base = create_pass_samplers(context, resources.base, options, cleanup);

    const VkImageLayout read = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    const std::vector<VkDescriptorImageInfo> textures = resource_textures(resources, variant, resource, sampler);
    // The summed-area table as the kind declares it (filter_select.glsl): usampler2D, utexture2D for the
    // separate kinds, arrays of one layer (views of the same images) for the array kinds.
    VkDescriptorImageInfo low = base.infos[1], high = base.infos[2];
    if (resources.sat_low_array) {
        low.imageView = resources.sat_low_array;
        high.imageView = resources.sat_high_array;
    }
    if (variant.table_type == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE)
        low.sampler = high.sampler = VK_NULL_HANDLE;
    std::vector<PassImages> images = {{HARNESS_BINDING_TEXTURE, variant.texture_type, textures},
                                      {HARNESS_BINDING_SAT_LOW, variant.table_type, {low}},
                                      {HARNESS_BINDING_SAT_HIGH, variant.table_type, {high}}};
    if (variant.separate_sampler)
        images.push_back({HARNESS_BINDING_SAMPLER, VK_DESCRIPTOR_TYPE_SAMPLER, {{sampler, VK_NULL_HANDLE, read}}});
    std::vector<PassBuffer> all = buffers;
    if (is_texel_source(resource.resource)) // the words texel_sources.glsl reads
        all.push_back({HARNESS_BINDING_SOURCE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, resources.source.buffer});
    return create_pass_with_images(context, images, stages, stages, all, cleanup);
}

void check_resource_options(const SamplerOptions& options, const ResourceOptions& resource)
{
    const std::string kind = "--resource " + to_string(resource.resource);
    const bool sat = options.filter == Filter::sat || options.filter == Filter::sat_assembly;
    if (is_texel_source(resource.resource)) {
        // The includes' TF_SOURCE overloads are the manual forms: texels through tf_source_fetch, no sampler.
        if (sat)
            throw Error(kind + " cannot run --filter " + to_string(options.filter) +
                        ": the summed-area table is built for one texture of its own, not texels read through "
                        "TF_SOURCE (use --resource combined or separate)");
        if (options.filter == Filter::ewa_fast)
            throw Error(kind + " cannot run --filter ewa-fast: its lookups filter a sampler's texture, and the "
                        "texels come through TF_SOURCE (use --filter ewa)");
        if (options.taps == Taps::hardware)
            throw Error(kind + " cannot run --taps hardware: a hardware tap filters a sampler's texture, and the "
                        "texels come through TF_SOURCE (use --taps manual)");
        if (is_hardware(options.filter) && resource.resource != Resource::atlas)
            throw Error(kind + " cannot run --filter " + to_string(options.filter) +
                        ": the hardware sampler would filter the physical texture's shuffled pages (use a manual "
                        "filter)");
    }
    if (sat && resource.resource != Resource::combined && resource.resource != Resource::separate)
        throw Error(kind + " cannot run --filter " + to_string(options.filter) +
                    ": the summed-area table is built for one colour texture (use --resource combined or separate)");
    if (resource.resource == Resource::bindless && resource.layers != bindless_texture_count)
        throw Error("--resource bindless: the harness's array holds HARNESS_BINDLESS_COUNT = " +
                    std::to_string(bindless_texture_count) + " textures, so --layers must be " +
                    std::to_string(bindless_texture_count) + " (not " + std::to_string(resource.layers) + ")");
    if (resource.resource == Resource::shadow && options.filter == Filter::hw_aniso)
        throw Error(kind + " cannot run --filter hw-aniso: the footprint of a hardware anisotropic comparison is "
                    "implementation-defined, so nothing can check it (use aniso or ewa, with --taps hardware for "
                    "hardware comparison taps)");
}

void check_resource_device(const VulkanContext& context, const SamplerOptions& options,
                           const ResourceOptions& resource)
{
    if (resource.resource == Resource::bindless && !context.info.sampled_image_array_non_uniform_indexing)
        throw Error("--resource bindless needs shaderSampledImageArrayNonUniformIndexing (Vulkan 1.2 descriptor "
                    "indexing), which " + context.info.name + " does not offer");
    if (resource.resource == Resource::shadow)
        check_shadow_format(context, uses_hardware_lookups(options) && options.filter != Filter::hw_nearest);
}

void check_source_device(const VulkanContext& context, Resource kind, int width, int height)
{
    check_source_size(kind, width, height, int(std::min<uint32_t>(context.info.max_image_dimension_2d, 1u << 30)));
}

std::vector<glm::vec4> gpu_sample_resource(const VulkanContext& context, const GpuResources& resources,
                                           const std::vector<Lookup>& lookups, const SamplerOptions& options,
                                           const ResourceOptions& resource, std::vector<LookupStats>* stats,
                                           ShaderCode shader)
{
    check_resource_options(options, resource);
    check_resource_device(context, options, resource);
    if (resource.resource != resources.resource)
        throw Error("gpu_sample_resource: the images were uploaded for --resource " + to_string(resources.resource));
    const HarnessVariant variant = harness_variant(resource.resource, uint32_t(resources.layers));
    return run_sample_pass(
        context, lookups, options, stats, shader.words ? shader : variant.sample,
        [&](const std::vector<PassBuffer>& buffers, Cleanup& cleanup) {
            return create_resource_pass(context, resources, variant, options, resource, VK_SHADER_STAGE_COMPUTE_BIT,
                                        buffers, cleanup);
        },
        [&](PushConstants& push) {
            const GpuTexture& t = resources.base;
            std::copy(&t.sat_offset.x, &t.sat_offset.x + 4, push.sat_offset);
            std::copy(&t.sat_scale.x, &t.sat_scale.x + 4, push.sat_scale);
            push.layer = resource.layer;
            push.compare_op = int32_t(resource.compare);
            push.dref = resource.dref;
        });
}

} // namespace tf
