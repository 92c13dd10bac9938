#include "vulkan/device.h"
#include "texture/error.h"
#include "vulkan/cleanup.h"
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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

// The instance, with the validation layers and their messenger when asked for.
namespace {

int validation_messages = 0;

VKAPI_ATTR VkBool32 VKAPI_CALL on_validation_message(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                     VkDebugUtilsMessageTypeFlagsEXT,
                                                     const VkDebugUtilsMessengerCallbackDataEXT* data, void*)
{
    ++validation_messages;
    std::fprintf(stderr, "validation: %s\n", data->pMessage);
    return VK_FALSE;
}

const char* validation_layer = "VK_LAYER_KHRONOS_validation";

bool has_validation_layer()
{
    uint32_t count = 0;
    TF_VK(vkEnumerateInstanceLayerProperties(&count, nullptr));
    std::vector<VkLayerProperties> layers(count);
    TF_VK(vkEnumerateInstanceLayerProperties(&count, layers.data()));
    return std::any_of(layers.begin(), layers.end(),
                       [](const VkLayerProperties& l) { return std::strcmp(l.layerName, validation_layer) == 0; });
}

} // namespace

int validation_message_count() { return validation_messages; }

namespace {

// Warnings and errors of every type, counted and printed by on_validation_message.
VkDebugUtilsMessengerCreateInfoEXT messenger_create_info()
{
    VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = on_validation_message;
    return info;
}

} // namespace

VkInstance create_instance(bool validate, VkDebugUtilsMessengerEXT* messenger,
                           const std::vector<std::string>& extensions)
{
    load_vulkan();
    uint32_t loader_version = 0;
    TF_VK(vkEnumerateInstanceVersion(&loader_version));
    if (VK_API_VERSION_MINOR(loader_version) < 3 && VK_API_VERSION_MAJOR(loader_version) == 1)
        throw Error("the Vulkan loader supports Vulkan " + version_string(loader_version) + "; texfilter needs 1.3");
    if (validate && !has_validation_layer())
        throw Error("validation was requested but VK_LAYER_KHRONOS_validation is not installed "
                    "(Debian: vulkan-validationlayers)");

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "texfilter";
    app.apiVersion = VK_API_VERSION_1_3;
    const char* debug_extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    VkDebugUtilsMessengerCreateInfoEXT messenger_info = messenger_create_info();

    const VkValidationFeatureEnableEXT sync_enable = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    VkValidationFeaturesEXT sync_features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    sync_features.enabledValidationFeatureCount = 1;
    sync_features.pEnabledValidationFeatures = &sync_enable;
    std::vector<const char*> names;
    for (const std::string& e : extensions)
        names.push_back(e.c_str());
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    if (validate) {
        info.enabledLayerCount = 1;
        info.ppEnabledLayerNames = &validation_layer;
        names.push_back(debug_extension);
        info.pNext = &messenger_info; // also catches messages from instance creation itself
        // TEXFILTER_SYNC_VALIDATION=1 adds synchronisation validation (hazards between commands): the
        // GPU-build tests set it; it is slower, so the rest of the suite runs without.
        if (const char* sync = std::getenv("TEXFILTER_SYNC_VALIDATION"); sync && std::strcmp(sync, "1") == 0) {
            sync_features.pNext = info.pNext;
            info.pNext = &sync_features;
        }
    }
    info.enabledExtensionCount = uint32_t(names.size());
    info.ppEnabledExtensionNames = names.data();
    VkInstance instance = VK_NULL_HANDLE;
    VkResult result = vkCreateInstance(&info, nullptr, &instance);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw Error("no Vulkan driver found: the loader is installed but no ICD answered "
                    "(install mesa-vulkan-drivers for lavapipe, or a GPU driver)");
    TF_VK(result);
    load_instance_functions(instance);
    Cleanup on_failure;
    on_failure.add([=] { destroy_instance(instance); });
    if (validate)
        TF_VK(vkCreateDebugUtilsMessengerEXT(instance, &messenger_info, nullptr, messenger));
    on_failure.dismiss();
    return instance;
}

