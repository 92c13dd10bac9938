#include "vulkan/device_memory_check.h"

namespace tf {

DeviceLimits device_limits(const DeviceInfo& device)
{
    return {device.name, device.max_memory_allocation_size, device.device_local_heap_size,
            device.device_local_heap_index, device.type == "cpu"};
}

} // namespace tf
