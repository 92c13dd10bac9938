// vulkan_util.h — the Vulkan plumbing of the texfilter example: checked calls, a headless device,
// buffers, images and one-shot command submission. Nothing here knows about texfilter.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <string>

// Every VkResult is checked: a failure prints the call and exits with status 1.
#define VK_CHECK(call) vk_check((call), #call, __FILE__, __LINE__)
void vk_check(VkResult result, const char* call, const char* file, int line);
[[noreturn]] void fail(const std::string& message);

struct Context {
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE; // null without VK_EXT_debug_utils
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceSubgroupProperties subgroup{};
    bool fullSubgroups = false; // computeFullSubgroups enabled
    // Descriptor indexing for bindless arrays (Vulkan 1.2 features runtimeDescriptorArray and
    // shaderSampledImageArrayNonUniformIndexing), enabled where supported; else the features missing.
    bool bindless = false;
    std::string bindlessMissing;
    VkDevice device = VK_NULL_HANDLE;
    uint32_t queueFamily = 0; // graphics + compute
    VkQueue queue = VK_NULL_HANDLE;
    VkCommandPool commandPool = VK_NULL_HANDLE;
};

// Vulkan 1.3 instance and device (dynamic rendering is required). The device is the first one whose
// name contains $TEXFILTER_EXAMPLE_DEVICE (case-insensitive) or, without it, the first usable one.
Context create_context();
void destroy_context(Context& context);
// Validation warnings and errors reported through VK_EXT_debug_utils so far.
int debug_message_count();

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr; // host-visible, coherent, mapped for its whole life
};
Buffer create_host_buffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage);
void destroy_buffer(const Context& context, Buffer& buffer);

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE; // all levels and layers, colour aspect
};
// A 2D image and its view: VK_IMAGE_VIEW_TYPE_2D, or 2D_ARRAY with `layers` > 1 (what texture2DArray binds).
Image create_image(const Context& context, VkFormat format, uint32_t width, uint32_t height, uint32_t levels,
                   VkImageUsageFlags usage, uint32_t layers = 1);
void destroy_image(const Context& context, Image& image);

// Layout transition of all levels and layers of a colour image, with the given execution and memory dependency.
void image_barrier(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                   VkPipelineStageFlags srcStage, VkAccessFlags srcAccess, VkPipelineStageFlags dstStage,
                   VkAccessFlags dstAccess);

// Records commands through `record`, submits them and waits until the queue is idle.
void submit_and_wait(const Context& context, const std::function<void(VkCommandBuffer)>& record);

VkShaderModule create_shader_module(const Context& context, const uint32_t* code, size_t bytes);
