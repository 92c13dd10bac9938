#include "vulkan/image.h"
#include "texture/error.h"
#include "vulkan/cleanup.h"
#include "vulkan/resources.h"

namespace tf {

GpuImage create_image(const VulkanContext& context, VkFormat format, uint32_t width, uint32_t height,
                      uint32_t levels, VkImageUsageFlags usage, VkImageAspectFlags aspect, uint32_t layers,
                      VkImageViewType view_type, VkImageCreateFlags flags)
{
    VkDevice device = context.device;
    GpuImage g;
    Cleanup on_failure;
    on_failure.add([&] { destroy_image(context, g); });
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.flags = flags;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {width, height, 1};
    info.mipLevels = levels;
    info.arrayLayers = layers;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    TF_VK(vkCreateImage(device, &info, nullptr, &g.image));
    VkMemoryRequirements requirements{};
    vkGetImageMemoryRequirements(device, g.image, &requirements);
    VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    allocate.allocationSize = requirements.size;
    allocate.memoryTypeIndex = find_memory_type(context, requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (vkAllocateMemory(device, &allocate, nullptr, &g.memory) != VK_SUCCESS)
        throw Error("out of device memory for a " + std::to_string(width) + "x" + std::to_string(height) +
                    (layers > 1 ? "x" + std::to_string(layers) : std::string()) + " image on " + context.info.name);
    TF_VK(vkBindImageMemory(device, g.image, g.memory, 0));
    g.memory_type = allocate.memoryTypeIndex;
    g.memory_size = allocate.allocationSize;
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    VkImageViewUsageCreateInfo view_usage{VK_STRUCTURE_TYPE_IMAGE_VIEW_USAGE_CREATE_INFO};
    view_usage.usage = usage & ~VkImageUsageFlags(VK_IMAGE_USAGE_STORAGE_BIT);
    if (flags & VK_IMAGE_CREATE_EXTENDED_USAGE_BIT)
        view.pNext = &view_usage;
    view.image = g.image;
    view.viewType = view_type;
    view.format = format;
    view.subresourceRange = {aspect, 0, levels, 0, layers};
    TF_VK(vkCreateImageView(device, &view, nullptr, &g.view));
    on_failure.dismiss();
    return g;
}

void destroy_image(const VulkanContext& context, GpuImage& image)
{
    if (image.view)
        vkDestroyImageView(context.device, image.view, nullptr);
    if (image.image)
        vkDestroyImage(context.device, image.image, nullptr);
    if (image.memory)
        vkFreeMemory(context.device, image.memory, nullptr);
    image = GpuImage{};
}

} // namespace tf
