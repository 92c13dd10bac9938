#pragma once
// Memory and images: buffers (host-visible or device-local) and memory types, shader modules, host
// memory for large staging, device images with their views, and pipeline barriers.
#include "vulkan/device.h"
#include <cstddef>
#include <cstdint>

namespace tf {

// Host-visible buffers, memory types and shader modules: the plain Vulkan objects every pass makes.
struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    void* mapped = nullptr; // host-visible and coherent: persistently mapped
};

// Throws a tf::Error naming the size and the device when there is no memory for it.
Buffer create_host_buffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage);
// The same in device-local memory, not mapped (mapped stays null).
Buffer create_device_buffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage);
void destroy_buffer(const VulkanContext& context, Buffer& buffer); // also a half-made or empty one

uint32_t find_memory_type(const VulkanContext& context, uint32_t type_bits, VkMemoryPropertyFlags properties);

VkShaderModule create_shader_module(const VulkanContext& context, const uint32_t* code, size_t size_bytes);

// Host-side memory advice for CPU devices (lavapipe), where the device's memory is the host's own: a
// staging buffer or image of a GiB is fresh anonymous memory, and faulting it in 4 KiB at a time is a
// large part of loading a big texture. Advice only: where the memory is not ordinary host memory (a
// discrete GPU's) the calls do nothing.
// Asks for transparent huge pages over [mapped, mapped + bytes) (granted here only on request).
void advise_huge_pages(void* mapped, size_t bytes);

// Faults [mapped, mapped + bytes) in without touching its contents (MADV_POPULATE_WRITE), so another thread
// may write the same memory meanwhile.
void populate_pages(void* mapped, size_t bytes);

// Device memory mapped for the host's advice where its type is host-visible (a CPU or unified-memory
// device; mapped stays null elsewhere); nothing is read or written through it. Unmapped on destruction.
struct HostMapping {
    const VulkanContext& context;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;
    size_t bytes = 0;
    HostMapping(const VulkanContext& context, VkDeviceMemory memory, uint32_t type, VkDeviceSize size);
    HostMapping(const HostMapping&) = delete;
    HostMapping& operator=(const HostMapping&) = delete;
    ~HostMapping();
};

// Device-local images with their memory and a view: the uploaded textures and the render targets.
struct GpuImage {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    uint32_t memory_type = 0;    // the memory type index it was allocated from
    VkDeviceSize memory_size = 0; // its allocation's size
};

// A 2D image of `levels` levels and `layers` layers in device-local memory, in UNDEFINED layout, with a view
// of every level and layer (VK_IMAGE_VIEW_TYPE_2D, or 2D_ARRAY for a texture array).
// Throws a tf::Error naming the size and the device when there is no memory for it.
GpuImage create_image(const VulkanContext& context, VkFormat format, uint32_t width, uint32_t height,
                      uint32_t levels, VkImageUsageFlags usage, VkImageAspectFlags aspect, uint32_t layers = 1,
                      VkImageViewType view_type = VK_IMAGE_VIEW_TYPE_2D, VkImageCreateFlags flags = 0);
// flags with VK_IMAGE_CREATE_EXTENDED_USAGE_BIT: `usage` may include what only other view formats support
// (STORAGE through an integer view of an sRGB image); the image's own view then omits STORAGE.
void destroy_image(const VulkanContext& context, GpuImage& image); // also a half-made or empty one

// Pipeline barriers, the two shapes the layer records: an image's layout change and a global memory
// dependency, each described by its two sides, written with designated initialisers:
//   image_barrier(cb, {.image = image, .from = scope::transfer_dst, .to = scope::shader_read, .levels = levels});
//   image_barrier(cb, {.image = image, .from = {VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_IMAGE_LAYOUT_UNDEFINED},
//                      .to = scope::transfer_dst});
// One side of a barrier: the stages and accesses that come before it (from) or wait for it (to), and the
// image's layout on that side (images only).
struct BarrierScope {
    VkPipelineStageFlags stage = VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT;
    VkAccessFlags access = 0;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
};

struct ImageBarrier {
    VkImage image = VK_NULL_HANDLE;
    BarrierScope from, to;
    uint32_t levels = 1, base_level = 0; // levels [base_level, base_level + levels)
    uint32_t layers = 1;
    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
};

// The sides the layer's barriers name most. undefined: nothing before, contents not kept; shader_read: read
// by the harness's fragment and compute shaders.
namespace scope {
constexpr BarrierScope undefined{};
constexpr BarrierScope transfer_dst{VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                                    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL};
constexpr BarrierScope transfer_src{VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT,
                                    VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
constexpr BarrierScope compute_write{VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                                     VK_IMAGE_LAYOUT_GENERAL};
constexpr BarrierScope compute_read_write{VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                                          VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT, VK_IMAGE_LAYOUT_GENERAL};
constexpr BarrierScope shader_read{VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                                   VK_ACCESS_SHADER_READ_BIT, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
} // namespace scope

void image_barrier(VkCommandBuffer command_buffer, const ImageBarrier& barrier);
void memory_barrier(VkCommandBuffer command_buffer, BarrierScope from, BarrierScope to);

} // namespace tf
