#include "vulkan/host_memory.h"
#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace tf {

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

} // namespace tf
