#pragma once
// Vulkan entry points loaded at run time (dlopen of libvulkan.so.1), so that a machine without a
// Vulkan loader gets one clear sentence instead of a dynamic-linker failure, and the reference
// backend works with no Vulkan at all.
#define VK_NO_PROTOTYPES
#include <vulkan/vulkan.h>

#define TF_VK_GLOBAL_FUNCTIONS(X) \
    X(vkCreateInstance)           \
    X(vkEnumerateInstanceLayerProperties) \
    X(vkEnumerateInstanceExtensionProperties) \
    X(vkEnumerateInstanceVersion)

#define TF_VK_INSTANCE_FUNCTIONS(X)            \
    X(vkDestroyInstance)                       \
    X(vkEnumeratePhysicalDevices)              \
    X(vkGetPhysicalDeviceProperties)           \
    X(vkGetPhysicalDeviceProperties2)          \
    X(vkGetPhysicalDeviceFeatures)             \
    X(vkGetPhysicalDeviceFormatProperties)     \
    X(vkGetPhysicalDeviceMemoryProperties)     \
    X(vkGetPhysicalDeviceQueueFamilyProperties) \
    X(vkCreateDevice)                          \
    X(vkGetDeviceProcAddr)                     \
    X(vkCreateDebugUtilsMessengerEXT)          \
    X(vkDestroyDebugUtilsMessengerEXT)

#define TF_VK_DEVICE_FUNCTIONS(X)       \
    X(vkDestroyDevice)                  \
    X(vkGetDeviceQueue)                 \
    X(vkDeviceWaitIdle)                 \
    X(vkQueueSubmit)                    \
    X(vkQueueWaitIdle)                  \
    X(vkCreateCommandPool)              \
    X(vkDestroyCommandPool)             \
    X(vkAllocateCommandBuffers)         \
    X(vkBeginCommandBuffer)             \
    X(vkEndCommandBuffer)               \
    X(vkCreateBuffer)                   \
    X(vkDestroyBuffer)                  \
    X(vkCreateImage)                    \
    X(vkDestroyImage)                   \
    X(vkCreateImageView)                \
    X(vkDestroyImageView)               \
    X(vkCreateSampler)                  \
    X(vkDestroySampler)                 \
    X(vkGetBufferMemoryRequirements)    \
    X(vkGetImageMemoryRequirements)     \
    X(vkAllocateMemory)                 \
    X(vkFreeMemory)                     \
    X(vkBindBufferMemory)               \
    X(vkBindImageMemory)                \
    X(vkMapMemory)                      \
    X(vkUnmapMemory)                    \
    X(vkCreateShaderModule)             \
    X(vkDestroyShaderModule)            \
    X(vkCreateDescriptorSetLayout)      \
    X(vkDestroyDescriptorSetLayout)     \
    X(vkCreatePipelineLayout)           \
    X(vkDestroyPipelineLayout)          \
    X(vkCreateGraphicsPipelines)        \
    X(vkCreateComputePipelines)         \
    X(vkDestroyPipeline)                \
    X(vkCreateDescriptorPool)           \
    X(vkDestroyDescriptorPool)          \
    X(vkAllocateDescriptorSets)         \
    X(vkUpdateDescriptorSets)           \
    X(vkCreateFence)                    \
    X(vkDestroyFence)                   \
    X(vkWaitForFences)                  \
    X(vkCmdPipelineBarrier)             \
    X(vkCmdCopyBufferToImage)           \
    X(vkCmdCopyImageToBuffer)           \
    X(vkCmdBindPipeline)                \
    X(vkCmdBindDescriptorSets)          \
    X(vkCmdPushConstants)               \
    X(vkCmdDispatch)                    \
    X(vkCmdDraw)                        \
    X(vkCmdBindVertexBuffers)           \
    X(vkCmdBeginRendering)              \
    X(vkCmdEndRendering)                \
    X(vkCmdSetViewport)                 \
    X(vkCmdSetScissor)                  \
    X(vkCreateQueryPool)                \
    X(vkDestroyQueryPool)               \
    X(vkCmdResetQueryPool)              \
    X(vkCmdWriteTimestamp)              \
    X(vkGetQueryPoolResults)

#define TF_VK_DECLARE(name) extern PFN_##name name;
TF_VK_GLOBAL_FUNCTIONS(TF_VK_DECLARE)
TF_VK_INSTANCE_FUNCTIONS(TF_VK_DECLARE)
TF_VK_DEVICE_FUNCTIONS(TF_VK_DECLARE)
#undef TF_VK_DECLARE

namespace tf {

// Loads libvulkan and the global entry points. Throws tf::Error with one sentence when it can't.
void load_vulkan();
void load_instance_functions(VkInstance instance);
void load_device_functions(VkDevice device);

} // namespace tf
