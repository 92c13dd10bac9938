#pragma once
// Host-side memory advice for CPU devices (lavapipe), where the device's memory is the host's own: a
// staging buffer or image of a GiB is fresh anonymous memory, and faulting it in 4 KiB at a time is a
// large part of loading a big texture. Advice only: where the memory is not ordinary host memory (a
// discrete GPU's) the calls do nothing.
#include "vulkan/context.h"
#include <cstddef>
#include <cstdint>

namespace tf {

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

} // namespace tf
