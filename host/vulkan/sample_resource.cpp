#include "vulkan/sample_resource.h"

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
    if (resource.resource != Resource::combined && (options.filter == Filter::sat || options.filter == Filter::sat_assembly))
        throw Error(kind + " cannot run --filter " + to_string(options.filter) +
                    ": the summed-area table is built for the combined texture only (use --resource combined)");
    if (resource.resource == Resource::shadow && options.filter == Filter::hw_aniso)
        throw Error(kind + " cannot run --filter hw-aniso: the footprint of a hardware anisotropic comparison is "
                    "implementation-defined, so nothing can check it (use aniso or ewa, with --taps hardware for "
                    "hardware comparison taps)");
}

void check_resource_device(const VulkanContext& context, const ResourceOptions& resource)
{
    if (resource.resource == Resource::bindless && !context.info.sampled_image_array_non_uniform_indexing)
        throw Error("--resource bindless needs shaderSampledImageArrayNonUniformIndexing (Vulkan 1.2 descriptor "
                    "indexing), which " + context.info.name + " does not offer");
    if (resource.resource == Resource::shadow)
        check_shadow_format(context);
}

std::vector<glm::vec4> gpu_sample_resource(const VulkanContext& context, const GpuResources& resources,
                                           const std::vector<Lookup>& lookups, const SamplerOptions& options,
                                           const ResourceOptions& resource, std::vector<LookupStats>* stats)
{
    check_resource_options(options, resource);
    check_resource_device(context, resource);
    if (resource.resource != resources.resource)
        throw Error("gpu_sample_resource: the images were uploaded for --resource " + to_string(resources.resource));
    const HarnessVariant variant = harness_variant(resource.resource, uint32_t(resources.layers));
    return run_sample_pass(
        context, lookups, options, stats, variant.sample,
        [&](const std::vector<PassBuffer>& buffers, Cleanup& cleanup) {
            return create_resource_pass(context, resources, variant, options, resource, VK_SHADER_STAGE_COMPUTE_BIT,
                                        buffers, cleanup);
        },
        [&](PushConstants& push) {
            (void)push; // TODO(after the access layer): layer, compareOp, dref
        });
}

} // namespace tf
