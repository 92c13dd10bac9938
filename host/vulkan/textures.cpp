#include "vulkan/textures.h"
#include "harness/config.h"
#include "texture/error.h"
#include "texture/sat.h"
#include "vulkan/cleanup.h"
#include "vulkan/device.h"
#include "vulkan/memory.h"
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <thread>

namespace tf {

// Textures onto the device: the MIP chain and the summed-area table as sampled images.
namespace {

// A device-local sampled image of `levels` levels (contents undefined until copied), its memory advised
// to use huge pages where the host can see it (a CPU device: see memory.h).
GpuImage create_sampled_image(const VulkanContext& context, VkFormat format, VkExtent2D extent, uint32_t levels)
{
    GpuImage g = create_image(context, format, extent.width, extent.height, levels,
                              VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
    const HostMapping host(context, g.memory, g.memory_type, g.memory_size);
    advise_huge_pages(host.mapped, host.bytes);
    return g;
}

// Where a copy stands in the image's life: the first copy moves every level from UNDEFINED to
// TRANSFER_DST, the last moves them all on to SHADER_READ_ONLY (a single copy does both).
struct CopyStep {
    bool first = true, last = true;
};

// Copies one level from the start of `staging` into the image and waits, so the staging memory may be
// rewritten at once (the fence wait orders the transfer's reads before the host's next writes).
void copy_level(const VulkanContext& context, const GpuImage& g, uint32_t levels, const Buffer& staging,
                uint32_t level, VkExtent2D extent, CopyStep step)
{
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
    copy.imageExtent = {extent.width, extent.height, 1};
    submit_and_wait(context, [&](VkCommandBuffer cb) {
        if (step.first)
            image_barrier(cb, {.image = g.image, .from = scope::undefined, .to = scope::transfer_dst,
                               .levels = levels});
        vkCmdCopyBufferToImage(cb, staging.buffer, g.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
        if (step.last)
            image_barrier(cb, {.image = g.image, .from = scope::transfer_dst, .to = scope::shader_read,
                               .levels = levels});
    });
}

// A one-level image filled from `bytes` of tightly packed texels.
GpuImage upload_single_level(const VulkanContext& context, VkFormat format, VkExtent2D extent, const void* data,
                             size_t bytes)
{
    GpuImage g = create_sampled_image(context, format, extent, 1);
    Cleanup on_failure;
    on_failure.add([&] { destroy_image(context, g); });
    Buffer staging = create_host_buffer(context, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    Cleanup cleanup;
    cleanup.add([&] { destroy_buffer(context, staging); });
    std::memcpy(staging.mapped, data, bytes);
    copy_level(context, g, 1, staging, 0, extent, {});
    on_failure.dismiss();
    return g;
}

void check_texture_size(const VulkanContext& context, int width, int height, bool with_sat)
{
    const uint32_t limit = context.info.max_image_dimension_2d;
    if (uint32_t(width) > limit || uint32_t(height) > limit)
        throw Error("texture " + std::to_string(width) + "x" + std::to_string(height) +
                    " exceeds the device limit maxImageDimension2D = " + std::to_string(limit));
    if (with_sat && (uint32_t(width) + 1 > limit || uint32_t(height) + 1 > limit))
        throw Error("the summed-area table of a " + std::to_string(width) + "x" + std::to_string(height) +
                    " texture needs one more texel a side than maxImageDimension2D = " + std::to_string(limit));
}

// The summed-area table images, or 1x1 zeros (which keep the descriptor set valid for every filter).
void upload_sat(const VulkanContext& context, const Image* level0, GpuTexture& t)
{
    SatTable sat;
    VkExtent2D extent{1, 1};
    if (level0) {
        sat = build_sat(*level0);
        extent = {uint32_t(sat.width + 1), uint32_t(sat.height + 1)};
    } else {
        sat.low.assign(4, 0u);
        sat.high.assign(1, 0u);
    }
    t.sat_offset = sat.offset;
    t.sat_scale = sat.scale;
    t.sat_low = upload_single_level(context, VK_FORMAT_R32G32B32A32_UINT, extent, sat.low.data(),
                                    sat.low.size() * sizeof(uint32_t));
    t.sat_high = upload_single_level(context, VK_FORMAT_R32_UINT, extent, sat.high.data(),
                                     sat.high.size() * sizeof(uint32_t));
}

} // namespace

void upload_empty_sat(const VulkanContext& context, GpuTexture& texture) { upload_sat(context, nullptr, texture); }

bool needs_sat(Filter filter) { return filter == Filter::sat || filter == Filter::sat_assembly; }

GpuTexture upload_texture(const VulkanContext& context, const MipChain& chain, bool with_sat, TextureFormat format)
{
    const Image& base = chain.levels.at(0);
    check_texture_size(context, base.width, base.height, with_sat);
    check_format_support(context, format, SamplerOptions{});
    GpuTexture t;
    t.format = format;
    t.filterable = format_filterable(context, format);
    t.width = base.width;
    t.height = base.height;
    t.levels = int(chain.levels.size());
    Cleanup on_failure;
    on_failure.add([&] { destroy_texture(context, t); });
    {
        const uint32_t levels = uint32_t(t.levels);
        t.chain = create_sampled_image(context, vk_format(format), {uint32_t(base.width), uint32_t(base.height)},
                                       levels);
        // One staging level at a time (the largest, level 0), reused for every level below it.
        const size_t level0_bytes = base.texels.size() * texel_bytes(format);
        Buffer staging = create_host_buffer(context, level0_bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        Cleanup cleanup;
        cleanup.add([&] { destroy_buffer(context, staging); });
        advise_huge_pages(staging.mapped, level0_bytes);
        for (uint32_t l = 0; l < levels; ++l) {
            const Image& level = chain.levels[l];
            if (format == TextureFormat::rgba32f)
                std::memcpy(staging.mapped, level.texels.data(), level.texels.size() * sizeof(glm::vec4));
            else
                pack_texels(level.texels.data(), level.texels.size(), format, staging.mapped);
            copy_level(context, t.chain, levels, staging, l, {uint32_t(level.width), uint32_t(level.height)},
                       {l == 0, l + 1 == levels});
        }
        upload_sat(context, with_sat ? &base : nullptr, t);
    }
    on_failure.dismiss();
    return t;
}

GpuTexture upload_streamed_texture(const VulkanContext& context, int width, int height,
                                   const std::function<void(glm::vec4* texels)>& fill_level0)
{
    if (width < 1 || height < 1)
        throw Error("texture " + std::to_string(width) + "x" + std::to_string(height) + " is empty");
    check_texture_size(context, width, height, false);
    GpuTexture t;
    t.width = width;
    t.height = height;
    t.levels = mip_level_count(width, height);
    Cleanup on_failure;
    on_failure.add([&] { destroy_texture(context, t); });
    {
        const uint32_t levels = uint32_t(t.levels);
        t.chain = create_sampled_image(context, VK_FORMAT_R32G32B32A32_SFLOAT, {uint32_t(width), uint32_t(height)},
                                       levels);
        const size_t level0_bytes = size_t(width) * size_t(height) * sizeof(glm::vec4);
        Buffer staging = create_host_buffer(context, level0_bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        Cleanup cleanup;
        cleanup.add([&] { destroy_buffer(context, staging); });
        glm::vec4* texels = static_cast<glm::vec4*>(staging.mapped);
        advise_huge_pages(texels, level0_bytes);
        {
            // While level 0 is decoded (one thread), another faults in the staging and the image's memory.
            const HostMapping image_memory(context, t.chain.memory, t.chain.memory_type, t.chain.memory_size);
            std::thread prefault([&] {
                populate_pages(texels, level0_bytes);
                populate_pages(image_memory.mapped, image_memory.bytes);
            });
            struct Join {
                std::thread& thread;
                ~Join() { thread.join(); }
            } join{prefault};
            fill_level0(texels);
        }
        int w = width, h = height;
        for (uint32_t l = 0; l < levels; ++l) {
            if (l > 0) { // the level below, built over the one just copied
                downsample_into(texels, w, h, texels);
                w = std::max(1, w >> 1);
                h = std::max(1, h >> 1);
            }
            copy_level(context, t.chain, levels, staging, l, {uint32_t(w), uint32_t(h)}, {l == 0, l + 1 == levels});
        }
        upload_sat(context, nullptr, t);
    }
    on_failure.dismiss();
    return t;
}

void destroy_texture(const VulkanContext& context, GpuTexture& texture)
{
    destroy_image(context, texture.chain);
    destroy_image(context, texture.sat_low);
    destroy_image(context, texture.sat_high);
    texture = GpuTexture{};
}

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
        image_barrier(cb, {.image = g.image, .from = scope::undefined, .to = scope::transfer_dst,
                           .levels = VK_REMAINING_MIP_LEVELS, .layers = VK_REMAINING_ARRAY_LAYERS, .aspect = aspect});
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
        image_barrier(cb, {.image = g.image, .from = scope::transfer_dst, .to = scope::shader_read,
                           .levels = VK_REMAINING_MIP_LEVELS, .layers = VK_REMAINING_ARRAY_LAYERS, .aspect = aspect});
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
