#pragma once
// The scene onto the window by blits, where it can be: straight from the renderers' RGBA32F colour targets
// into the swapchain image (nearest, the hardware's sRGB encode), A left of the divider and B right of it,
// the loupe a magnifying blit. On a CPU rasterizer this costs a tenth of the composition pass (a full-window
// fragment shader), which is what keeps a moving camera interactive. The composition pass remains for what
// blits cannot do: the error view, the compute stage's pixel buffers, an accumulated ground truth.
#include "vulkan/device.h"

namespace tf {

struct Viewer;

// Every half on screen is in a colour target, the view is not the error view, the swapchain takes blits.
bool can_blit(const Viewer& viewer);

// The swapchain image `target` from UNDEFINED to COLOR_ATTACHMENT_OPTIMAL with the scene blitted in (and
// the loupe, with_loupe), ready for the swapchain's load_pass.
void record_blit_composition(VkCommandBuffer command_buffer, const Viewer& viewer, VkImage target, bool with_loupe);

} // namespace tf
