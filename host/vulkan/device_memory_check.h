#pragma once
// The device's memory limits as the plain numbers load_texture checks before it decodes anything.
#include "core/memory_budget.h"
#include "vulkan/context.h"

namespace tf {

DeviceLimits device_limits(const DeviceInfo& device);

} // namespace tf
