#include "core/memory_budget.h"
#include "core/numbers.h"
#include "texture/error.h"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <unistd.h>

namespace tf {

TextureMemory estimate_texture_memory(int width, int height, bool with_sat, TextureLoad load, bool from_file,
                                      bool device_in_host_memory)
{
    const uint64_t texel = 4 * sizeof(float);
    TextureMemory m;
    m.decode = uint64_t(width) * uint64_t(height) * texel;
    m.decoder = from_file ? uint64_t(4) << 20 : 0; // oiio_module.cpp's band: 1 Mi values of at most 4 bytes
    for (uint64_t w = uint64_t(width), h = uint64_t(height);; w = std::max<uint64_t>(1, w / 2),
                  h = std::max<uint64_t>(1, h / 2)) {
        m.chain += w * h * texel;
        if (w == 1 && h == 1)
            break;
    }
    if (with_sat)
        m.sat = (uint64_t(width) + 1) * (uint64_t(height) + 1) * (4 + 1) * sizeof(uint32_t);
    m.device = load == TextureLoad::host ? 0 : m.chain + m.sat;
    m.device_in_host_memory = device_in_host_memory && load != TextureLoad::host;
    const uint64_t device = m.device_in_host_memory ? m.device : 0;
    const uint64_t decoding = m.decode + m.decoder;
    switch (load) {
    case TextureLoad::host: // the table as texfilter build --build cpu makes it (the reference's sat reads level 0)
        m.host_peak = std::max(decoding, m.chain + m.sat);
        break;
    case TextureLoad::device: // the chain and table stay until the upload ends; the chain's staging buffer and
        // the table's may both be held (measured: lavapipe, 4096^2 with sat)
        m.staging = m.decode + m.sat;
        m.host_peak = std::max(decoding, m.chain + m.sat + m.staging + device);
        break;
    case TextureLoad::device_streamed: // level 0 decoded into the staging buffer, the device's images beside it
        m.level0_in_staging = true;
        m.chain_on_host = false;
        m.host_peak = decoding + device;
        break;
    case TextureLoad::device_level0: // level 0 decoded, then a copy of it staged; the device builds the rest
        m.staging = m.decode;
        m.chain_on_host = false;
        m.host_peak = std::max(decoding, m.decode + m.staging + device);
        break;
    }
    return m;
}

void add_other(TextureMemory& need, uint64_t bytes, const std::string& what)
{
    need.other += bytes;
    need.other_what += (need.other_what.empty() ? "" : ", ") + what + " " + format_bytes(bytes);
    need.host_peak += bytes;
}

uint64_t render_output_bytes(int width, int height, bool reference, bool device_in_host_memory)
{
    const uint64_t per_pixel = reference ? 32 + 56 : device_in_host_memory ? 48 : 32;
    return uint64_t(width) * uint64_t(height) * per_pixel;
}

uint64_t sample_lookup_bytes(bool reference) { return 2 * 48 + 32 + 72 + (reference ? 0 : 80); }

uint64_t default_memory_budget()
{
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    if (pages <= 0 || page <= 0)
        return uint64_t(4) << 30; // unknown machine: 4 GiB
    return uint64_t(pages) * uint64_t(page) / 2;
}

uint64_t parse_byte_size(const std::string& text)
{
    const std::optional<uint64_t> bytes = parse_byte_count(text);
    if (!bytes)
        throw Error("'" + text + "' is not a size (a whole number of bytes, or of K, M, G or T: 512M, 8G; "
                    "1536M, not 1.5G)");
    if (*bytes < 1 || *bytes > uint64_t(1e18)) // a number of bytes, but none a budget can be
        throw Error("'" + text + "' is out of range (expected 1 byte to 1e18 bytes, e.g. 512M, 8G)");
    return *bytes;
}

std::string format_bytes(uint64_t bytes)
{
    const char* units[] = {"KiB", "MiB", "GiB", "TiB"};
    if (bytes < 1024)
        return std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes");
    double value = double(bytes) / 1024;
    int u = 0;
    while (value >= 1024 && u < 3) {
        value /= 1024;
        ++u;
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.1f %s", value, units[u]);
    return text;
}

void check_memory_budget(const std::string& what, int width, int height, const TextureMemory& need, uint64_t budget)
{
    if (need.host_peak <= budget)
        return;
    std::string parts = need.chain_on_host ? "MIP chain " + format_bytes(need.chain)
                        : "level 0 " + format_bytes(need.decode) + (need.level0_in_staging ? " in the staging buffer" : "");
    if (need.sat && need.chain_on_host)
        parts += ", summed-area table " + format_bytes(need.sat);
    if (need.staging)
        parts += ", staging " + format_bytes(need.staging);
    if (need.device_in_host_memory)
        parts += ", the CPU device's images " + format_bytes(need.device);
    if (!need.other_what.empty())
        parts += ", " + need.other_what;
    throw Error(what + ": a " + std::to_string(width) + "x" + std::to_string(height) + " texture needs " +
                format_bytes(need.host_peak) + " of memory at the peak (" + parts + "), over the memory budget of " +
                format_bytes(budget) + " (set by --memory-budget SIZE; half of physical memory without it)");
}

void check_device_limits(const std::string& what, int width, int height, const TextureMemory& need,
                         const DeviceLimits& device)
{
    const uint64_t largest_image = std::max(need.chain, need.sat * 4 / 5); // the SAT's RGBA32UI part
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (device.max_allocation && largest_image > device.max_allocation)
        throw Error(what + ": the " + size + " texture needs one allocation of " + format_bytes(largest_image) +
                    ", over " + device.name + "'s maxMemoryAllocationSize of " + format_bytes(device.max_allocation) +
                    " (out of device memory)");
    if (device.heap && need.device > device.heap)
        throw Error(what + ": the " + size + " texture needs " + format_bytes(need.device) + " of device memory, over " +
                    device.name + "'s device-local heap " + std::to_string(device.heap_index) + " of " +
                    format_bytes(device.heap) + " (out of device memory)");
}

} // namespace tf
