#include "reference/resources.h"

#include "reference/render.h"
#include "texture/error.h"

namespace tf {

MipChain compare_chain(const MipChain& depth, CompareOp op, double dref)
{
    MipChain chain = depth;
    for (Image& level : chain.levels)
        for (glm::vec4& t : level.texels)
            t = glm::vec4(float(compare_depth(op, dref, double(t.r))));
    return chain;
}

std::vector<glm::dvec4> reference_sample_resource(const std::vector<MipChain>& chains,
                                                  const std::vector<Lookup>& lookups, const SamplerOptions& options,
                                                  const ResourceOptions& resource)
{
    if (chains.empty())
        throw Error("reference_sample_resource: no texture");
    if (resource.resource == Resource::shadow)
        return reference_sample_all(compare_chain(chains[0], resource.compare, double(float(resource.dref))),
                                    lookups, options);
    // Lookups grouped by the texture they read, each group one batch, the results put back in order.
    std::vector<std::vector<size_t>> rows(chains.size());
    for (size_t i = 0; i < lookups.size(); ++i) {
        const size_t t = size_t(texture_index(resource, i));
        if (t >= chains.size())
            throw Error("reference_sample_resource: lookup " + std::to_string(i) + " reads texture " +
                        std::to_string(t) + " of " + std::to_string(chains.size()));
        rows[t].push_back(i);
    }
    std::vector<glm::dvec4> colors(lookups.size());
    for (size_t t = 0; t < chains.size(); ++t) {
        if (rows[t].empty())
            continue;
        std::vector<Lookup> group;
        std::vector<uint32_t> rows_read; // --stochastic: each lookup draws its own row's numbers, as on the device
        for (size_t i : rows[t]) {
            group.push_back(lookups[i]);
            rows_read.push_back(uint32_t(i));
        }
        const std::vector<glm::dvec4> out = reference_sample_all(chains[t], group, options, &rows_read);
        for (size_t k = 0; k < rows[t].size(); ++k)
            colors[rows[t][k]] = out[k];
    }
    return colors;
}

std::vector<glm::dvec4> reference_sample_source(const SourceBinding& source, const std::vector<Lookup>& lookups,
                                                const SamplerOptions& options)
{
    if (!is_hardware(options.filter))
        return reference_sample_all(read_source(source), lookups, options);
    if (source.kind != Resource::atlas)
        throw Error("reference_sample_source: --resource " + to_string(source.kind) + " has no hardware lookups");
    std::vector<Lookup> in_atlas;
    in_atlas.reserve(lookups.size());
    for (const Lookup& l : lookups)
        in_atlas.push_back(atlas_lookup(source, l));
    return reference_sample_all(source.image, in_atlas, options);
}

} // namespace tf
