#pragma once
// The device's memory limits as the plain numbers load_texture checks before it decodes anything.
#include "memory_budget.h"
#include "vk_context.h"

namespace tf {

DeviceLimits device_limits(const DeviceInfo& device);

} // namespace tf
