#include "vulkan/harness_variant.h"

#include "core/resource.h"
#include "harness/config.h"
#include "vulkan/harness_spirv.h"

#include "sample_comp.h"

namespace tf {

namespace {

ShaderCode code(SpirvWords w) { return {w.words, w.bytes}; }

} // namespace

HarnessVariant harness_variant(Resource resource, uint32_t textures)
{
    const VkDescriptorType combined = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    // {SPIR-V, texture descriptors, how many, the SAT tables' descriptors, a separate sampler, non-uniform,
    // 2D array images}
    switch (resource) {
    case Resource::combined: return {{sample_comp, sizeof(sample_comp)}, combined, 1, combined};
    case Resource::separate: return {code(sample_spirv_separate()), sampled, 1, sampled, true};
    case Resource::array: return {code(sample_spirv_array()), combined, 1, combined, false, false, true};
    case Resource::separate_array:
        return {code(sample_spirv_separate_array()), sampled, 1, sampled, true, false, true};
    case Resource::bindless: return {code(sample_spirv_bindless()), combined, textures, combined, false, true};
    case Resource::shadow: return {code(sample_spirv_shadow()), sampled, 1, combined, true};
    case Resource::atlas: return {code(sample_spirv_atlas()), combined, 1, combined};
    case Resource::virtual_texture: return {code(sample_spirv_virtual()), combined, 1, combined};
    }
    return {{sample_comp, sizeof(sample_comp)}, combined, 1, combined};
}

std::map<uint32_t, PassBinding> sample_pass_bindings(Resource resource)
{
    const HarnessVariant v = harness_variant(resource, 1);
    const VkDescriptorType buffer = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    std::map<uint32_t, PassBinding> bindings = {
        {HARNESS_BINDING_TEXTURE, {v.texture_type, v.layered}}, {HARNESS_BINDING_SAT_LOW, {v.table_type, v.layered}},
        {HARNESS_BINDING_SAT_HIGH, {v.table_type, v.layered}},  {HARNESS_BINDING_LOOKUPS, {buffer}},
        {HARNESS_BINDING_RESULTS, {buffer}},                    {HARNESS_BINDING_STATS, {buffer}}};
    if (v.separate_sampler)
        bindings[HARNESS_BINDING_SAMPLER] = {VK_DESCRIPTOR_TYPE_SAMPLER};
    if (is_texel_source(resource))
        bindings[HARNESS_BINDING_SOURCE] = {buffer};
    return bindings;
}

} // namespace tf
