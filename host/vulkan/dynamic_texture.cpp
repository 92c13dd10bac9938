// The dynamic texture: its generator pipeline and each frame's commands.
#include "vulkan/dynamic_texture.h"
#include "texture/error.h"
#include "vulkan/barriers.h"
#include "vulkan/compute_objects.h"
#include "vulkan/pipeline.h"

#include "dynamic_texture_comp.h"

namespace tf {

namespace {

struct GeneratorPush {
    int32_t size, frame;
};

} // namespace

DynamicTexture create_dynamic_texture(const VulkanContext& context, int size)
{
    DynamicTexture d;
    d.size = size;
    d.build = prepare_gpu_build(context, nullptr, size, size, false, TextureFormat::rgba32f);
    Cleanup on_failure;
    on_failure.add([&] { destroy_dynamic_texture(context, d); });
    d.objects = std::make_shared<Cleanup>();
    Cleanup& objects = *d.objects;
    d.set_layout = create_set_layout(context, {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}},
                                     objects);
    d.layout = create_push_layout(context, d.set_layout, sizeof(GeneratorPush), objects);
    d.pipeline = create_compute_pipeline(context, {dynamic_texture_comp, sizeof(dynamic_texture_comp)}, d.layout,
                                         Filter::nearest, objects);
    d.set = allocate_set(context, d.set_layout, {{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}}, d.pool, objects);
    const VkDescriptorImageInfo image{VK_NULL_HANDLE, d.build.mip.level_views[0], VK_IMAGE_LAYOUT_GENERAL};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = d.set;
    write.dstBinding = 0;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    write.pImageInfo = &image;
    vkUpdateDescriptorSets(context.device, 1, &write, 0, nullptr);
    on_failure.dismiss();
    return d;
}

void record_dynamic_frame(VkCommandBuffer cb, DynamicTexture& d, int frame)
{
    const uint32_t levels = uint32_t(d.build.texture.levels);
    // The last frame's reads (fragment or compute) before this frame's writes; the first frame discards.
    image_barrier(cb, d.build.built.image, levels,
                  d.first ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                  d.first ? 0 : VK_ACCESS_SHADER_READ_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT,
                  d.first ? VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT
                          : VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                  VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, d.pipeline);
    vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, d.layout, 0, 1, &d.set, 0, nullptr);
    const GeneratorPush push{d.size, frame};
    vkCmdPushConstants(cb, d.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdDispatch(cb, uint32_t(d.size + 15) / 16, uint32_t(d.size + 15) / 16, 1);
    record_gpu_build(cb, d.build, d.first ? Level0::written_first : Level0::written);
    d.first = false;
}

void destroy_dynamic_texture(const VulkanContext& context, DynamicTexture& d)
{
    d.objects.reset();
    destroy_gpu_build(context, d.build);
    d = DynamicTexture{};
}

} // namespace tf
