#pragma once
// The one cleanup style of host/vulkan and host/view. Each object is made by a create call with its destroy
// beside it, and whoever creates registers the destroy in a Cleanup at once; the Cleanup runs the steps in
// reverse order however the scope is left (return or exception).
// - A create that makes several objects takes the caller's Cleanup and registers each as it is made
//   (create_set_layout, create_compose_pass, create_imgui_layer): a failure part-way leaves nothing behind.
// - An object that outlives one function holds its Cleanup as a member (GpuRenderer, GpuBuild::objects);
//   a create that hands a whole object to the caller registers its destroy in a local Cleanup and dismisses
//   it once the object is whole, so a half-made object is undone and a whole one kept.
// - An object remade in place while it lives (a swapchain, the viewer's texture) has one destroy for
//   whatever it holds, registered once by its owner (the viewer's teardown).
// Steps run from a destructor, so they never throw (wait_idle_before_destroy reports a failure instead).
#include <functional>
#include <vector>

namespace tf {

struct Cleanup {
    std::vector<std::function<void()>> steps;

    Cleanup() = default;
    Cleanup(const Cleanup&) = delete; // the steps run once, from one place
    Cleanup& operator=(const Cleanup&) = delete;
    ~Cleanup()
    {
        for (auto it = steps.rbegin(); it != steps.rend(); ++it)
            (*it)();
    }
    void add(std::function<void()> step) { steps.push_back(std::move(step)); }
    // Success: the caller owns what was made; nothing runs.
    void dismiss() { steps.clear(); }
};

} // namespace tf
