#include "vulkan/texture_format_support.h"
#include "texture/error.h"

namespace tf {

VkFormat vk_format(TextureFormat format)
{
    switch (format) {
    case TextureFormat::rgba32f: return VK_FORMAT_R32G32B32A32_SFLOAT;
    case TextureFormat::rgba8_srgb: return VK_FORMAT_R8G8B8A8_SRGB;
    case TextureFormat::rgba8: return VK_FORMAT_R8G8B8A8_UNORM;
    case TextureFormat::rgba16f: return VK_FORMAT_R16G16B16A16_SFLOAT;
    case TextureFormat::r8: return VK_FORMAT_R8_UNORM;
    case TextureFormat::r16f: return VK_FORMAT_R16_SFLOAT;
    case TextureFormat::r32f: return VK_FORMAT_R32_SFLOAT;
    case TextureFormat::r16ui: return VK_FORMAT_R16_UINT;
    case TextureFormat::r32ui: return VK_FORMAT_R32_UINT;
    }
    throw Error("invalid texture format value " + std::to_string(int(format)));
}

namespace {

VkFormatFeatureFlags optimal_features(const VulkanContext& context, TextureFormat format)
{
    VkFormatProperties properties{};
    vkGetPhysicalDeviceFormatProperties(context.physical, vk_format(format), &properties);
    return properties.optimalTilingFeatures;
}

} // namespace

bool format_filterable(const VulkanContext& context, TextureFormat format)
{
    return (optimal_features(context, format) & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) != 0;
}

void check_format_support(const VulkanContext& context, TextureFormat format, const SamplerOptions& options)
{
    check_format_filter(format, options);
    const VkFormatFeatureFlags features = optimal_features(context, format);
    const VkFormatFeatureFlags upload = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
    if ((features & upload) != upload)
        throw Error("--format " + to_string(format) + ": " + context.info.name +
                    " cannot sample this format from an optimally tiled image it copies into "
                    "(VkFormatProperties::optimalTilingFeatures lacks SAMPLED_IMAGE or TRANSFER_DST)");
    if (needs_hardware_filtering(options) && !(features & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT))
        throw Error("--format " + to_string(format) + ": " + context.info.name +
                    " cannot filter this format linearly (no SAMPLED_IMAGE_FILTER_LINEAR), which --filter " +
                    to_string(options.filter) + (is_hardware(options.filter) ? "" : " --taps hardware") +
                    " needs; use a manual filter or another format");
}

} // namespace tf