// The physical devices: what each offers, whether texfilter can use it, and which one a --device names.
namespace {

std::string lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

std::string type_name(VkPhysicalDeviceType type)
{
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual";
    default: return "other";
    }
}

uint32_t queue_family_timestamp_bits(VkPhysicalDevice physical, uint32_t family)
{
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
    return family < count ? families[family].timestampValidBits : 0;
}

std::string usability_problem(VkPhysicalDevice physical, const DeviceInfo& info)
{
    if (VK_API_VERSION_MINOR(info.api_version) < 3 && VK_API_VERSION_MAJOR(info.api_version) == 1)
        return "supports Vulkan " + version_string(info.api_version) + ", texfilter needs 1.3 (dynamic rendering)";
    if (find_queue_family(physical) < 0)
        return "has no queue family with both graphics and compute";
    VkFormatProperties format{};
    vkGetPhysicalDeviceFormatProperties(physical, VK_FORMAT_R32G32B32A32_SFLOAT, &format);
    VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
                                  VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT |
                                  VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT;
    if ((format.optimalTilingFeatures & needed) != needed)
        return "cannot sample RGBA32F with linear filtering and render to it";
    return "";
}

} // namespace

int find_queue_family(VkPhysicalDevice physical)
{
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
    for (uint32_t i = 0; i < count; ++i)
        if ((families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT))
            return int(i);
    return -1;
}

