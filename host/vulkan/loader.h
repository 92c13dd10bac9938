#pragma once
// Vulkan entry points through volk, loaded at run time (dlopen of libvulkan.so.1), so that a machine
// without a Vulkan loader gets one clear sentence instead of a dynamic-linker failure, and the reference
// backend works with no Vulkan at all. Every vk* function the layer calls is one of volk's pointers.
#include <volk.h>

namespace tf {

// Loads libvulkan and the global entry points. Throws tf::Error with one sentence when it can't.
void load_vulkan();
// After vkCreateInstance / vkCreateDevice: the instance's and then the device's entry points (volk).
void load_instance_functions(VkInstance instance);
void load_device_functions(VkDevice device);

} // namespace tf
