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
// vkDestroyInstance, then volk's instance entry points go back to the newest instance still alive (volk holds
// one instance's: a second instance, made and destroyed while a context lives, e.g. to read a device's
// properties, left that context with the destroyed one's vkDestroy* pointers).
void destroy_instance(VkInstance instance);

} // namespace tf
