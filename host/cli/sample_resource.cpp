#include "cli/sample_resource.h"

#include "core/resource_textures.h"
#include "core/texel_sources.h"
#include "reference/resources.h"
#include "texture/error.h"
#include "vulkan/cleanup.h"
#include "vulkan/pipelines.h"
#include "vulkan/sample.h"

namespace tf {

namespace {

constexpr int kMaxLayers = 64; // distinct layer content (core/resource_textures.cpp) and a small upload

// The lookups on uploaded images, which are destroyed afterwards (also when the pass throws).
std::vector<glm::dvec4> sample_on_device(const VulkanContext& context, GpuResources images,
                                         const std::vector<Lookup>& lookups, const SamplerOptions& options,
                                         const ResourceOptions& resource, std::vector<LookupStats>* stats,
                                         ShaderCode shader)
{
    Cleanup cleanup;
    cleanup.add([&] { destroy_resources(context, images); });
    const std::vector<glm::vec4> results =
        gpu_sample_resource(context, images, lookups, options, resource, stats, shader);
    return {results.begin(), results.end()};
}

} // namespace

std::vector<FlagSpec> resource_flags()
{
    return {{"--resource", "K",
             "combined (default), separate (texture2D + sampler), array, separate-array, bindless (sampler2D[] "
             "indexed non-uniformly), shadow (a depth image: PCF), atlas (one tile of an atlas), virtual (pages "
             "and a page table); atlas and virtual read texels through TF_SOURCE: manual taps only, hw-* on the "
             "atlas samples it at the tile's uv (and bleeds)"},
            {"--layers", "N", "array kinds, bindless: layers / textures, 1..64, each distinct (default 4)"},
            {"--layer", "L", "array kinds: the layer read (clamped to 0..N-1 as Vulkan does); bindless: the first "
                             "index, 0..N-1 (lookup i reads (L + i) % N) (default 0)"},
            {"--compare", "OP", "shadow: never, less, equal, less-or-equal (default), greater, not-equal, "
                                "greater-or-equal, always; a texel passes when dref OP depth"},
            {"--dref", "D", "shadow: the reference depth (default 0.5; not clamped)"}};
}

ResourceOptions resource_options_from(const Args& args)
{
    ResourceOptions r;
    r.resource = parse_flag(args, "--resource", "combined", parse_resource);
    const std::string kind = "--resource " + to_string(r.resource);
    const bool layered = is_layered(r.resource);
    for (const char* flag : {"--layers", "--layer"})
        if (args.has(flag) && !layered)
            throw Error(std::string(flag) + " is for --resource array, separate-array or bindless, not " + kind);
    for (const char* flag : {"--compare", "--dref"})
        if (args.has(flag) && r.resource != Resource::shadow)
            throw Error(std::string(flag) + " is for --resource shadow, not " + kind);
    if (layered) {
        // bindless: the harness's array has a fixed size (checked with a message in check_resource_options)
        r.layers = args.get_int("--layers", r.resource == Resource::bindless ? bindless_texture_count : 4, 1,
                                kMaxLayers);
        // Arrays clamp any layer (as the hardware does: checked against the reference); a bindless index
        // past the array is undefined behaviour in the shader, so it must be in range.
        r.layer = r.resource == Resource::bindless ? args.get_int("--layer", 0, 0, r.layers - 1)
                                                   : args.get_int("--layer", 0, -1000000, 1000000);
    }
    if (r.resource == Resource::shadow) {
        r.compare = parse_flag(args, "--compare", "less-or-equal", parse_compare_op);
        r.dref = float(args.get_double("--dref", 0.5, -1e30, 1e30));
    }
    return r;
}

std::vector<glm::dvec4> sample_resource(GpuSession* gpu, const MipChain& chain, const std::vector<Lookup>& lookups,
                                        const SamplerOptions& options, const ResourceOptions& resource,
                                        std::vector<LookupStats>* stats, ShaderCode shader)
{
    check_resource_options(options, resource);
    if (gpu)
        check_resource_device(gpu->context, options, resource); // before any upload
    if (is_texel_source(resource.resource)) {
        const Image& level0 = chain.levels.at(0);
        if (gpu)
            check_source_device(gpu->context, resource.resource, level0.width, level0.height);
        const SourceBinding source = make_source_binding(chain, resource.resource);
        if (!gpu)
            return reference_sample_source(source, lookups, options);
        return sample_on_device(gpu->context, upload_texel_source(gpu->context, source), lookups, options, resource,
                                stats, shader);
    }
    const std::vector<MipChain> chains = make_resource_chains(chain, resource);
    if (!gpu)
        return reference_sample_resource(chains, lookups, options, resource);
    return sample_on_device(gpu->context, upload_resources(gpu->context, chains, resource.resource,
                                                           needs_sat(options.filter)),
                            lookups, options, resource, stats, shader);
}

} // namespace tf
