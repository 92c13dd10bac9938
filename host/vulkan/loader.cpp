#include "vulkan/loader.h"
#include "texture/error.h"
#include <dlfcn.h>

#define TF_VK_DEFINE(name) PFN_##name name = nullptr;
TF_VK_GLOBAL_FUNCTIONS(TF_VK_DEFINE)
TF_VK_INSTANCE_FUNCTIONS(TF_VK_DEFINE)
TF_VK_DEVICE_FUNCTIONS(TF_VK_DEFINE)
#undef TF_VK_DEFINE

namespace tf {

namespace {
PFN_vkGetInstanceProcAddr get_instance_proc = nullptr;
}

void load_vulkan()
{
    if (get_instance_proc)
        return;
    void* library = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!library)
        library = dlopen("libvulkan.so", RTLD_NOW | RTLD_LOCAL);
    if (!library)
        throw Error("no Vulkan loader found (libvulkan.so.1): install the Vulkan loader and a driver "
                    "(on Debian: tools/setup.sh), or use --backend reference");
    get_instance_proc = reinterpret_cast<PFN_vkGetInstanceProcAddr>(dlsym(library, "vkGetInstanceProcAddr"));
    if (!get_instance_proc)
        throw Error("the Vulkan loader libvulkan.so.1 has no vkGetInstanceProcAddr: it is broken or not a Vulkan loader");
#define TF_VK_LOAD_GLOBAL(name) name = reinterpret_cast<PFN_##name>(get_instance_proc(nullptr, #name));
    TF_VK_GLOBAL_FUNCTIONS(TF_VK_LOAD_GLOBAL)
#undef TF_VK_LOAD_GLOBAL
    if (!vkCreateInstance || !vkEnumerateInstanceVersion)
        throw Error("the Vulkan loader is older than Vulkan 1.1; texfilter needs a Vulkan 1.3 loader and driver");
}

void load_instance_functions(VkInstance instance)
{
#define TF_VK_LOAD_INSTANCE(name) name = reinterpret_cast<PFN_##name>(get_instance_proc(instance, #name));
    TF_VK_INSTANCE_FUNCTIONS(TF_VK_LOAD_INSTANCE)
#undef TF_VK_LOAD_INSTANCE
}

void load_device_functions(VkDevice device)
{
#define TF_VK_LOAD_DEVICE(name) name = reinterpret_cast<PFN_##name>(vkGetDeviceProcAddr(device, #name));
    TF_VK_DEVICE_FUNCTIONS(TF_VK_LOAD_DEVICE)
#undef TF_VK_LOAD_DEVICE
}

} // namespace tf
