#pragma once
// How much memory a texture will take, worked out from its size alone (a file's header, a procedural
// texture's side) so that a texture that cannot fit is refused before anything is allocated or decoded.
#include <cstdint>
#include <string>

namespace tf {

// How a texture is loaded, which decides what the host holds at once.
enum class TextureLoad {
    host,            // the CPU reference: the MIP chain (and the table, where one is built) in host memory
    device,          // a MipChain (and table) built on the host, then staged to a Vulkan device one image at a time
    device_streamed, // an image file decoded straight into the staging buffer, its levels built there in place
    device_level0,   // --build gpu: level 0 on the host, staged whole; the device builds the chain and table
};

// Bytes the host needs at the peak of loading a width x height texture, phase by phase. Files decode a band
// of rows at a time (at most 4 MiB) straight into level 0's RGBA floats, so there is no whole-file float copy.
// On a CPU device (lavapipe) device memory is the process's own memory, so it counts as host memory too.
struct TextureMemory {
    uint64_t decode = 0;  // level 0, RGBA32F: what decoding the file fills
    uint64_t decoder = 0; // the decoder's own buffers beside it (a band of rows; 0 for procedural textures)
    uint64_t chain = 0;   // every MIP level, RGBA32F
    uint64_t sat = 0;     // RGBA32UI + R32UI table of (w+1) x (h+1) entries, 0 unless asked for
    uint64_t staging = 0; // staging buffers held at once: level 0's, and the table's (0 for the CPU reference)
    bool chain_on_host = true; // false when streamed or built on the device: the host never holds the chain
    bool level0_in_staging = false; // streamed: level 0 is decoded into the staging buffer (staging 0)
    uint64_t device = 0;  // what a Vulkan device holds: chain + sat (0 for the CPU reference)
    bool device_in_host_memory = false; // a CPU device: `device` is part of host_peak
    uint64_t other = 0;   // what the command holds beside the texture (add_other)
    std::string other_what;
    uint64_t host_peak = 0;
};
TextureMemory estimate_texture_memory(int width, int height, bool with_sat, TextureLoad load, bool from_file = false,
                                      bool device_in_host_memory = false);

// Adds what a command holds beside its texture for as long as the texture lives (the output image, the
// lookups and their results) to the peak, named in check_memory_budget's message.
void add_other(TextureMemory& need, uint64_t bytes, const std::string& what);

// The host bytes a render of width x height pixels holds beside its texture, at its peak (the colour view):
// the CPU reference 88 a pixel (each pixel's ray hit, 32, and its lookup, 56, then the image, 16); Vulkan 32
// (the read-back buffer and the image) plus the 16 of the render target on a CPU device.
uint64_t render_output_bytes(int width, int height, bool reference, bool device_in_host_memory);

// The host bytes `sample` holds a lookup beside its texture: the parsed row (48, up to twice that in a
// growing vector), its result (32), its CSV row (up to 72), and on Vulkan the device's lookup, result and
// read-back words (80; the buffers are host memory on a CPU device as on most GPUs).
uint64_t sample_lookup_bytes(bool reference);

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
    bool host_memory = false;    // a CPU device (lavapipe): its images and buffers are the process's memory
};

// Throws tf::Error naming `what` and the device's limit when the texture's images cannot be allocated there:
// one image over maxMemoryAllocationSize, or all of them over the device-local heap. (Vulkan itself would
// only say VkResult -2 from vkAllocateMemory or vkBindImageMemory.)
void check_device_limits(const std::string& what, int width, int height, const TextureMemory& need,
                         const DeviceLimits& device);

} // namespace tf
