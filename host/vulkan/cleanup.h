#pragma once
// The Vulkan layer's one cleanup style. Each Vulkan object is made by a create call with its destroy
// beside it: whoever creates registers the destroy in a Cleanup at once, which runs the steps in reverse
// order however the scope is left (return or exception). An object that outlives one function (a
// GpuRenderer) holds its Cleanup as a member; a create function that hands its object to the caller
// dismisses its Cleanup once the object is whole, so a half-made object is undone and a whole one kept.
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
