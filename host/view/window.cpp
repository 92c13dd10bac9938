#include "view/window.h"
#include "texture/error.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <cstdlib>
#include <string>

namespace tf {

namespace {

std::string glfw_error_text()
{
    const char* text = nullptr;
    glfwGetError(&text);
    return text ? text : "no reason given";
}

void on_framebuffer_size(GLFWwindow* handle, int, int)
{
    static_cast<Window*>(glfwGetWindowUserPointer(handle))->resized = true;
}

void on_drop(GLFWwindow* handle, int count, const char** paths)
{
    Window* window = static_cast<Window*>(glfwGetWindowUserPointer(handle));
    for (int i = 0; i < count; ++i)
        window->dropped.push_back(paths[i]);
}

} // namespace

void init_window_system()
{
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display)
        throw Error("view needs a display and DISPLAY is not set: run it in an X session, set DISPLAY, or run it "
                    "under xvfb-run (Debian: xvfb)");
    glfwInitHint(GLFW_JOYSTICK_HAT_BUTTONS, GLFW_FALSE);
    if (!glfwInit())
        throw Error(std::string("view cannot open the display '") + display + "' (" + glfw_error_text() +
                    "): set DISPLAY to a running X server, or run it under xvfb-run");
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw Error("view: GLFW found no Vulkan loader with window-system support (install the Vulkan loader and "
                    "a driver: tools/setup.sh)");
    }
}

std::vector<std::string> window_instance_extensions()
{
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names)
        throw Error("view: the Vulkan loader cannot present to this window system (" + glfw_error_text() + ")");
    return std::vector<std::string>(names, names + count);
}

Window* create_window(int width, int height, const std::string& title)
{
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    GLFWwindow* handle = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!handle)
        throw Error("view cannot create a " + std::to_string(width) + "x" + std::to_string(height) +
                    " window: " + glfw_error_text());
    Window* window = new Window{handle};
    glfwSetWindowUserPointer(handle, window);
    glfwSetFramebufferSizeCallback(handle, on_framebuffer_size);
    glfwSetDropCallback(handle, on_drop);
    glfwSetWindowPos(handle, 0, 0); // where the tests' X-side capture looks for it
    return window;
}

void destroy_window(Window* window)
{
    glfwDestroyWindow(window->handle);
    delete window;
}

void terminate_window_system() { glfwTerminate(); }

VkSurfaceKHR create_window_surface(const VulkanContext& context, const Window& window)
{
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    TF_VK(glfwCreateWindowSurface(context.instance, window.handle, nullptr, &surface));
    return surface;
}

void framebuffer_size(const Window& window, int& width, int& height)
{
    glfwGetFramebufferSize(window.handle, &width, &height);
    if (glfwGetWindowAttrib(window.handle, GLFW_ICONIFIED) || !glfwGetWindowAttrib(window.handle, GLFW_VISIBLE))
        width = height = 0;
}

bool should_close(const Window& window) { return glfwWindowShouldClose(window.handle); }
void request_close(Window& window) { glfwSetWindowShouldClose(window.handle, GLFW_TRUE); }
void poll_events() { glfwPollEvents(); }
void wait_events(double seconds) { glfwWaitEventsTimeout(seconds); }
void set_window_size(Window& window, int width, int height) { glfwSetWindowSize(window.handle, width, height); }
void set_window_title(Window& window, const std::string& title) { glfwSetWindowTitle(window.handle, title.c_str()); }

// Without a window manager (Xvfb) nothing answers an iconify request: the window is also hidden, which is
// what a minimised window is to the viewer (nothing to present to).
void iconify(Window& window)
{
    glfwIconifyWindow(window.handle);
    glfwHideWindow(window.handle);
}
void restore(Window& window)
{
    glfwShowWindow(window.handle);
    glfwRestoreWindow(window.handle);
}

} // namespace tf
