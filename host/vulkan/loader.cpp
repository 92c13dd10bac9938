#include "vulkan/loader.h"
#include "texture/error.h"
#include <algorithm>
#include <dlfcn.h>
#include <vector>

// volk's definitions (its function pointers and loaders), compiled once, here.
#define VOLK_IMPLEMENTATION
#include <volk.h>

namespace tf {

void load_vulkan()
{
    if (vkCreateInstance && vkEnumerateInstanceVersion)
        return;
    // Opened here rather than by volkInitialize(), which would call a missing vkGetInstanceProcAddr
    // (a crash) where this gives a message. Same names, same order as volkInitialize().
    void* library = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!library)
        library = dlopen("libvulkan.so", RTLD_NOW | RTLD_LOCAL);
    if (!library)
        throw Error("no Vulkan loader found (libvulkan.so.1): install the Vulkan loader and a driver "
                    "(on Debian: tools/setup.sh), or use --backend reference");
    auto get_instance_proc = reinterpret_cast<PFN_vkGetInstanceProcAddr>(dlsym(library, "vkGetInstanceProcAddr"));
    if (!get_instance_proc)
        throw Error("the Vulkan loader libvulkan.so.1 has no vkGetInstanceProcAddr: it is broken or not a Vulkan loader");
    volkInitializeCustom(get_instance_proc);
    if (!vkCreateInstance || !vkEnumerateInstanceVersion)
        throw Error("the Vulkan loader is older than Vulkan 1.1; texfilter needs a Vulkan 1.3 loader and driver");
}

namespace {
std::vector<VkInstance>& live_instances() // in the order they were made
{
    static std::vector<VkInstance> live;
    return live;
}
} // namespace

void load_instance_functions(VkInstance instance)
{
    live_instances().push_back(instance);
    volkLoadInstanceOnly(instance);
}

void destroy_instance(VkInstance instance)
{
    vkDestroyInstance(instance, nullptr);
    std::vector<VkInstance>& live = live_instances();
    live.erase(std::remove(live.begin(), live.end(), instance), live.end());
    if (!live.empty() && volkGetLoadedInstance() != live.back())
        volkLoadInstanceOnly(live.back());
}

void load_device_functions(VkDevice device) { volkLoadDevice(device); }

} // namespace tf
