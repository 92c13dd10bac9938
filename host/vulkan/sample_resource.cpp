#include "vulkan/sample_resource.h"

#include "core/texel_sources.h"
#include "harness/config.h"
#include "texture/error.h"
#include "vulkan/harness_variant.h"
#include "vulkan/resource_pass.h"
#include "vulkan/sample_pass.h"
#include <algorithm>

namespace tf {

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
