// vulkan_util.cpp — see vulkan_util.h.
#include "vulkan_util.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

const char* result_name(VkResult result)
{
    switch (result) {
    case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
    case VK_ERROR_INITIALIZATION_FAILED: return "VK_ERROR_INITIALIZATION_FAILED";
    case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST";
    case VK_ERROR_MEMORY_MAP_FAILED: return "VK_ERROR_MEMORY_MAP_FAILED";
    case VK_ERROR_LAYER_NOT_PRESENT: return "VK_ERROR_LAYER_NOT_PRESENT";
    case VK_ERROR_EXTENSION_NOT_PRESENT: return "VK_ERROR_EXTENSION_NOT_PRESENT";
    case VK_ERROR_FEATURE_NOT_PRESENT: return "VK_ERROR_FEATURE_NOT_PRESENT";
    case VK_ERROR_INCOMPATIBLE_DRIVER: return "VK_ERROR_INCOMPATIBLE_DRIVER";
    case VK_ERROR_FORMAT_NOT_SUPPORTED: return "VK_ERROR_FORMAT_NOT_SUPPORTED";
    case VK_ERROR_UNKNOWN: return "VK_ERROR_UNKNOWN";
    default: return "VkResult";
    }
}

int debugMessages = 0;

VKAPI_ATTR VkBool32 VKAPI_CALL on_debug_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                VkDebugUtilsMessageTypeFlagsEXT, const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                void*)
{
    ++debugMessages;
    bool error = severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    std::fprintf(stderr, "vulkan %s: %s\n", error ? "error" : "warning", data->pMessage);
    return VK_FALSE; // the call that triggered it goes on
}

// Validation and performance warnings and errors. Not "general" ones: the loader warns there about
// ordinary things, such as VK_INSTANCE_LAYERS being set (which is how validation gets turned on).
VkDebugUtilsMessengerCreateInfoEXT messenger_info()
{
    return {.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
            .messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
            .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT,
            .pfnUserCallback = on_debug_message};
}

bool has_instance_extension(const char* name)
{
    uint32_t count = 0;
    VK_CHECK(vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr));
    std::vector<VkExtensionProperties> extensions(count);
    VK_CHECK(vkEnumerateInstanceExtensionProperties(nullptr, &count, extensions.data()));
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

std::string lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

// Why this device cannot run the example ("" if it can); sets `family` to a graphics + compute queue family.
std::string why_unusable(VkPhysicalDevice physical, const VkPhysicalDeviceProperties& properties, uint32_t& family)
{
    if (properties.apiVersion < VK_API_VERSION_1_3)
        return "supports Vulkan " + std::to_string(VK_API_VERSION_MAJOR(properties.apiVersion)) + "." +
               std::to_string(VK_API_VERSION_MINOR(properties.apiVersion)) + ", the example needs 1.3";
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
    const VkQueueFlags wanted = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    auto it = std::find_if(families.begin(), families.end(),
                           [&](const VkQueueFamilyProperties& f) { return (f.queueFlags & wanted) == wanted; });
    if (it == families.end())
        return "has no queue family with both graphics and compute";
    family = uint32_t(it - families.begin());
    VkPhysicalDeviceVulkan13Features features13{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceFeatures2 features{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &features13};
    vkGetPhysicalDeviceFeatures2(physical, &features);
    if (!features13.dynamicRendering)
        return "lacks dynamicRendering";
    return "";
}

uint32_t memory_type(const Context& context, uint32_t typeBits, VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred)
{
    VkPhysicalDeviceMemoryProperties memory;
    vkGetPhysicalDeviceMemoryProperties(context.physical, &memory);
    for (VkMemoryPropertyFlags flags : {required | preferred, required})
        for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
            if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & flags) == flags)
                return i;
    fail("no suitable memory type");
}

} // namespace

void fail(const std::string& message)
{
    std::fprintf(stderr, "texfilter_example: %s\n", message.c_str());
    std::exit(1);
}

void vk_check(VkResult result, const char* call, const char* file, int line)
{
    if (result == VK_SUCCESS)
        return;
    std::fprintf(stderr, "%s:%d: %s failed: %s (%d)\n", file, line, call, result_name(result), int(result));
    std::exit(1);
}

int debug_message_count() { return debugMessages; }

