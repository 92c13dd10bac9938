#include "view/imgui_layer.h"
#include "texture/error.h"
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

namespace tf {

namespace {

PFN_vkVoidFunction load_function(const char* name, void* user)
{
    auto* context = static_cast<const VulkanContext*>(user);
    PFN_vkVoidFunction f = vkGetDeviceProcAddr(context->device, name);
    return f ? f : vkGetInstanceProcAddr(context->instance, name);
}

void check_result(VkResult result) { vk_check(result, "Dear ImGui's Vulkan backend"); }

} // namespace

void create_imgui_layer(const VulkanContext& context, Window& window, const Swapchain& swapchain, ImGuiLayer& layer)
{
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // no imgui.ini written into the user's directory
    ImGui::StyleColorsDark();
    layer.started = true;
    if (!ImGui_ImplVulkan_LoadFunctions(load_function, const_cast<VulkanContext*>(&context)))
        throw Error("view: Dear ImGui's Vulkan backend could not load its Vulkan entry points");
    layer.glfw_started = ImGui_ImplGlfw_InitForVulkan(window.handle, true);

    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
    VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    pool.maxSets = 4;
    pool.poolSizeCount = 1;
    pool.pPoolSizes = &size;
    TF_VK(vkCreateDescriptorPool(context.device, &pool, nullptr, &layer.pool));

    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = context.instance;
    info.PhysicalDevice = context.physical;
    info.Device = context.device;
    info.QueueFamily = context.queue_family;
    info.Queue = context.queue;
    info.DescriptorPool = layer.pool;
    info.MinImageCount = swapchain.min_image_count;
    info.ImageCount = uint32_t(swapchain.images.size());
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = check_result;
    layer.vulkan_started = ImGui_ImplVulkan_Init(&info, swapchain.render_pass);
    if (!layer.vulkan_started)
        throw Error("view: Dear ImGui's Vulkan backend did not start");
    submit_and_wait(context, [](VkCommandBuffer cb) { ImGui_ImplVulkan_CreateFontsTexture(cb); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

void destroy_imgui_layer(const VulkanContext& context, ImGuiLayer& layer)
{
    if (context.device)
        vkDeviceWaitIdle(context.device);
    if (layer.vulkan_started)
        ImGui_ImplVulkan_Shutdown();
    if (layer.glfw_started)
        ImGui_ImplGlfw_Shutdown();
    if (layer.started)
        ImGui::DestroyContext();
    if (layer.pool)
        vkDestroyDescriptorPool(context.device, layer.pool, nullptr);
    layer = ImGuiLayer{};
}

void imgui_swapchain_recreated(const Swapchain& swapchain) { ImGui_ImplVulkan_SetMinImageCount(swapchain.min_image_count); }

void imgui_begin_frame()
{
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void imgui_end_frame() { ImGui::Render(); }

void record_imgui(VkCommandBuffer command_buffer)
{
    ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), command_buffer);
}

} // namespace tf
