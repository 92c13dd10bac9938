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

void create_imgui_layer(const VulkanContext& context, Window& window, const Swapchain& swapchain, Cleanup& cleanup)
{
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    cleanup.add([] { ImGui::DestroyContext(); });
    ImGui::GetIO().IniFilename = nullptr; // no imgui.ini written into the user's directory
    ImGui::StyleColorsDark();
    if (!ImGui_ImplVulkan_LoadFunctions(load_function, const_cast<VulkanContext*>(&context)))
        throw Error("view: Dear ImGui's Vulkan backend could not load its Vulkan entry points");
    if (ImGui_ImplGlfw_InitForVulkan(window.handle, true))
        cleanup.add([] { ImGui_ImplGlfw_Shutdown(); });

    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
    VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    pool.maxSets = 4;
    pool.poolSizeCount = 1;
    pool.pPoolSizes = &size;
    VkDescriptorPool descriptor_pool = VK_NULL_HANDLE; // the font texture's descriptor
    TF_VK(vkCreateDescriptorPool(context.device, &pool, nullptr, &descriptor_pool));
    cleanup.add([device = context.device, descriptor_pool] { vkDestroyDescriptorPool(device, descriptor_pool, nullptr); });

    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = context.instance;
    info.PhysicalDevice = context.physical;
    info.Device = context.device;
    info.QueueFamily = context.queue_family;
    info.Queue = context.queue;
    info.DescriptorPool = descriptor_pool;
    info.MinImageCount = swapchain.min_image_count;
    info.ImageCount = uint32_t(swapchain.images.size());
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = check_result;
    if (!ImGui_ImplVulkan_Init(&info, swapchain.render_pass))
        throw Error("view: Dear ImGui's Vulkan backend did not start");
    cleanup.add([] { ImGui_ImplVulkan_Shutdown(); });
    submit_and_wait(context, [](VkCommandBuffer cb) { ImGui_ImplVulkan_CreateFontsTexture(cb); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
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
