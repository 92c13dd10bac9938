// The physical devices: what each offers, whether texfilter can use it, and which one a --device names.
#include "vulkan/context.h"
#include "texture/error.h"
#include <algorithm>
#include <cctype>

namespace tf {

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

std::vector<DeviceInfo> list_devices(VkInstance instance)
{
    uint32_t count = 0;
    TF_VK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
    std::vector<VkPhysicalDevice> physicals(count);
    TF_VK(vkEnumeratePhysicalDevices(instance, &count, physicals.data()));
    std::vector<DeviceInfo> devices;
    for (uint32_t i = 0; i < count; ++i) {
        VkPhysicalDeviceMaintenance3Properties maintenance3{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
        VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
        driver.pNext = &maintenance3;
        VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
        subgroup.pNext = &driver;
        VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
        properties.pNext = &subgroup;
        vkGetPhysicalDeviceProperties2(physicals[i], &properties);
        VkPhysicalDeviceFeatures features{};
        vkGetPhysicalDeviceFeatures(physicals[i], &features);
        VkPhysicalDeviceVulkan12Features features12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
        VkPhysicalDeviceFeatures2 features2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
        features2.pNext = &features12;
        if (properties.properties.apiVersion >= VK_API_VERSION_1_2)
            vkGetPhysicalDeviceFeatures2(physicals[i], &features2);
        const VkPhysicalDeviceLimits& limits = properties.properties.limits;

        DeviceInfo d;
        d.index = int(i);
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
        VkPhysicalDeviceMemoryProperties memory{};
        vkGetPhysicalDeviceMemoryProperties(physicals[i], &memory);
        for (uint32_t h = 0; h < memory.memoryHeapCount; ++h)
            if ((memory.memoryHeaps[h].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) &&
                memory.memoryHeaps[h].size > d.device_local_heap_size) {
                d.device_local_heap_size = memory.memoryHeaps[h].size;
                d.device_local_heap_index = h;
            }
        if (int family = find_queue_family(physicals[i]); family >= 0)
            d.timestamp_valid_bits = queue_family_timestamp_bits(physicals[i], uint32_t(family));
        d.why_not_usable = usability_problem(physicals[i], d);
        d.usable = d.why_not_usable.empty();
        devices.push_back(d);
    }
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

} // namespace tf
