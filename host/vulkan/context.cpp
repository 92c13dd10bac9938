// The context: one device with one graphics-and-compute queue and a command pool.
#include "vulkan/context.h"
#include "texture/error.h"
#include "vulkan/cleanup.h"

namespace tf {

void vk_check(VkResult result, const char* what)
{
    if (result != VK_SUCCESS)
        throw Error(std::string("Vulkan call failed (VkResult ") + std::to_string(int(result)) + "): " + what);
}

std::string version_string(uint32_t version)
{
    return std::to_string(VK_API_VERSION_MAJOR(version)) + "." + std::to_string(VK_API_VERSION_MINOR(version)) +
           "." + std::to_string(VK_API_VERSION_PATCH(version));
}

VulkanContext create_context(const ContextOptions& options)
{
    VulkanContext context;
    context.instance = create_instance(options.validate, &context.messenger, options.instance_extensions);
    Cleanup on_failure; // destroy_context undoes a half-made context
    on_failure.add([&] { destroy_context(context); });

    std::vector<DeviceInfo> devices = list_devices(context.instance);
    context.info = devices[size_t(select_device(devices, options.device))];
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(context.instance, &count, nullptr);
    std::vector<VkPhysicalDevice> physicals(count);
    vkEnumeratePhysicalDevices(context.instance, &count, physicals.data());
    context.physical = physicals[size_t(context.info.index)];
    context.queue_family = uint32_t(find_queue_family(context.physical));

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue.queueFamilyIndex = context.queue_family;
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    VkPhysicalDeviceVulkan13Features features13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    features13.dynamicRendering = VK_TRUE;
    // Descriptor indexing where offered (a bindless array indexed non-uniformly: sample --resource bindless).
    VkPhysicalDeviceVulkan12Features features12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    features12.shaderSampledImageArrayNonUniformIndexing =
        context.info.sampled_image_array_non_uniform_indexing ? VK_TRUE : VK_FALSE;
    features12.runtimeDescriptorArray = context.info.runtime_descriptor_array ? VK_TRUE : VK_FALSE;
    features13.pNext = &features12;
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    features.pNext = &features13;
    features.features.samplerAnisotropy = context.info.sampler_anisotropy ? VK_TRUE : VK_FALSE;
    features.features.shaderFloat64 = context.info.shader_float64 ? VK_TRUE : VK_FALSE;
    features.features.shaderStorageImageExtendedFormats = context.info.storage_image_extended_formats ? VK_TRUE : VK_FALSE;
    features.features.shaderSampledImageArrayDynamicIndexing =
        context.info.sampled_image_array_dynamic_indexing ? VK_TRUE : VK_FALSE;
    const char* swapchain_extension = VK_KHR_SWAPCHAIN_EXTENSION_NAME;
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pNext = &features;
    if (options.swapchain) {
        info.enabledExtensionCount = 1;
        info.ppEnabledExtensionNames = &swapchain_extension;
    }
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue;
    TF_VK(vkCreateDevice(context.physical, &info, nullptr, &context.device));
    load_device_functions(context.device);
    vkGetDeviceQueue(context.device, context.queue_family, 0, &context.queue);

    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    pool.queueFamilyIndex = context.queue_family;
    TF_VK(vkCreateCommandPool(context.device, &pool, nullptr, &context.command_pool));
    on_failure.dismiss();
    return context;
}

void destroy_context(VulkanContext& context)
{
    if (context.device) {
        vkDeviceWaitIdle(context.device);
        if (context.command_pool)
            vkDestroyCommandPool(context.device, context.command_pool, nullptr);
        vkDestroyDevice(context.device, nullptr);
    }
    if (context.messenger)
        vkDestroyDebugUtilsMessengerEXT(context.instance, context.messenger, nullptr);
    if (context.instance)
        destroy_instance(context.instance);
    context = VulkanContext{};
}

} // namespace tf
