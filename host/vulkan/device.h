#pragma once
// Instance and device: the loader (volk, libvulkan dlopen'ed), the instance with its validation messenger,
// device listing and choice, the context (device, queue, command pool), one-shot submission, the device's
// memory limits and which --format it samples and filters.
#include "core/filter.h"
#include "core/memory_budget.h"
#include "core/texture_format.h"
#include "vulkan/cleanup.h"
#include <string>
#include <vector>
#include <volk.h>

namespace tf {

// Vulkan entry points through volk, loaded at run time (dlopen of libvulkan.so.1), so that a machine
// without a Vulkan loader gets one clear sentence instead of a dynamic-linker failure, and the reference
// backend works with no Vulkan at all. Every vk* function the layer calls is one of volk's pointers.
// Loads libvulkan and the global entry points. Throws tf::Error with one sentence when it can't.
void load_vulkan();
// After vkCreateInstance / vkCreateDevice: the instance's and then the device's entry points (volk).
void load_instance_functions(VkInstance instance);
void load_device_functions(VkDevice device);
// vkDestroyInstance, then volk's instance entry points go back to the newest instance still alive (volk holds
// one instance's: a second instance, made and destroyed while a context lives, e.g. to read a device's
// properties, left that context with the destroyed one's vkDestroy* pointers).
void destroy_instance(VkInstance instance);

// Headless Vulkan: instance (optionally with validation), device listing and selection, one queue.
struct DeviceInfo {
    int index = 0;
    std::string name;
    std::string type;        // "cpu", "discrete", "integrated", ...
    std::string driver_name; // VkPhysicalDeviceDriverProperties
    std::string driver_info;
    VkDriverId driver_id = VkDriverId(0);
    uint32_t api_version = 0;
    uint32_t driver_version = 0;
    uint32_t sub_texel_precision_bits = 0;
    uint32_t mipmap_precision_bits = 0;
    uint32_t sub_pixel_precision_bits = 0; // rasterization: the fraction bits of a vertex's pixel position
    float max_sampler_anisotropy = 0;
    float max_sampler_lod_bias = 0;
    uint32_t max_image_dimension_2d = 0;
    uint32_t max_image_dimension_cube = 0;
    uint32_t subgroup_size = 0;
    bool quad_ops_fragment = false;
    bool quad_ops_compute = false;
    bool sampler_anisotropy = false; // feature
    bool shader_float64 = false;     // feature, enabled when offered (the GPU SAT build's exact quantisation)
    bool storage_image_extended_formats = false; // feature, enabled when offered (the GPU build's r8ui, r16ui codes)
    // Vulkan 1.2 descriptor indexing (enabled when offered; `sample --resource bindless` needs the first)
    bool sampled_image_array_non_uniform_indexing = false;
    bool runtime_descriptor_array = false;
    bool sampled_image_array_dynamic_indexing = false; // Vulkan 1.0 feature, enabled when offered
    float timestamp_period_ns = 0;     // nanoseconds a timestamp tick
    uint32_t timestamp_valid_bits = 0; // of the queue texfilter uses; 0: no timestamps (no bench timings)
    uint64_t max_memory_allocation_size = 0; // VkPhysicalDeviceMaintenance3Properties: the largest one allocation
    uint64_t device_local_heap_size = 0;     // the largest DEVICE_LOCAL heap, where textures go
    uint32_t device_local_heap_index = 0;
    bool usable = false;
    std::string why_not_usable; // empty when usable
};

struct ContextOptions {
    std::string device; // "" = default (lavapipe first), else an index or part of a name
    bool validate = false;
    // A window (texfilter view): the surface extensions the window system needs, and VK_KHR_swapchain.
    std::vector<std::string> instance_extensions;
    bool swapchain = false;
};

struct VulkanContext {
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    DeviceInfo info;
    VkDevice device = VK_NULL_HANDLE;
    uint32_t queue_family = 0;
    VkQueue queue = VK_NULL_HANDLE;
    VkCommandPool command_pool = VK_NULL_HANDLE;
};

// Throws tf::Error when a Vulkan call fails, naming the call and the result: the layer's one error style.
void vk_check(VkResult result, const char* what);
#define TF_VK(call) ::tf::vk_check((call), #call)
// vkDeviceWaitIdle in a destroy, which runs from a Cleanup step and must not throw: a failure (a lost
// device) is reported on stderr and the destroy goes on (nothing can still be running on a lost device).
void wait_idle_before_destroy(const VulkanContext& context) noexcept;

// Instance only (for listing devices). Throws tf::Error with one sentence if there is no loader/driver.
VkInstance create_instance(bool validate, VkDebugUtilsMessengerEXT* messenger,
                           const std::vector<std::string>& extensions = {});
std::vector<DeviceInfo> list_devices(VkInstance instance);
// The device `request` names (see ContextOptions::device), or the default; throws with a per-device
// account of why when nothing fits.
int select_device(const std::vector<DeviceInfo>& devices, const std::string& request);
// A queue family that does graphics and compute (every Vulkan GPU has one), or -1.
int find_queue_family(VkPhysicalDevice physical);

VulkanContext create_context(const ContextOptions& options);
void destroy_context(VulkanContext& context);

// Validation messages reported so far (warnings and errors). Tests expect zero.
int validation_message_count();

// Records with `record`, submits, and waits; the command buffer is freed again (the benchmark submits
// thousands).
template <typename Record>
void submit_and_wait(const VulkanContext& context, Record&& record);
VkCommandBuffer begin_one_shot(const VulkanContext& context);
void end_one_shot(const VulkanContext& context, VkCommandBuffer command_buffer); // submits and waits
void free_one_shot(const VulkanContext& context, VkCommandBuffer command_buffer);

template <typename Record>
void submit_and_wait(const VulkanContext& context, Record&& record)
{
    VkCommandBuffer command_buffer = begin_one_shot(context);
    Cleanup cleanup;
    cleanup.add([&] { free_one_shot(context, command_buffer); });
    record(command_buffer);
    end_one_shot(context, command_buffer);
}

std::string version_string(uint32_t version);

// The device's memory limits as the plain numbers load_texture checks before it decodes anything.
DeviceLimits device_limits(const DeviceInfo& device);

// The Vulkan side of the --format table (core/texture_format.h): each format's VkFormat, and whether this
// device can sample it and filter it linearly (VkFormatProperties::optimalTilingFeatures), checked before
// any work starts.
VkFormat vk_format(TextureFormat format);

// SAMPLED_IMAGE_FILTER_LINEAR with optimal tiling on this device.
bool format_filterable(const VulkanContext& context, TextureFormat format);

// Throws tf::Error naming the device and the format when it cannot sample the format with optimal tiling
// (and as a transfer destination), or, for options that filter through the sampler (hw-* modes, --taps
// hardware), cannot filter it linearly; and as check_format_filter for integer formats.
void check_format_support(const VulkanContext& context, TextureFormat format, const SamplerOptions& options);

} // namespace tf
