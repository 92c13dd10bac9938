#pragma once
// Pipelines from embedded SPIR-V, each specialised to one filter (the harness shaders' specialization
// constants HARNESS_SPEC_FILTER, HARNESS_SPEC_MAGNIFY and HARNESS_SPEC_STOCHASTIC) and, for render, to one
// debug view, one gradient form, a number of lookups a pixel and one scene kind (HARNESS_SPEC_VIEW,
// HARNESS_SPEC_GRADIENTS, HARNESS_SPEC_LOOKUPS, HARNESS_SPEC_SCENE), so that a pipeline holds the
// code of one filter only and a frame runs only what it shows.
#include "core/filter.h"
#include "harness/config.h"
#include "scene/scene.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"
#include <array>
#include <cstddef>
#include <cstdint>

namespace tf {

// What a harness pipeline is specialised to: the filter, level 0's reconstruction (trilinear, aniso, ewa:
// --magnify), the stochastic forms (--stochastic) and render's view and gradients (render.cpp sets them). Made
// from a Filter alone for the deterministic bilinear default, colour view, fine quad gradients.
struct FilterVariant {
    Filter filter = Filter::nearest;
    Reconstruction magnify = Reconstruction::bilinear;
    bool stochastic = false; // --stochastic: HARNESS_SPEC_STOCHASTIC 1, the one-texel forms
    int view = HARNESS_VIEW_COLOR;           // render --view: HARNESS_VIEW_* (tf::DebugView)
    int gradients = HARNESS_GRADIENTS_FINE;  // render --derivatives: HARNESS_GRADIENTS_* (tf::Gradients)
    int lookups = 1;                         // lookups a pixel (bench --lookups-per-pixel)
    int scene = -1;                          // render: the ray-cast scene's kind (HARNESS_SCENE_*); -1: any
    MinimalPass minimal = MinimalPass::none; // compute render: the bench's minimal pass instead (scene/scene.h)
    FilterVariant(Filter f) : filter(f) {} // NOLINT: implicit, most pipelines vary by filter alone
    FilterVariant(Filter f, Reconstruction m, bool s = false) : filter(f), magnify(m), stochastic(s) {}
    bool operator==(const FilterVariant&) const = default;
};
inline FilterVariant filter_variant(const SamplerOptions& options)
{
    return {options.filter, options.magnify, options.stochastic};
}

// The variant as the harness's specialization constants: (HARNESS_SPEC_* id, value), one list for the
// VkSpecializationInfo (pipeline.cpp) and the host-side specialisation (specialize_spirv.cpp).
struct SpecConstant {
    uint32_t id;
    int32_t value;
};
inline std::array<SpecConstant, 7> spec_constants(FilterVariant v)
{
    return {{{HARNESS_SPEC_FILTER, int32_t(v.filter)},
             {HARNESS_SPEC_MAGNIFY, int32_t(v.magnify)},
             {HARNESS_SPEC_STOCHASTIC, v.stochastic ? 1 : 0},
             {HARNESS_SPEC_VIEW, v.view},
             {HARNESS_SPEC_GRADIENTS, v.gradients},
             {HARNESS_SPEC_LOOKUPS, v.lookups},
             {HARNESS_SPEC_SCENE, v.scene}}};
}

struct ShaderCode {
    const uint32_t* words;
    size_t bytes;
};

// Destroyed by `cleanup`.
VkPipeline create_compute_pipeline(const VulkanContext& context, ShaderCode code, VkPipelineLayout layout,
                                   FilterVariant filter, Cleanup& cleanup);

// A triangle-list pipeline for dynamic rendering into one colour attachment of `color_format`, with a
// fixed viewport; the filter specialises the fragment stage.
struct GraphicsPipelineDesc {
    ShaderCode vertex, fragment;
    const VkPipelineVertexInputStateCreateInfo* vertex_input = nullptr; // null: no vertex buffers
    VkFormat color_format = VK_FORMAT_UNDEFINED;
    VkFormat depth_format = VK_FORMAT_UNDEFINED; // UNDEFINED: no depth test
    uint32_t width = 0, height = 0;   // the fixed viewport; 0 x 0: viewport and scissor set when drawing
    VkRenderPass render_pass = VK_NULL_HANDLE; // set: for subpass 0 of it (the viewer's window) instead of dynamic rendering
};
// Destroyed by `cleanup`.
VkPipeline create_graphics_pipeline(const VulkanContext& context, const GraphicsPipelineDesc& desc,
                                    VkPipelineLayout layout, FilterVariant filter, Cleanup& cleanup);

} // namespace tf
