// The instance, with the validation layers and their messenger when asked for.
#include "vulkan/context.h"
#include "texture/error.h"
#include "vulkan/cleanup.h"
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace tf {

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
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    return std::any_of(layers.begin(), layers.end(),
                       [](const VkLayerProperties& l) { return std::strcmp(l.layerName, validation_layer) == 0; });
}

} // namespace

int validation_message_count() { return validation_messages; }

VkInstance create_instance(bool validate, VkDebugUtilsMessengerEXT* messenger,
                           const std::vector<std::string>& extensions)
{
    load_vulkan();
    uint32_t loader_version = 0;
    vkEnumerateInstanceVersion(&loader_version);
    if (VK_API_VERSION_MINOR(loader_version) < 3 && VK_API_VERSION_MAJOR(loader_version) == 1)
        throw Error("the Vulkan loader supports Vulkan " + version_string(loader_version) + "; texfilter needs 1.3");
    if (validate && !has_validation_layer())
        throw Error("validation was requested but VK_LAYER_KHRONOS_validation is not installed "
                    "(Debian: vulkan-validationlayers)");

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "texfilter";
    app.apiVersion = VK_API_VERSION_1_3;
    const char* debug_extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    VkDebugUtilsMessengerCreateInfoEXT messenger_info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messenger_info.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                 VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                 VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger_info.pfnUserCallback = on_validation_message;

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

} // namespace tf
