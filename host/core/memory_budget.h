#pragma once
// How much memory a texture will take, worked out from its size alone (a file's header, a procedural
// texture's side) so that a texture that cannot fit is refused before anything is allocated or decoded.
#include <cstdint>
#include <string>

namespace tf {

// How a texture is loaded, which decides what the host holds at once.
enum class TextureLoad {
    host,            // the CPU reference: the MIP chain (and the table) in host memory
    device,          // a MipChain built on the host, then staged to a Vulkan device one image at a time
    device_streamed, // an image file decoded straight into the staging buffer, its levels built there in place
};

// Bytes the host needs at the peak of loading a width x height texture. Files decode a band of rows at a
// time (about 1 MiB) straight into level 0's RGBA floats, so there is no whole-file float copy.
struct TextureMemory {
    uint64_t decode = 0;  // level 0, RGBA32F: what decoding the file fills
    uint64_t chain = 0;   // every MIP level, RGBA32F
    uint64_t sat = 0;     // RGBA32UI + R32UI table of (w+1) x (h+1) entries, 0 unless asked for
    uint64_t staging = 0; // the largest one image staged to the device (0 for the CPU reference)
    bool chain_on_host = true; // false when streamed: the host never holds the chain
    uint64_t host_peak = 0;
    uint64_t device = 0;  // what a Vulkan device holds: chain + sat (0 for the CPU reference)
};
TextureMemory estimate_texture_memory(int width, int height, bool with_sat, TextureLoad load);

// The default host budget: half of physical memory (the rest is the system's, the driver's and the scene's).
uint64_t default_memory_budget();

// "512M", "8G", "1048576": core/numbers.h's byte size (binary units: K = 1024; whole numbers, so not 1.5G),
// from 1 byte to 1e18. Throws tf::Error naming the text.
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
