// Textures onto the device: the MIP chain and the summed-area table as sampled images.
#include "vulkan/upload.h"
#include "harness/config.h"
#include "texture/error.h"
#include "texture/sat.h"
#include "vulkan/barriers.h"
#include "vulkan/cleanup.h"
#include "vulkan/image.h"
#include "vulkan/resources.h"
#include <algorithm>
#include <cstdint>
#include <cstring>

namespace tf {

namespace {

// A device-local sampled image with `levels` levels, filled from tightly packed level data.
GpuImage upload_image(const VulkanContext& context, VkFormat format, const std::vector<VkExtent2D>& extents,
                      const std::vector<const void*>& data, const std::vector<size_t>& bytes)
{
    VkDevice device = context.device;
    GpuImage g;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {extents[0].width, extents[0].height, 1};
    info.mipLevels = uint32_t(extents.size());
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    try {
        TF_VK(vkCreateImage(device, &info, nullptr, &g.image));
        VkMemoryRequirements requirements{};
        vkGetImageMemoryRequirements(device, g.image, &requirements);
        VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        allocate.allocationSize = requirements.size;
        allocate.memoryTypeIndex =
            find_memory_type(context, requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        if (vkAllocateMemory(device, &allocate, nullptr, &g.memory) != VK_SUCCESS)
            throw Error("out of device memory for a " + std::to_string(extents[0].width) + "x" +
                        std::to_string(extents[0].height) + " texture on " + context.info.name);
        TF_VK(vkBindImageMemory(device, g.image, g.memory, 0));

        VkDeviceSize total = 0;
        for (size_t b : bytes)
            total += b;
        Buffer staging = create_host_buffer(context, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        Cleanup cleanup;
        cleanup.add([&] { destroy_buffer(context, staging); });
        std::vector<VkBufferImageCopy> copies;
        VkDeviceSize offset = 0;
        for (size_t l = 0; l < extents.size(); ++l) {
            std::memcpy(static_cast<char*>(staging.mapped) + offset, data[l], bytes[l]);
            VkBufferImageCopy copy{};
            copy.bufferOffset = offset;
            copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, uint32_t(l), 0, 1};
            copy.imageExtent = {extents[l].width, extents[l].height, 1};
            copies.push_back(copy);
            offset += bytes[l];
        }
        uint32_t levels = uint32_t(extents.size());
        submit_and_wait(context, [&](VkCommandBuffer cb) {
            image_barrier(cb, g.image, levels, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
                          VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                          VK_PIPELINE_STAGE_TRANSFER_BIT);
            vkCmdCopyBufferToImage(cb, staging.buffer, g.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                   uint32_t(copies.size()), copies.data());
            image_barrier(cb, g.image, levels, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
                          VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                          VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
        });

        VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        view.image = g.image;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = format;
        view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, levels, 0, 1};
        TF_VK(vkCreateImageView(device, &view, nullptr, &g.view));
    } catch (...) {
        destroy_image(context, g);
        throw;
    }
    return g;
}


} // namespace


bool needs_sat(Filter filter) { return filter == Filter::sat || filter == Filter::sat_assembly; }

GpuTexture upload_texture(const VulkanContext& context, const MipChain& chain, bool with_sat)
{
    const Image& base = chain.levels.at(0);
    uint32_t limit = context.info.max_image_dimension_2d;
    if (uint32_t(base.width) > limit || uint32_t(base.height) > limit)
        throw Error("texture " + std::to_string(base.width) + "x" + std::to_string(base.height) +
                    " exceeds the device limit maxImageDimension2D = " + std::to_string(limit));
    if (with_sat && (uint32_t(base.width) + 1 > limit || uint32_t(base.height) + 1 > limit))
        throw Error("the summed-area table of a " + std::to_string(base.width) + "x" + std::to_string(base.height) +
                    " texture needs one more texel a side than maxImageDimension2D = " + std::to_string(limit));
    GpuTexture t;
    t.width = base.width;
    t.height = base.height;
    t.levels = int(chain.levels.size());
    try {
        std::vector<VkExtent2D> extents;
        std::vector<const void*> data;
        std::vector<size_t> bytes;
        for (const Image& level : chain.levels) {
            extents.push_back({uint32_t(level.width), uint32_t(level.height)});
            data.push_back(level.texels.data());
            bytes.push_back(level.texels.size() * sizeof(glm::vec4));
        }
        t.chain = upload_image(context, VK_FORMAT_R32G32B32A32_SFLOAT, extents, data, bytes);

        SatTable sat;
        if (with_sat) {
            sat = build_sat(base);
        } else { // a 1x1 zero table keeps the descriptor set valid for every filter
            sat.low.assign(4, 0u);
            sat.high.assign(1, 0u);
        }
        VkExtent2D sat_extent{uint32_t(sat.width + 1), uint32_t(sat.height + 1)};
        if (!with_sat)
            sat_extent = {1, 1};
        t.sat_offset = sat.offset;
        t.sat_scale = sat.scale;
        t.sat_low = upload_image(context, VK_FORMAT_R32G32B32A32_UINT, {sat_extent}, {sat.low.data()},
                                 {sat.low.size() * sizeof(uint32_t)});
        t.sat_high = upload_image(context, VK_FORMAT_R32_UINT, {sat_extent}, {sat.high.data()},
                                  {sat.high.size() * sizeof(uint32_t)});
    } catch (...) {
        destroy_texture(context, t);
        throw;
    }
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
