#include "vulkan/samplers.h"
#include "texture/error.h"
#include <algorithm>

namespace tf {

VkSamplerCreateInfo sampler_create_info(const VulkanContext& context, const SamplerOptions& options, int levels)
{
    VkSamplerAddressMode address = options.wrap == Wrap::clamp    ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE
                                   : options.wrap == Wrap::mirror ? VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT
                                                                  : VK_SAMPLER_ADDRESS_MODE_REPEAT;
    bool nearest = options.filter == Filter::hw_nearest;
    bool level0_only = options.filter == Filter::hw_nearest || options.filter == Filter::hw_bilinear;
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = info.minFilter = nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
    info.mipmapMode = level0_only ? VK_SAMPLER_MIPMAP_MODE_NEAREST : VK_SAMPLER_MIPMAP_MODE_LINEAR;
    info.addressModeU = info.addressModeV = info.addressModeW = address;
    float max_bias = context.info.max_sampler_lod_bias;
    if (is_hardware(options.filter) && (options.lod_bias > max_bias || options.lod_bias < -max_bias))
        throw Error("--lod-bias " + std::to_string(options.lod_bias) + " exceeds this device's maxSamplerLodBias " +
                    std::to_string(max_bias) + " for hardware filters");
    bool hw = is_hardware(options.filter);
    // Manual filters apply bias and LOD clamps in the shader; hardware taps ask for explicit LODs.
    info.mipLodBias = hw ? options.lod_bias : 0.0f;
    info.minLod = level0_only || !hw ? 0.0f : options.lod_min;
    info.maxLod = level0_only ? 0.0f : hw ? std::min(options.lod_max, float(levels - 1)) : float(levels - 1);
    if (info.minLod > info.maxLod)
        info.minLod = info.maxLod;
    if (options.filter == Filter::hw_aniso) {
        if (!context.info.sampler_anisotropy)
            throw Error(context.info.name + " does not support anisotropic filtering (samplerAnisotropy)");
        info.anisotropyEnable = VK_TRUE;
        info.maxAnisotropy = std::min(float(options.aniso), context.info.max_sampler_anisotropy);
    }
    info.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
    return info;
}

VkSampler create_sampler(const VulkanContext& context, const SamplerOptions& options, int levels)
{
    const VkSamplerCreateInfo info = sampler_create_info(context, options, levels);
    VkSampler sampler = VK_NULL_HANDLE;
    TF_VK(vkCreateSampler(context.device, &info, nullptr, &sampler));
    return sampler;
}

PassSamplers create_pass_samplers(const VulkanContext& context, const GpuTexture& texture,
                                  const SamplerOptions& options, Cleanup& cleanup)
{
    VkDevice device = context.device;
    PassSamplers samplers;
    // A format the sampler cannot filter (integer data, or no SAMPLED_IMAGE_FILTER_LINEAR on this device) is
    // bound with a nearest sampler: the manual filters read it with texelFetch, which ignores the sampler,
    // and the commands refuse hardware filtering of it before they start (check_format_support).
    SamplerOptions texture_options = options;
    if (!texture.filterable && !is_hardware(options.filter)) {
        texture_options.filter = Filter::hw_nearest;
        texture_options.lod_bias = 0.0f; // the shader applies the manual filters' bias
    }
    VkSampler texture_sampler = samplers.texture = create_sampler(context, texture_options, texture.levels);
    cleanup.add([=] { vkDestroySampler(device, texture_sampler, nullptr); });
    SamplerOptions nearest;
    nearest.filter = Filter::hw_nearest;
    VkSampler table_sampler = samplers.table = create_sampler(context, nearest, 1);
    cleanup.add([=] { vkDestroySampler(device, table_sampler, nullptr); });
    samplers.infos[0] = {samplers.texture, texture.chain.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    samplers.infos[1] = {samplers.table, texture.sat_low.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    samplers.infos[2] = {samplers.table, texture.sat_high.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    return samplers;
}

} // namespace tf
