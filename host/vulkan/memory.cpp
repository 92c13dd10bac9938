#include "vulkan/memory.h"
#include "texture/error.h"
#include "vulkan/cleanup.h"
#include <algorithm>
#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace tf {

uint32_t find_memory_type(const VulkanContext& context, uint32_t type_bits, VkMemoryPropertyFlags properties)
{
    VkPhysicalDeviceMemoryProperties memory{};
    vkGetPhysicalDeviceMemoryProperties(context.physical, &memory);
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((type_bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & properties) == properties)
            return i;
    throw Error("the Vulkan device has no memory type with the needed properties");
}

namespace {

Buffer create_buffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage,
                     VkMemoryPropertyFlags properties)
{
    Buffer b;
    Cleanup on_failure;
    on_failure.add([&] { destroy_buffer(context, b); });
    b.size = std::max<VkDeviceSize>(size, 16);
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = b.size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    TF_VK(vkCreateBuffer(context.device, &info, nullptr, &b.buffer));
    VkMemoryRequirements requirements{};
    vkGetBufferMemoryRequirements(context.device, b.buffer, &requirements);
    VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    allocate.allocationSize = requirements.size;
    allocate.memoryTypeIndex = find_memory_type(context, requirements.memoryTypeBits, properties);
    if (vkAllocateMemory(context.device, &allocate, nullptr, &b.memory) != VK_SUCCESS)
        throw Error("out of memory for a " + std::to_string(size) + "-byte buffer on " + context.info.name);
    TF_VK(vkBindBufferMemory(context.device, b.buffer, b.memory, 0));
    if (properties & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)
        TF_VK(vkMapMemory(context.device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped));
    on_failure.dismiss();
    return b;
}

} // namespace

Buffer create_host_buffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage)
{
    return create_buffer(context, size, usage, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
}

Buffer create_device_buffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage)
{
    return create_buffer(context, size, usage, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
}

void destroy_buffer(const VulkanContext& context, Buffer& buffer)
{
    if (buffer.buffer)
        vkDestroyBuffer(context.device, buffer.buffer, nullptr);
    if (buffer.memory)
        vkFreeMemory(context.device, buffer.memory, nullptr); // unmaps implicitly
    buffer = Buffer{};
}

VkShaderModule create_shader_module(const VulkanContext& context, const uint32_t* code, size_t size_bytes)
{
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = size_bytes;
    info.pCode = code;
    VkShaderModule module = VK_NULL_HANDLE;
    TF_VK(vkCreateShaderModule(context.device, &info, nullptr, &module));
    return module;
}

namespace {

// madvise on the whole pages inside [mapped, mapped + bytes); advice only, so a refusal changes nothing.
void advise(void* mapped, size_t bytes, [[maybe_unused]] int advice)
{
#if defined(__linux__)
    const uintptr_t page = uintptr_t(sysconf(_SC_PAGESIZE));
    const uintptr_t begin = (uintptr_t(mapped) + page - 1) / page * page;
    const uintptr_t end = (uintptr_t(mapped) + bytes) / page * page;
    if (mapped && end > begin)
        madvise(reinterpret_cast<void*>(begin), end - begin, advice);
#else
    (void)mapped;
    (void)bytes;
#endif
}

} // namespace

// A GiB of 4 KiB pages is 262144 page faults, or 512 with transparent huge pages.
void advise_huge_pages(void* mapped, size_t bytes)
{
#if defined(MADV_HUGEPAGE)
    advise(mapped, bytes, MADV_HUGEPAGE);
#else
    (void)mapped;
    (void)bytes;
#endif
}

// Zeroing a fresh GiB is a large part of loading a texture on a CPU device; done on another thread beside
// a single-threaded image decode, it costs no wall time.
void populate_pages(void* mapped, size_t bytes)
{
#if defined(MADV_POPULATE_WRITE)
    advise(mapped, bytes, MADV_POPULATE_WRITE);
#else
    (void)mapped;
    (void)bytes;
#endif
}

HostMapping::HostMapping(const VulkanContext& c, VkDeviceMemory m, uint32_t type, VkDeviceSize size) : context(c)
{
    VkPhysicalDeviceMemoryProperties properties{};
    vkGetPhysicalDeviceMemoryProperties(context.physical, &properties);
    if (!(properties.memoryTypes[type].propertyFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT))
        return;
    if (vkMapMemory(context.device, m, 0, VK_WHOLE_SIZE, 0, &mapped) != VK_SUCCESS) {
        mapped = nullptr;
        return;
    }
    memory = m;
    bytes = size_t(size);
}

HostMapping::~HostMapping()
{
    if (mapped)
        vkUnmapMemory(context.device, memory);
}

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

void image_barrier(VkCommandBuffer command_buffer, const ImageBarrier& b)
{
    VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    barrier.srcAccessMask = b.from.access;
    barrier.dstAccessMask = b.to.access;
    barrier.oldLayout = b.from.layout;
    barrier.newLayout = b.to.layout;
    barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = b.image;
    barrier.subresourceRange = {b.aspect, b.base_level, b.levels, 0, b.layers};
    vkCmdPipelineBarrier(command_buffer, b.from.stage, b.to.stage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

void memory_barrier(VkCommandBuffer command_buffer, BarrierScope from, BarrierScope to)
{
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = from.access;
    barrier.dstAccessMask = to.access;
    vkCmdPipelineBarrier(command_buffer, from.stage, to.stage, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

} // namespace tf
