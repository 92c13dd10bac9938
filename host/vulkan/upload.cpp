// Textures onto the device: the MIP chain and the summed-area table as sampled images.
#include "vulkan/upload.h"
#include "harness/config.h"
#include "texture/error.h"
#include "texture/sat.h"
#include "vulkan/barriers.h"
#include "vulkan/cleanup.h"
#include "vulkan/host_memory.h"
#include "vulkan/image.h"
#include "vulkan/resources.h"
#include "vulkan/texture_format_support.h"
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <thread>

namespace tf {

namespace {

// A device-local sampled image of `levels` levels (contents undefined until copied), its memory advised
// to use huge pages where the host can see it (a CPU device: see host_memory.h).
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
            image_barrier(cb, g.image, levels, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
                          VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                          VK_PIPELINE_STAGE_TRANSFER_BIT);
        vkCmdCopyBufferToImage(cb, staging.buffer, g.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
        if (step.last)
            image_barrier(cb, g.image, levels, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
                          VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                          VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
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

GpuTexture upload_texture(const VulkanContext& context, const MipChain& chain, bool with_sat, TextureFormat format,
                          TextureBuild build)
{
    if (build == TextureBuild::gpu)
        return upload_gpu_built_texture(context, chain.levels.at(0), with_sat, format);
    return upload_texture(context, chain, with_sat, format);
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

} // namespace tf
