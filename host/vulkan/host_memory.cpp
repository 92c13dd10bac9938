#include "vulkan/host_memory.h"
#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace tf {

// A GiB of 4 KiB pages is 262144 page faults, or 512 with transparent huge pages.
void advise_huge_pages(void* mapped, size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const uintptr_t page = uintptr_t(sysconf(_SC_PAGESIZE));
    const uintptr_t begin = (uintptr_t(mapped) + page - 1) / page * page;
    const uintptr_t end = (uintptr_t(mapped) + bytes) / page * page;
    if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
    (void)mapped;
    (void)bytes;
#endif
}

// Faults memory in ahead of its first use on another thread (MADV_POPULATE_WRITE: page tables filled, the
// contents left alone, so the caller may write the same memory meanwhile). Zeroing a fresh GiB is a large part
// of loading a texture on a CPU device; done beside a single-threaded image decode, it costs no wall time.
void populate_pages(void* mapped, size_t bytes)
{
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    const uintptr_t page = uintptr_t(sysconf(_SC_PAGESIZE));
    const uintptr_t begin = (uintptr_t(mapped) + page - 1) / page * page;
    const uintptr_t end = (uintptr_t(mapped) + bytes) / page * page;
    if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
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

} // namespace tf
