// A texture whose levels and summed-area table the device builds (--build gpu): level 0 up as RGBA32F,
// then record_mip_build and record_sat_build, and for a format other than RGBA32F a blit a level.
#include "vulkan/gpu_built_texture.h"
#include "texture/error.h"
#include "vulkan/barriers.h"
#include "vulkan/host_memory.h"
#include "vulkan/texture_format_support.h"
#include <algorithm>
#include <cstring>

namespace tf {

namespace {

void check_features(const VulkanContext& context, VkFormat format, VkFormatFeatureFlags needed, const std::string& what)
{
    VkFormatProperties properties{};
    vkGetPhysicalDeviceFormatProperties(context.physical, format, &properties);
    if ((properties.optimalTilingFeatures & needed) != needed)
        throw Error("--build gpu: " + context.info.name + " cannot " + what);
}

constexpr VkPipelineStageFlags shader_stages = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;

} // namespace

GpuBuild prepare_gpu_build(const VulkanContext& context, const Image* level0, int w, int h, bool with_sat,
                           TextureFormat format)
{
    check_gpu_build(format, "");
    if (w < 1 || h < 1 || (level0 && (level0->width != w || level0->height != h ||
                                      level0->texels.size() != size_t(w) * size_t(h))))
        throw Error("--build gpu: level 0 of " + std::to_string(w) + "x" + std::to_string(h) + " is not whole");
    check_format_support(context, format, SamplerOptions{});
    check_features(context, VK_FORMAT_R32G32B32A32_SFLOAT, VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT | VK_FORMAT_FEATURE_BLIT_SRC_BIT,
                   "store into or blit from R32G32B32A32_SFLOAT images");
    GpuBuild b;
    b.in_place = format == TextureFormat::rgba32f;
    if (!b.in_place && !level0)
        throw Error("--build gpu: a level 0 written on the device is RGBA32F (no format conversion of level 0)");
    b.with_sat = with_sat;
    b.objects = std::make_shared<Cleanup>();
    Cleanup& objects = *b.objects;
    Cleanup on_early_failure;
    on_early_failure.add([&] { b.objects.reset(); });
    b.kernels = create_gpu_build_kernels(context, objects);
    b.pack = !b.in_place && pack_supported(context, b.kernels, format);
    if (!b.in_place && !b.pack)
        check_features(context, vk_format(format), VK_FORMAT_FEATURE_BLIT_DST_BIT, "blit into " + to_string(format) + " images");
    on_early_failure.dismiss();
    GpuTexture& t = b.texture;
    t.format = format;
    t.filterable = format_filterable(context, format);
    t.width = w;
    t.height = h;
    t.levels = mip_level_count(w, h);
    const uint32_t levels = uint32_t(t.levels);
    Cleanup on_failure;
    on_failure.add([&] { destroy_gpu_build(context, b); });
    b.built = create_image(context, VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t(w), uint32_t(h), levels,
                           gpu_build_chain_usage, VK_IMAGE_ASPECT_COLOR_BIT);
    if (b.in_place) {
        t.chain = b.built;
    } else {
        objects.add([&context, image = b.built]() mutable { destroy_image(context, image); });
        const VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                        VK_IMAGE_USAGE_TRANSFER_SRC_BIT | (b.pack ? VkImageUsageFlags(VK_IMAGE_USAGE_STORAGE_BIT) : 0u);
        t.chain = create_image(context, vk_format(format), uint32_t(w), uint32_t(h), levels, usage,
                               VK_IMAGE_ASPECT_COLOR_BIT, 1, VK_IMAGE_VIEW_TYPE_2D, b.pack ? gpu_pack_image_flags : 0u);
    }
    b.mip = create_mip_build_target(context, b.kernels, b.built.image, w, h, objects);
    if (b.pack)
        b.pack_target = create_pack_target(context, b.kernels, b.mip, t.chain.image, format, objects);
    if (with_sat) {
        b.sat = create_sat_build_target(context, b.kernels, b.mip.level_views[0], w, h, objects);
        t.sat_low = b.sat.low; // the texture's from here on
        t.sat_high = b.sat.high;
    } else {
        upload_empty_sat(context, t);
    }
    if (level0) {
        // Staging: level 0 as RGBA32F (what the levels are built from: as given, like build_mip_chain); for
        // another format, level 0 as the format stores it, then (with a table) its rounded texels as RGBA32F,
        // which the table sums (as load_texture's quantise_chain does before build_sat).
        const size_t texels = level0->texels.size();
        b.float_bytes = texels * sizeof(glm::vec4);
        const size_t packed_bytes = b.in_place ? 0 : texels * texel_bytes(format);
        b.rounded_offset = b.float_bytes + (packed_bytes + 15) / 16 * 16;
        const size_t total = b.in_place ? b.float_bytes : b.rounded_offset + (with_sat ? b.float_bytes : 0);
        b.staging = create_host_buffer(context, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        objects.add([&context, buffer = b.staging]() mutable { destroy_buffer(context, buffer); });
        advise_huge_pages(b.staging.mapped, total);
        char* bytes = static_cast<char*>(b.staging.mapped);
        std::memcpy(bytes, level0->texels.data(), b.float_bytes);
        if (!b.in_place)
            pack_texels(level0->texels.data(), texels, format, bytes + b.float_bytes);
        if (!b.in_place && with_sat) {
            glm::vec4* rounded = reinterpret_cast<glm::vec4*>(bytes + b.rounded_offset);
            for (size_t i = 0; i < texels; ++i)
                rounded[i] = quantise_texel(level0->texels[i], format);
        }
    }
    on_failure.dismiss();
    return b;
}

void record_gpu_build(VkCommandBuffer cb, GpuBuild& b, Level0 level0)
{
    const GpuTexture& t = b.texture;
    const uint32_t levels = uint32_t(t.levels);
    const VkExtent3D extent{uint32_t(t.width), uint32_t(t.height), 1};
    const bool first = level0 != Level0::written;
    if (level0 == Level0::from_staging) {
        image_barrier(cb, b.built.image, levels, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
                      VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        copy.imageExtent = extent;
        vkCmdCopyBufferToImage(cb, b.staging.buffer, b.built.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
        image_barrier(cb, b.built.image, levels, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                      VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
    } else {
        memory_barrier(cb, VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
    }
    if (b.with_sat)
        for (VkImage image : {b.sat.low.image, b.sat.high.image}) // the last frame's reads before this build's writes
            image_barrier(cb, image, 1, first ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                          VK_IMAGE_LAYOUT_GENERAL, 0, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT,
                          first ? VkPipelineStageFlags(VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT) : shader_stages, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
    record_mip_build(cb, b.kernels, b.mip);
    if (b.with_sat && !b.in_place && level0 == Level0::from_staging) {
        // The table sums the texels the format stores: level 0 rounded, over the unrounded one the levels
        // were built from (the build's reads done first).
        image_barrier(cb, b.built.image, 1, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
        VkBufferImageCopy rounded{};
        rounded.bufferOffset = b.rounded_offset;
        rounded.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        rounded.imageExtent = extent;
        vkCmdCopyBufferToImage(cb, b.staging.buffer, b.built.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &rounded);
        image_barrier(cb, b.built.image, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                      VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
    }
    if (b.with_sat) {
        // The build's dispatches bind every level writable (the validator counts level 0 as written).
        memory_barrier(cb, VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
        record_sat_build(cb, b.kernels, b.sat);
        for (VkImage image : {b.sat.low.image, b.sat.high.image})
            image_barrier(cb, image, 1, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                          VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                          shader_stages);
    }
    if (b.in_place) {
        image_barrier(cb, b.built.image, levels, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                      VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                      shader_stages);
        return;
    }
    const VkPipelineStageFlags before = first ? VkPipelineStageFlags(VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT) : shader_stages;
    const VkImageLayout was = first ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    if (b.pack) {
        // Level 0 as the format stores it (copied); levels 1.. stored by pack_level, the host's codes.
        image_barrier(cb, t.chain.image, 1, was, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT,
                      before, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_IMAGE_ASPECT_COLOR_BIT, 1, 0);
        VkBufferImageCopy packed{};
        packed.bufferOffset = b.float_bytes;
        packed.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        packed.imageExtent = extent;
        vkCmdCopyBufferToImage(cb, b.staging.buffer, t.chain.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &packed);
        image_barrier(cb, t.chain.image, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, shader_stages,
                      VK_IMAGE_ASPECT_COLOR_BIT, 1, 0);
        if (levels > 1) {
            image_barrier(cb, t.chain.image, levels - 1, was, VK_IMAGE_LAYOUT_GENERAL, 0, VK_ACCESS_SHADER_WRITE_BIT,
                          before, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_IMAGE_ASPECT_COLOR_BIT, 1, 1);
            memory_barrier(cb, VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                           VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
            record_pack_levels(cb, b.kernels, b.pack_target, b.mip);
            image_barrier(cb, t.chain.image, levels - 1, VK_IMAGE_LAYOUT_GENERAL,
                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_SHADER_WRITE_BIT,
                          VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, shader_stages,
                          VK_IMAGE_ASPECT_COLOR_BIT, 1, 1);
        }
        image_barrier(cb, b.built.image, levels, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                      VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                      shader_stages);
        return;
    }
    // No integer stores: level 0 as the format stores it; every other level blitted (1:1, nearest: a format
    // conversion with the device's rounding).
    image_barrier(cb, b.built.image, levels, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                  VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                  VK_PIPELINE_STAGE_TRANSFER_BIT);
    image_barrier(cb, t.chain.image, levels,
                  first ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                  VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT,
                  first ? VkPipelineStageFlags(VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT) : shader_stages, VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkBufferImageCopy packed{};
    packed.bufferOffset = b.float_bytes;
    packed.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    packed.imageExtent = extent;
    vkCmdCopyBufferToImage(cb, b.staging.buffer, t.chain.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &packed);
    for (uint32_t l = 1; l < levels; ++l) {
        const int32_t lw = std::max(1, t.width >> l), lh = std::max(1, t.height >> l);
        VkImageBlit blit{};
        blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l, 0, 1};
        blit.dstSubresource = blit.srcSubresource;
        blit.srcOffsets[1] = blit.dstOffsets[1] = {lw, lh, 1};
        vkCmdBlitImage(cb, b.built.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, t.chain.image,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_NEAREST);
    }
    image_barrier(cb, t.chain.image, levels, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                  VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, shader_stages);
    // Leave `built` as an in-place build leaves its image, so a rebuild starts from one layout.
    image_barrier(cb, b.built.image, levels, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                  VK_ACCESS_TRANSFER_READ_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
}

void finish_gpu_build(GpuBuild& b, const std::string& texture_name)
{
    if (b.with_sat)
        read_sat_range(b.sat, texture_name, b.texture.sat_offset, b.texture.sat_scale);
}

void destroy_gpu_build(const VulkanContext& context, GpuBuild& b)
{
    destroy_texture(context, b.texture);
    b.objects.reset(); // runs the build objects' cleanup
    b = GpuBuild{};
}

GpuTexture upload_gpu_built_texture(const VulkanContext& context, const Image& level0, bool with_sat,
                                    TextureFormat format)
{
    GpuBuild b = prepare_gpu_build(context, &level0, level0.width, level0.height, with_sat, format);
    Cleanup on_failure;
    on_failure.add([&] { destroy_gpu_build(context, b); });
    submit_and_wait(context, [&](VkCommandBuffer cb) { record_gpu_build(cb, b, Level0::from_staging); });
    finish_gpu_build(b);
    GpuTexture t = b.texture;
    b.texture = GpuTexture{}; // handed on
    b.objects.reset();
    on_failure.dismiss();
    return t;
}

} // namespace tf
