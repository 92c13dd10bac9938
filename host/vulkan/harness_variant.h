#pragma once
// Which harness shader a resource kind runs and what it binds at HARNESS_BINDING_TEXTURE (and, for the
// kinds with a separate sampler, HARNESS_BINDING_SAMPLER): the one place that choice is made, so that a
// kind chosen by something else (an integer format's HARNESS_RESOURCE_UINT) is one more case here.
//
// Use: HarnessVariant v = harness_variant(resource, textures); create the pass with v's descriptors
// (resource_pass.h), the pipeline from v.sample. Cost: none (tables).
#include "core/resource.h"
#include "harness/config.h"
#include "vulkan/pipeline.h"
#include <map>

namespace tf {

struct HarnessVariant {
    ShaderCode sample;              // sample.comp.glsl compiled with -DHARNESS_RESOURCE=<the kind's id>
    VkDescriptorType texture_type;  // at HARNESS_BINDING_TEXTURE: combined image sampler or sampled image
    uint32_t texture_count = 1;     // descriptors there (bindless: the array's size)
    VkDescriptorType table_type;    // at HARNESS_BINDING_SAT_LOW, _SAT_HIGH (the summed-area table's two words)
    bool separate_sampler = false;  // a VK_DESCRIPTOR_TYPE_SAMPLER at HARNESS_BINDING_SAMPLER
    bool descriptor_indexing = false; // needs non-uniform indexing of sampled-image arrays (bindless)
    bool layered = false;           // the images at HARNESS_BINDING_TEXTURE and the SAT's are 2D arrays
};

// textures: how many textures the resource holds (bindless: its descriptor count; 1 otherwise).
HarnessVariant harness_variant(Resource resource, uint32_t textures);

// What the `sample` pass of a resource kind binds in set 0, from its variant: the texture, the SAT's tables and
// the sampler as resource_pass.cpp (combined: pass.cpp's create_pass) makes them, the buffers of
// run_sample_pass (sample_pass.h) and, for the texel sources, HARNESS_BINDING_SOURCE. A sample shader from
// elsewhere (`sample --spirv`, spirv_module.h) is held to it.
struct PassBinding {
    VkDescriptorType type;
    bool layered = false; // an image binding: a 2D array image
};
std::map<uint32_t, PassBinding> sample_pass_bindings(Resource resource);

// How many textures the harness's bindless variant declares (HARNESS_BINDLESS_COUNT): --layers for bindless.
constexpr int bindless_texture_count = HARNESS_BINDLESS_COUNT;

} // namespace tf
