#include "vulkan/resource_images.h"

#include "texture/error.h"
#include "vulkan/barriers.h"
#include "vulkan/cleanup.h"
#include "vulkan/image.h"
#include "vulkan/resources.h"
#include <cstring>

namespace tf {

// Every level of every chain into layer k of `g` (texel_bytes a texel: RGBA32F, or D32 from .r), one
// level at a time through one staging buffer of level 0's size; the image ends SHADER_READ_ONLY.
void upload_layers(const VulkanContext& context, const GpuImage& g, const std::vector<MipChain>& chains,
                   VkImageAspectFlags aspect, bool depth_only)
{
    const Image& base = chains.at(0).levels.at(0);
    const size_t texel_bytes = depth_only ? sizeof(float) : sizeof(glm::vec4);
    Buffer staging = create_host_buffer(context, base.texels.size() * texel_bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    Cleanup cleanup;
    cleanup.add([&] { destroy_buffer(context, staging); });
    submit_and_wait(context, [&](VkCommandBuffer cb) {
        image_barrier(cb, g.image, VK_REMAINING_MIP_LEVELS, VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, aspect,
                      VK_REMAINING_ARRAY_LAYERS);
    });
    for (size_t layer = 0; layer < chains.size(); ++layer)
        for (size_t l = 0; l < chains[layer].levels.size(); ++l) {
            const Image& level = chains[layer].levels[l];
            if (depth_only) {
                float* out = static_cast<float*>(staging.mapped);
                for (size_t i = 0; i < level.texels.size(); ++i)
                    out[i] = level.texels[i].r;
            } else {
                std::memcpy(staging.mapped, level.texels.data(), level.texels.size() * sizeof(glm::vec4));
            }
            VkBufferImageCopy copy{};
            copy.imageSubresource = {aspect, uint32_t(l), uint32_t(layer), 1};
            copy.imageExtent = {uint32_t(level.width), uint32_t(level.height), 1};
            // The fence wait orders the copy's reads before the next level's host writes.
            submit_and_wait(context, [&](VkCommandBuffer cb) {
                vkCmdCopyBufferToImage(cb, staging.buffer, g.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
            });
        }
    submit_and_wait(context, [&](VkCommandBuffer cb) {
        image_barrier(cb, g.image, VK_REMAINING_MIP_LEVELS, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT,
                      VK_PIPELINE_STAGE_TRANSFER_BIT,
                      VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, aspect,
                      VK_REMAINING_ARRAY_LAYERS);
    });
}

namespace {

// A one-layer 2D_ARRAY view of a one-level 2D colour image (Vulkan allows it for any 2D image).
VkImageView array_view(const VulkanContext& context, VkImage image, VkFormat format)
{
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    view.format = format;
    view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView out = VK_NULL_HANDLE;
    TF_VK(vkCreateImageView(context.device, &view, nullptr, &out));
    return out;
}

} // namespace

void check_shadow_format(const VulkanContext& context, bool linear)
{
    VkFormatProperties3 features3{VK_STRUCTURE_TYPE_FORMAT_PROPERTIES_3};
    VkFormatProperties2 properties{VK_STRUCTURE_TYPE_FORMAT_PROPERTIES_2};
    properties.pNext = &features3;
    vkGetPhysicalDeviceFormatProperties2(context.physical, shadow_depth_format, &properties);
    const VkFormatFeatureFlags2 have = features3.optimalTilingFeatures;
    const std::pair<VkFormatFeatureFlags2, const char*> needed[] = {
        {VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_BIT, "SAMPLED_IMAGE"},
        {VK_FORMAT_FEATURE_2_TRANSFER_DST_BIT, "TRANSFER_DST"},
        {VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_DEPTH_COMPARISON_BIT, "SAMPLED_IMAGE_DEPTH_COMPARISON"},
        {VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_FILTER_LINEAR_BIT, "SAMPLED_IMAGE_FILTER_LINEAR"},
    };
    std::string missing;
    for (const auto& [bit, name] : needed)
        if (!(have & bit) && (linear || bit != VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_FILTER_LINEAR_BIT))
            missing += (missing.empty() ? "" : ", ") + std::string(name);
    if (!missing.empty())
        throw Error("--resource shadow: " + context.info.name + " lacks " + missing +
                    " for VK_FORMAT_D32_SFLOAT (optimal tiling), which the shadow kind samples" +
                    (linear ? " with the hardware's linear comparison lookups (hw-bilinear, hw-trilinear, --taps "
                              "hardware; the manual filters need no linear filtering)"
                            : ""));
}

GpuResources upload_resources(const VulkanContext& context, const std::vector<MipChain>& chains, Resource resource,
                              bool with_sat)
{
    if (chains.empty())
        throw Error("upload_resources: no texture");
    const Image& level0 = chains[0].levels.at(0);
    for (const MipChain& c : chains)
        if (c.levels.size() != chains[0].levels.size() || c.levels.at(0).width != level0.width ||
            c.levels.at(0).height != level0.height)
            throw Error("upload_resources: the layers differ in size");
    GpuResources r;
    r.resource = resource;
    r.width = level0.width;
    r.height = level0.height;
    r.levels = int(chains[0].levels.size());
    r.layers = int(chains.size());
    Cleanup on_failure;
    on_failure.add([&] { destroy_resources(context, r); });
    r.base = upload_texture(context, chains[0], with_sat);
    const uint32_t w = uint32_t(r.width), h = uint32_t(r.height), levels = uint32_t(r.levels);
    const VkImageUsageFlags layer_usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if (resource == Resource::array || resource == Resource::separate_array) {
        r.sat_low_array = array_view(context, r.base.sat_low.image, VK_FORMAT_R32G32B32A32_UINT);
        r.sat_high_array = array_view(context, r.base.sat_high.image, VK_FORMAT_R32_UINT);
        r.layered = create_image(context, VK_FORMAT_R32G32B32A32_SFLOAT, w, h, levels, layer_usage,
                                 VK_IMAGE_ASPECT_COLOR_BIT, uint32_t(r.layers), VK_IMAGE_VIEW_TYPE_2D_ARRAY);
        upload_layers(context, r.layered, chains, VK_IMAGE_ASPECT_COLOR_BIT, false);
    } else if (resource == Resource::bindless) {
        for (size_t k = 1; k < chains.size(); ++k)
            r.textures.push_back(upload_texture(context, chains[k], false));
    } else if (resource == Resource::shadow) {
        r.depth = create_image(context, shadow_depth_format, w, h, levels, layer_usage, VK_IMAGE_ASPECT_DEPTH_BIT);
        upload_layers(context, r.depth, chains, VK_IMAGE_ASPECT_DEPTH_BIT, true);
    }
    on_failure.dismiss();
    return r;
}

GpuResources upload_texel_source(const VulkanContext& context, const SourceBinding& source)
{
    const Image& level0 = source.image.levels.at(0);
    GpuResources r;
    r.resource = source.kind;
    r.width = level0.width;
    r.height = level0.height;
    r.levels = int(source.image.levels.size());
    Cleanup on_failure;
    on_failure.add([&] { destroy_resources(context, r); });
    r.base = upload_texture(context, source.image, false);
    const size_t bytes = source.words.size() * sizeof(int32_t);
    r.source = create_host_buffer(context, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    std::memcpy(r.source.mapped, source.words.data(), bytes);
    on_failure.dismiss();
    return r;
}

void destroy_resources(const VulkanContext& context, GpuResources& resources)
{
    for (VkImageView view : {resources.sat_low_array, resources.sat_high_array})
        if (view)
            vkDestroyImageView(context.device, view, nullptr);
    destroy_texture(context, resources.base);
    destroy_image(context, resources.layered);
    for (GpuTexture& t : resources.textures)
        destroy_texture(context, t);
    destroy_image(context, resources.depth);
    destroy_buffer(context, resources.source);
    resources = GpuResources{};
}

} // namespace tf