Context create_context()
{
    Context context;
    uint32_t loaderVersion = 0;
    VK_CHECK(vkEnumerateInstanceVersion(&loaderVersion));
    if (loaderVersion < VK_API_VERSION_1_3)
        fail("the Vulkan loader supports only Vulkan " + std::to_string(VK_API_VERSION_MAJOR(loaderVersion)) + "." +
             std::to_string(VK_API_VERSION_MINOR(loaderVersion)) + "; the example needs 1.3");

    // The messenger is also chained into instance creation, so that messages from vkCreateInstance count too.
    bool debugUtils = has_instance_extension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    VkDebugUtilsMessengerCreateInfoEXT messengerInfo = messenger_info();
    const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
    VkApplicationInfo app{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO, .pApplicationName = "texfilter_example",
                          .apiVersion = VK_API_VERSION_1_3};
    VkInstanceCreateInfo instanceInfo{.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
                                      .pNext = debugUtils ? &messengerInfo : nullptr,
                                      .pApplicationInfo = &app,
                                      .enabledExtensionCount = debugUtils ? 1u : 0u,
                                      .ppEnabledExtensionNames = extensions};
    VK_CHECK(vkCreateInstance(&instanceInfo, nullptr, &context.instance));
    if (debugUtils) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(context.instance, "vkCreateDebugUtilsMessengerEXT"));
        VK_CHECK(create(context.instance, &messengerInfo, nullptr, &context.messenger));
    } else {
        std::fprintf(stderr, "texfilter_example: no VK_EXT_debug_utils, so validation messages are not counted\n");
    }

    uint32_t count = 0;
    VK_CHECK(vkEnumeratePhysicalDevices(context.instance, &count, nullptr));
    std::vector<VkPhysicalDevice> physicals(count);
    VK_CHECK(vkEnumeratePhysicalDevices(context.instance, &count, physicals.data()));
    const char* request = std::getenv("TEXFILTER_EXAMPLE_DEVICE");
    std::string wanted = request ? lower(request) : "", rejected;
    for (VkPhysicalDevice physical : physicals) {
        VkPhysicalDeviceProperties properties;
        vkGetPhysicalDeviceProperties(physical, &properties);
        if (!wanted.empty() && lower(properties.deviceName).find(wanted) == std::string::npos) {
            rejected += std::string("\n  ") + properties.deviceName + ": name does not match";
            continue;
        }
        uint32_t family = 0;
        if (std::string why = why_unusable(physical, properties, family); !why.empty()) {
            rejected += std::string("\n  ") + properties.deviceName + ": " + why;
            continue;
        }
        context.physical = physical;
        context.properties = properties;
        context.queueFamily = family;
        break;
    }
    if (!context.physical)
        fail(std::string("no usable Vulkan device") + (request ? std::string(" for TEXFILTER_EXAMPLE_DEVICE=") + request : "") +
             (rejected.empty() ? "" : ":" + rejected));

    context.subgroup = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
    VkPhysicalDeviceProperties2 properties2{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, .pNext = &context.subgroup};
    vkGetPhysicalDeviceProperties2(context.physical, &properties2);
    VkPhysicalDeviceVulkan13Features supported{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceFeatures2 features2{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &supported};
    vkGetPhysicalDeviceFeatures2(context.physical, &features2);
    context.fullSubgroups = supported.computeFullSubgroups;
    VkPhysicalDeviceVulkan12Features supported12{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    features2.pNext = &supported12;
    vkGetPhysicalDeviceFeatures2(context.physical, &features2);
    if (!supported12.runtimeDescriptorArray)
        context.bindlessMissing += " runtimeDescriptorArray";
    if (!supported12.shaderSampledImageArrayNonUniformIndexing)
        context.bindlessMissing += " shaderSampledImageArrayNonUniformIndexing";
    context.bindless = context.bindlessMissing.empty();

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
                                      .queueFamilyIndex = context.queueFamily,
                                      .queueCount = 1,
                                      .pQueuePriorities = &priority};
    VkPhysicalDeviceVulkan12Features enabled12{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                               .shaderSampledImageArrayNonUniformIndexing = context.bindless,
                                               .runtimeDescriptorArray = context.bindless};
    VkPhysicalDeviceVulkan13Features enabled{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
                                             .pNext = &enabled12,
                                             .computeFullSubgroups = supported.computeFullSubgroups,
                                             .dynamicRendering = VK_TRUE};
    VkDeviceCreateInfo deviceInfo{.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
                                  .pNext = &enabled,
                                  .queueCreateInfoCount = 1,
                                  .pQueueCreateInfos = &queueInfo};
    VK_CHECK(vkCreateDevice(context.physical, &deviceInfo, nullptr, &context.device));
    vkGetDeviceQueue(context.device, context.queueFamily, 0, &context.queue);
    VkCommandPoolCreateInfo poolInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                     .flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT,
                                     .queueFamilyIndex = context.queueFamily};
    VK_CHECK(vkCreateCommandPool(context.device, &poolInfo, nullptr, &context.commandPool));
    return context;
}

void destroy_context(Context& context)
{
    vkDestroyCommandPool(context.device, context.commandPool, nullptr);
    vkDestroyDevice(context.device, nullptr);
    if (context.messenger) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(context.instance, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(context.instance, context.messenger, nullptr);
    }
    vkDestroyInstance(context.instance, nullptr);
    context = Context{};
}