namespace {

// The largest DEVICE_LOCAL heap, where textures go.
void find_texture_heap(VkPhysicalDevice physical, DeviceInfo& d)
{
    VkPhysicalDeviceMemoryProperties memory{};
    vkGetPhysicalDeviceMemoryProperties(physical, &memory);
    for (uint32_t h = 0; h < memory.memoryHeapCount; ++h)
        if ((memory.memoryHeaps[h].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) &&
            memory.memoryHeaps[h].size > d.device_local_heap_size) {
            d.device_local_heap_size = memory.memoryHeaps[h].size;
            d.device_local_heap_index = h;
        }
}

// What texfilter needs to know of one device: properties, limits, features, the texture heap, the queue's
// timestamps, and whether it can run texfilter at all.
DeviceInfo describe_device(VkPhysicalDevice physical, int index)
{
    VkPhysicalDeviceMaintenance3Properties maintenance3{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    driver.pNext = &maintenance3;
    VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
    subgroup.pNext = &driver;
    VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    properties.pNext = &subgroup;
    vkGetPhysicalDeviceProperties2(physical, &properties);
    VkPhysicalDeviceFeatures features{};
    vkGetPhysicalDeviceFeatures(physical, &features);
    VkPhysicalDeviceVulkan12Features features12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceFeatures2 features2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    features2.pNext = &features12;
    if (properties.properties.apiVersion >= VK_API_VERSION_1_2)
        vkGetPhysicalDeviceFeatures2(physical, &features2);
    const VkPhysicalDeviceLimits& limits = properties.properties.limits;

    DeviceInfo d;
    d.index = index;
    d.name = properties.properties.deviceName;
    d.type = type_name(properties.properties.deviceType);
    d.driver_name = driver.driverName;
    d.driver_info = driver.driverInfo;
    d.driver_id = driver.driverID;
    d.api_version = properties.properties.apiVersion;
    d.driver_version = properties.properties.driverVersion;
    d.sub_texel_precision_bits = limits.subTexelPrecisionBits;
    d.mipmap_precision_bits = limits.mipmapPrecisionBits;
    d.sub_pixel_precision_bits = limits.subPixelPrecisionBits;
    d.max_sampler_anisotropy = limits.maxSamplerAnisotropy;
    d.max_sampler_lod_bias = limits.maxSamplerLodBias;
    d.max_image_dimension_2d = limits.maxImageDimension2D;
    d.max_image_dimension_cube = limits.maxImageDimensionCube;
    d.subgroup_size = subgroup.subgroupSize;
    bool quad = (subgroup.supportedOperations & VK_SUBGROUP_FEATURE_QUAD_BIT) != 0;
    d.quad_ops_fragment = quad && (subgroup.supportedStages & VK_SHADER_STAGE_FRAGMENT_BIT);
    // The compute render also votes (subgroupAny: whether a subgroup's quads must share a missed lane's uv).
    const bool vote = (subgroup.supportedOperations & VK_SUBGROUP_FEATURE_VOTE_BIT) != 0;
    d.quad_ops_compute = quad && vote && (subgroup.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT);
    d.sampler_anisotropy = features.samplerAnisotropy == VK_TRUE;
    d.shader_float64 = features.shaderFloat64 == VK_TRUE;
    d.storage_image_extended_formats = features.shaderStorageImageExtendedFormats == VK_TRUE;
    d.sampled_image_array_non_uniform_indexing = features12.shaderSampledImageArrayNonUniformIndexing == VK_TRUE;
    d.runtime_descriptor_array = features12.runtimeDescriptorArray == VK_TRUE;
    d.sampled_image_array_dynamic_indexing = features.shaderSampledImageArrayDynamicIndexing == VK_TRUE;
    d.timestamp_period_ns = limits.timestampPeriod;
    d.max_memory_allocation_size = maintenance3.maxMemoryAllocationSize;
    find_texture_heap(physical, d);
    if (int family = find_queue_family(physical); family >= 0)
        d.timestamp_valid_bits = queue_family_timestamp_bits(physical, uint32_t(family));
    d.why_not_usable = usability_problem(physical, d);
    d.usable = d.why_not_usable.empty();
    return d;
}

} // namespace

std::vector<DeviceInfo> list_devices(VkInstance instance)
{
    uint32_t count = 0;
    TF_VK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
    std::vector<VkPhysicalDevice> physicals(count);
    TF_VK(vkEnumeratePhysicalDevices(instance, &count, physicals.data()));
    std::vector<DeviceInfo> devices;
    for (uint32_t i = 0; i < count; ++i)
        devices.push_back(describe_device(physicals[i], int(i)));
    return devices;
}

int select_device(const std::vector<DeviceInfo>& devices, const std::string& request)
{
    auto account = [&]() { // one line, as every message: " [0] NAME: usable; [1] NAME: why not"
        std::string s;
        for (const DeviceInfo& d : devices)
            s += std::string(s.empty() ? " [" : "; [") + std::to_string(d.index) + "] " + d.name + ": " +
                 (d.usable ? "usable" : d.why_not_usable);
        return s;
    };
    if (devices.empty())
        throw Error("no Vulkan device found: the loader and driver answered but listed no physical device");
    if (request.empty()) {
        for (const DeviceInfo& d : devices)
            if (d.usable && d.driver_id == VK_DRIVER_ID_MESA_LLVMPIPE)
                return d.index;
        for (const DeviceInfo& d : devices)
            if (d.usable)
                return d.index;
        throw Error("no usable Vulkan device:" + account());
    }
    bool numeric = !request.empty() && std::all_of(request.begin(), request.end(), ::isdigit);
    for (const DeviceInfo& d : devices) {
        bool match = numeric ? std::to_string(d.index) == request
                             : lower(d.name).find(lower(request)) != std::string::npos;
        if (!match)
            continue;
        if (!d.usable)
            throw Error("--device '" + request + "' names " + d.name + ", which " + d.why_not_usable);
        return d.index;
    }
    throw Error("--device '" + request + "' matches no Vulkan device; devices are:" + account());
}

// The context: one device with one graphics-and-compute queue and a command pool.
void vk_check(VkResult result, const char* what)
{
    if (result != VK_SUCCESS)
        throw Error(std::string("Vulkan call failed (VkResult ") + std::to_string(int(result)) + "): " + what);
}

void wait_idle_before_destroy(const VulkanContext& context) noexcept
{
    const VkResult result = vkDeviceWaitIdle(context.device);
    if (result != VK_SUCCESS)
        std::fprintf(stderr, "texfilter: vkDeviceWaitIdle failed (VkResult %d) before destroying the device's objects\n",
                     int(result));
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
    TF_VK(vkEnumeratePhysicalDevices(context.instance, &count, nullptr));
    std::vector<VkPhysicalDevice> physicals(count);
    TF_VK(vkEnumeratePhysicalDevices(context.instance, &count, physicals.data()));
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
        wait_idle_before_destroy(context);
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

// One-shot command buffers: record, submit, wait, free.
VkCommandBuffer begin_one_shot(const VulkanContext& context)
{
    VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocate.commandPool = context.command_pool;
    allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocate.commandBufferCount = 1;
    VkCommandBuffer command_buffer = VK_NULL_HANDLE;
    TF_VK(vkAllocateCommandBuffers(context.device, &allocate, &command_buffer));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VkResult result = vkBeginCommandBuffer(command_buffer, &begin);
    if (result != VK_SUCCESS)
        free_one_shot(context, command_buffer);
    TF_VK(result);
    return command_buffer;
}

void end_one_shot(const VulkanContext& context, VkCommandBuffer command_buffer)
{
    TF_VK(vkEndCommandBuffer(command_buffer));
    VkDevice device = context.device;
    Cleanup cleanup;
    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence = VK_NULL_HANDLE;
    TF_VK(vkCreateFence(device, &fence_info, nullptr, &fence));
    cleanup.add([=] { vkDestroyFence(device, fence, nullptr); });
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &command_buffer;
    TF_VK(vkQueueSubmit(context.queue, 1, &submit, fence));
    TF_VK(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX));
}

void free_one_shot(const VulkanContext& context, VkCommandBuffer command_buffer)
{
    vkFreeCommandBuffers(context.device, context.command_pool, 1, &command_buffer);
}

DeviceLimits device_limits(const DeviceInfo& device)
{
    return {device.name, device.max_memory_allocation_size, device.device_local_heap_size,
            device.device_local_heap_index, device.type == "cpu"};
}

VkFormat vk_format(TextureFormat format)
{
    switch (format) {
    case TextureFormat::rgba32f: return VK_FORMAT_R32G32B32A32_SFLOAT;
    case TextureFormat::rgba8_srgb: return VK_FORMAT_R8G8B8A8_SRGB;
    case TextureFormat::rgba8: return VK_FORMAT_R8G8B8A8_UNORM;
    case TextureFormat::rgba16f: return VK_FORMAT_R16G16B16A16_SFLOAT;
    case TextureFormat::r8: return VK_FORMAT_R8_UNORM;
    case TextureFormat::r16f: return VK_FORMAT_R16_SFLOAT;
    case TextureFormat::r32f: return VK_FORMAT_R32_SFLOAT;
    case TextureFormat::r16ui: return VK_FORMAT_R16_UINT;
    case TextureFormat::r32ui: return VK_FORMAT_R32_UINT;
    }
    throw Error("invalid texture format value " + std::to_string(int(format)));
}

namespace {

VkFormatFeatureFlags optimal_features(const VulkanContext& context, TextureFormat format)
{
    VkFormatProperties properties{};
    vkGetPhysicalDeviceFormatProperties(context.physical, vk_format(format), &properties);
    return properties.optimalTilingFeatures;
}

} // namespace

bool format_filterable(const VulkanContext& context, TextureFormat format)
{
    return (optimal_features(context, format) & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) != 0;
}

void check_format_support(const VulkanContext& context, TextureFormat format, const SamplerOptions& options)
{
    check_format_filter(format, options);
    const VkFormatFeatureFlags features = optimal_features(context, format);
    const VkFormatFeatureFlags upload = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
    if ((features & upload) != upload)
        throw Error("--format " + to_string(format) + ": " + context.info.name +
                    " cannot sample this format from an optimally tiled image it copies into "
                    "(VkFormatProperties::optimalTilingFeatures lacks SAMPLED_IMAGE or TRANSFER_DST)");
    if (needs_hardware_filtering(options) && !(features & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT))
        throw Error("--format " + to_string(format) + ": " + context.info.name +
                    " cannot filter this format linearly (no SAMPLED_IMAGE_FILTER_LINEAR), which --filter " +
                    to_string(options.filter) + (is_hardware(options.filter) ? "" : " --taps hardware") +
                    " needs; use a manual filter or another format");
}

} // namespace tf
