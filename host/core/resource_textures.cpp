#include "core/resource_textures.h"

#include "texture/error.h"

#include <algorithm>
#include <cmath>

namespace tf {

namespace {

// A colour for layer k: the low bits of k pick the channels, the rest a shade (distinct for k < 64).
glm::vec4 layer_colour(int k)
{
    const float shade = 1.0f - 0.125f * float((k / 8) % 8);
    return glm::vec4((k & 1) ? shade : 0.0f, (k & 2) ? shade : 0.0f, (k & 4) ? shade : 0.2f, 0.0f);
}

} // namespace

MipChain make_layer(const MipChain& base, int layer)
{
    if (layer < 0)
        throw Error("layer " + std::to_string(layer) + " is negative");
    if (layer == 0)
        return base;
    const glm::vec4 colour = layer_colour(layer);
    MipChain chain = base;
    for (Image& level : chain.levels)
        for (glm::vec4& t : level.texels) {
            const glm::vec4 in = t;
            for (int c = 0; c < 3; ++c)
                t[c] = 0.5f * in[(c + layer) % 3] + 0.5f * colour[c];
        }
    return chain;
}

MipChain make_depth_chain(const MipChain& base)
{
    Image depth = base.levels.at(0);
    for (glm::vec4& t : depth.texels) {
        const double luminance = 0.2126 * t.r + 0.7152 * t.g + 0.0722 * t.b;
        const float d = std::isfinite(luminance) ? float(std::clamp(luminance, 0.0, 1.0)) : 0.0f;
        t = glm::vec4(d, 0.0f, 0.0f, 1.0f);
    }
    return build_mip_chain(std::move(depth));
}

std::vector<MipChain> make_resource_chains(const MipChain& base, const ResourceOptions& options)
{
    if (options.resource == Resource::shadow)
        return {make_depth_chain(base)};
    if (!is_layered(options.resource))
        return {base};
    std::vector<MipChain> chains;
    for (int k = 0; k < options.layers; ++k)
        chains.push_back(make_layer(base, k));
    return chains;
}

} // namespace tf
