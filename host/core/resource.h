#pragma once
// The kinds of texture resource `texfilter sample --resource` binds (shaders/harness/filter_select.glsl's
// HARNESS_RESOURCE_* variants: one SPIR-V each) and the depth comparison of the shadow kind, with parse and
// to-string (the CLI's vocabulary), the per-lookup choice of layer or bindless texture, and the options
// that go with them. Values are the harness's ids and Vulkan's VkCompareOp (checked in
// scene/shader_interface.h).
#include "harness/config.h"
#include <cstddef>
#include <string>

namespace tf {

enum class Resource {
    combined = HARNESS_RESOURCE_COMBINED,             // sampler2D (today's harness)
    separate = HARNESS_RESOURCE_SEPARATE,             // texture2D + sampler
    array = HARNESS_RESOURCE_ARRAY,                   // sampler2DArray, one layer read (--layer)
    separate_array = HARNESS_RESOURCE_SEPARATE_ARRAY, // texture2DArray + sampler
    bindless = HARNESS_RESOURCE_BINDLESS,             // sampler2D[], a non-uniform index a lookup
    shadow = HARNESS_RESOURCE_SHADOW,                 // a depth image: percentage-closer filtering
    atlas = HARNESS_RESOURCE_ATLAS,                   // one tile of an atlas, read through TF_SOURCE
    virtual_texture = HARNESS_RESOURCE_VIRTUAL,       // pages of a physical texture and a page table (TF_SOURCE)
};

// VkCompareOp's values (TF_COMPARE_* in the includes): a depth texel D passes when `dref OP D`.
enum class CompareOp { never = 0, less, equal, less_or_equal, greater, not_equal, greater_or_equal, always };

Resource parse_resource(const std::string& name); // throws tf::Error listing the valid names
std::string to_string(Resource resource);
CompareOp parse_compare_op(const std::string& name);
std::string to_string(CompareOp op);

bool is_layered(Resource resource); // array, separate-array, bindless: more than one texture (--layers)
// atlas, virtual: the texture's texels lie elsewhere (core/texel_sources.h), read through the includes'
// TF_SOURCE overloads (manual taps only).
bool is_texel_source(Resource resource);

// Vulkan's depth comparison (Image Operations, "Depth Compare Operation"): 1 when `dref OP depth`, else 0.
double compare_depth(CompareOp op, double dref, double depth);

// What `sample --resource` reads besides the filter's own options.
struct ResourceOptions {
    Resource resource = Resource::combined;
    int layers = 1;  // array kinds: layers; bindless: textures (each distinct: core/resource_textures.h)
    int layer = 0;   // array kinds: the layer every lookup reads (clamped to [0, layers-1] as Vulkan
                     // does); bindless: the first index
    CompareOp compare = CompareOp::less_or_equal; // shadow
    float dref = 0.5f;                            // shadow: the reference depth (not clamped)
};

// The texture lookup `index` reads, as the harness picks it: array kinds clamp the layer to
// [0, layers-1]; bindless takes (layer + index) % layers; one texture otherwise (0).
int texture_index(const ResourceOptions& options, size_t lookup_index);

} // namespace tf
