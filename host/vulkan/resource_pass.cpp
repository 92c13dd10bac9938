#include "vulkan/resource_pass.h"

#include "harness/config.h"
#include "texture/error.h"
#include "vulkan/sample_resource.h"
#include "vulkan/samplers.h"

namespace tf {

Pass create_resource_pass(const VulkanContext& context, const GpuResources& resources, const HarnessVariant& variant,
                          const SamplerOptions& options, const ResourceOptions& resource, VkShaderStageFlags stages,
                          const std::vector<PassBuffer>& buffers, Cleanup& cleanup)
{
    VkDevice device = context.device;
    // The filter's sampler (hw-* state, or trilinear with the wrap mode for hardware taps), as for the
    // combined kind; shadow adds the depth comparison (Vulkan compares each texel before filtering).
    VkSamplerCreateInfo info = sampler_create_info(context, options, resources.levels);
    if (resource.resource == Resource::shadow) {
        info.compareEnable = VK_TRUE;
        info.compareOp = VkCompareOp(resource.compare);
        // The manual filters only texelFetch the depth image; a nearest sampler keeps them free of the
        // linear-filter feature depth formats need not have.
        if (!uses_hardware_lookups(options)) {
            info.magFilter = info.minFilter = VK_FILTER_NEAREST;
            info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
        }
    }
    VkSampler sampler = VK_NULL_HANDLE;
    TF_VK(vkCreateSampler(device, &info, nullptr, &sampler));
    cleanup.add([=] { vkDestroySampler(device, sampler, nullptr); });
    // The SAT placeholders (1x1 zeros) with the base texture's own pass samplers.
    const PassSamplers base = create_pass_samplers(context, resources.base, options, cleanup);

    const VkImageLayout read = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    const VkSampler texture_sampler = variant.separate_sampler ? VK_NULL_HANDLE : sampler;
    std::vector<VkDescriptorImageInfo> textures;
    switch (resource.resource) {
    case Resource::combined:
    case Resource::separate: textures.push_back({texture_sampler, resources.base.chain.view, read}); break;
    case Resource::array:
    case Resource::separate_array: textures.push_back({texture_sampler, resources.layered.view, read}); break;
    case Resource::bindless:
        textures.push_back({texture_sampler, resources.base.chain.view, read});
        for (const GpuTexture& t : resources.textures)
            textures.push_back({texture_sampler, t.chain.view, read});
        break;
    case Resource::shadow: textures.push_back({texture_sampler, resources.depth.view, read}); break;
    case Resource::atlas:
    case Resource::virtual_texture: textures.push_back({texture_sampler, resources.base.chain.view, read}); break;
    }
    if (textures.size() != variant.texture_count)
        throw Error("--resource " + to_string(resource.resource) + ": the shader binds " +
                    std::to_string(variant.texture_count) + " textures, the resource holds " +
                    std::to_string(textures.size()));
    // The summed-area table as the kind declares it (filter_select.glsl): usampler2D, utexture2D for the
    // separate kinds, arrays of one layer (views of the same images) for the array kinds.
    VkDescriptorImageInfo low = base.infos[1], high = base.infos[2];
    if (resources.sat_low_array) {
        low.imageView = resources.sat_low_array;
        high.imageView = resources.sat_high_array;
    }
    if (variant.table_type == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE)
        low.sampler = high.sampler = VK_NULL_HANDLE;
    std::vector<PassImages> images = {{HARNESS_BINDING_TEXTURE, variant.texture_type, textures},
                                      {HARNESS_BINDING_SAT_LOW, variant.table_type, {low}},
                                      {HARNESS_BINDING_SAT_HIGH, variant.table_type, {high}}};
    if (variant.separate_sampler)
        images.push_back({HARNESS_BINDING_SAMPLER, VK_DESCRIPTOR_TYPE_SAMPLER, {{sampler, VK_NULL_HANDLE, read}}});
    std::vector<PassBuffer> all = buffers;
    if (is_texel_source(resource.resource)) // the words texel_sources.glsl reads
        all.push_back({HARNESS_BINDING_SOURCE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, resources.source.buffer});
    return create_pass_with_images(context, images, stages, stages, all, cleanup);
}

} // namespace tf