Buffer create_host_buffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage)
{
    Buffer b;
    VkBufferCreateInfo info{.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO, .size = size, .usage = usage};
    VK_CHECK(vkCreateBuffer(context.device, &info, nullptr, &b.buffer));
    VkMemoryRequirements needs;
    vkGetBufferMemoryRequirements(context.device, b.buffer, &needs);
    VkMemoryAllocateInfo allocation{
        .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
        .allocationSize = needs.size,
        .memoryTypeIndex = memory_type(context, needs.memoryTypeBits,
                                       VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, 0)};
    VK_CHECK(vkAllocateMemory(context.device, &allocation, nullptr, &b.memory));
    VK_CHECK(vkBindBufferMemory(context.device, b.buffer, b.memory, 0));
    VK_CHECK(vkMapMemory(context.device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped));
    return b;
}

void destroy_buffer(const Context& context, Buffer& buffer)
{
    vkDestroyBuffer(context.device, buffer.buffer, nullptr);
    vkFreeMemory(context.device, buffer.memory, nullptr); // unmaps it
    buffer = Buffer{};
}

Image create_image(const Context& context, VkFormat format, uint32_t width, uint32_t height, uint32_t levels,
                   VkImageUsageFlags usage, uint32_t layers)
{
    Image image;
    VkImageCreateInfo info{.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
                           .imageType = VK_IMAGE_TYPE_2D,
                           .format = format,
                           .extent = {width, height, 1},
                           .mipLevels = levels,
                           .arrayLayers = layers,
                           .samples = VK_SAMPLE_COUNT_1_BIT,
                           .tiling = VK_IMAGE_TILING_OPTIMAL,
                           .usage = usage,
                           .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED};
    VK_CHECK(vkCreateImage(context.device, &info, nullptr, &image.image));
    VkMemoryRequirements needs;
    vkGetImageMemoryRequirements(context.device, image.image, &needs);
    VkMemoryAllocateInfo allocation{
        .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
        .allocationSize = needs.size,
        .memoryTypeIndex = memory_type(context, needs.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT)};
    VK_CHECK(vkAllocateMemory(context.device, &allocation, nullptr, &image.memory));
    VK_CHECK(vkBindImageMemory(context.device, image.image, image.memory, 0));
    VkImageViewCreateInfo viewInfo{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                                   .image = image.image,
                                   .viewType = layers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D,
                                   .format = format,
                                   .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, levels, 0, layers}};
    VK_CHECK(vkCreateImageView(context.device, &viewInfo, nullptr, &image.view));
    return image;
}

void destroy_image(const Context& context, Image& image)
{
    vkDestroyImageView(context.device, image.view, nullptr);
    vkDestroyImage(context.device, image.image, nullptr);
    vkFreeMemory(context.device, image.memory, nullptr);
    image = Image{};
}

void image_barrier(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                   VkPipelineStageFlags srcStage, VkAccessFlags srcAccess, VkPipelineStageFlags dstStage,
                   VkAccessFlags dstAccess)
{
    VkImageMemoryBarrier barrier{.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER,
                                 .srcAccessMask = srcAccess,
                                 .dstAccessMask = dstAccess,
                                 .oldLayout = from,
                                 .newLayout = to,
                                 .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                 .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                 .image = image,
                                 .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, VK_REMAINING_MIP_LEVELS, 0,
                                                      VK_REMAINING_ARRAY_LAYERS}};
    vkCmdPipelineBarrier(commands, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

void submit_and_wait(const Context& context, const std::function<void(VkCommandBuffer)>& record)
{
    VkCommandBufferAllocateInfo allocation{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                           .commandPool = context.commandPool,
                                           .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                           .commandBufferCount = 1};
    VkCommandBuffer commands;
    VK_CHECK(vkAllocateCommandBuffers(context.device, &allocation, &commands));
    VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                   .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    VK_CHECK(vkBeginCommandBuffer(commands, &begin));
    record(commands);
    VK_CHECK(vkEndCommandBuffer(commands));
    VkSubmitInfo submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &commands};
    VK_CHECK(vkQueueSubmit(context.queue, 1, &submit, VK_NULL_HANDLE));
    VK_CHECK(vkQueueWaitIdle(context.queue));
    vkFreeCommandBuffers(context.device, context.commandPool, 1, &commands);
}

VkShaderModule create_shader_module(const Context& context, const uint32_t* code, size_t bytes)
{
    VkShaderModuleCreateInfo info{.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO, .codeSize = bytes, .pCode = code};
    VkShaderModule module;
    VK_CHECK(vkCreateShaderModule(context.device, &info, nullptr, &module));
    return module;
}
