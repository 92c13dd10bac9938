#pragma once
// How much memory a texture will take, worked out from its size alone (a file's header, a procedural
// texture's side) so that a texture that cannot fit is refused before anything is allocated or decoded.
#include <cstdint>
#include <string>

namespace tf {

// Bytes the host needs at the peak of loading a width x height texture: the decode (the file's channels
// as float, then RGBA float), then the MIP chain (RGBA float, every level), the summed-area table when
// asked for, and a staging copy of the largest image when it goes to a Vulkan device.
struct TextureMemory {
    uint64_t decode = 0;  // file pixels as float + the RGBA level 0
    uint64_t chain = 0;   // every MIP level, RGBA32F
    uint64_t sat = 0;     // RGBA32UI + R32UI table of (w+1) x (h+1) entries, 0 unless asked for
    uint64_t host_peak = 0;
    uint64_t device = 0;  // what a Vulkan device holds: chain + sat (0 for the CPU reference)
};
TextureMemory estimate_texture_memory(int width, int height, int file_channels, bool with_sat, bool on_device);

// The default host budget: half of physical memory (the rest is the system's, the driver's and the scene's).
uint64_t default_memory_budget();

// "512M", "8G", "1.5T", "1048576" (binary units: K = 1024). Throws tf::Error naming the text.
uint64_t parse_byte_size(const std::string& text);

// "4.2 GiB", "512 MiB", "900 bytes".
std::string format_bytes(uint64_t bytes);

// Throws tf::Error "WHAT: needs N for ..., over the memory budget of B (--memory-budget raises it)".
void check_memory_budget(const std::string& what, int width, int height, const TextureMemory& need, uint64_t budget);

// What a Vulkan device can hold, as plain numbers (filled from the device by device_limits(), vk side).
struct DeviceLimits {
    std::string name;
    uint64_t max_allocation = 0; // maxMemoryAllocationSize; 0: unknown
    uint64_t heap = 0;           // the largest device-local heap; 0: unknown
    uint32_t heap_index = 0;
};

// Throws tf::Error naming `what` and the device's limit when the texture's images cannot be allocated there:
// one image over maxMemoryAllocationSize, or all of them over the device-local heap. (Vulkan itself would
// only say VkResult -2 from vkAllocateMemory or vkBindImageMemory.)
void check_device_limits(const std::string& what, int width, int height, const TextureMemory& need,
                         const DeviceLimits& device);

} // namespace tf
