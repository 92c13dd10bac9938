#pragma once
// The viewer's window: GLFW on X11 with no client API (Vulkan draws into it), and what the window system
// tells the viewer between frames (size, minimised, files dropped, close).
#include "vulkan/device.h"
#include <string>
#include <vector>

struct GLFWwindow;

namespace tf {

struct Window {
    GLFWwindow* handle = nullptr;
    std::vector<std::string> dropped; // files dropped onto the window since the viewer last took them
    bool resized = false;             // the framebuffer changed size: recreate the swapchain
};

// Throws tf::Error with one sentence when there is no display (DISPLAY unset, or the X server refuses).
// GLFW stays initialised until terminate_window_system.
void init_window_system();
void terminate_window_system();
// The instance extensions a surface on this window system needs.
std::vector<std::string> window_instance_extensions();
Window* create_window(int width, int height, const std::string& title);
void destroy_window(Window* window);
VkSurfaceKHR create_window_surface(const VulkanContext& context, const Window& window);

// The framebuffer's size in pixels; zero while minimised.
void framebuffer_size(const Window& window, int& width, int& height);
bool should_close(const Window& window);
void request_close(Window& window); // as the window's close button does
void poll_events();
void wait_events(double seconds); // sleeps until an event or the timeout: an idle viewer costs nothing
void set_window_size(Window& window, int width, int height);
void iconify(Window& window);
void set_window_title(Window& window, const std::string& title);
void restore(Window& window);

} // namespace tf
