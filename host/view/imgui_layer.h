#pragma once
// Dear ImGui on the viewer's window: the GLFW backend for input, the Vulkan backend drawing into the
// swapchain's render pass after the composition. Debian's libimgui-dev ships the backends as sources; they
// are compiled here with IMGUI_IMPL_VULKAN_NO_PROTOTYPES and fed volk's entry points.
#include "view/swapchain.h"
#include "view/window.h"
#include "vulkan/cleanup.h"

namespace tf {

// The ImGui context, its GLFW and Vulkan backends and the font texture's descriptor pool, each undone by
// `cleanup` (the device idle first: the caller's).
void create_imgui_layer(const VulkanContext& context, Window& window, const Swapchain& swapchain, Cleanup& cleanup);
void imgui_swapchain_recreated(const Swapchain& swapchain);
void imgui_begin_frame(); // then ImGui:: calls
void imgui_end_frame();   // ImGui::Render
// Inside the render pass: the UI of the frame ended last.
void record_imgui(VkCommandBuffer command_buffer);

} // namespace tf
