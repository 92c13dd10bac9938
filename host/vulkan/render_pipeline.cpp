#include "vulkan/render_pipeline.h"
#include "harness/config.h"
#include "texture/error.h"
#include "vulkan/harness_shaders.h"
#include "vulkan/mesh.h"
#include "vulkan/pipeline.h"
#include "vulkan/render_targets.h"
#include <cstddef>


namespace tf {

void check_render_kind(const VulkanContext& context, RenderKind kind)
{
    if (kind != RenderKind::compute)
        return;
    if (!context.info.quad_ops_compute)
        throw Error(context.info.name + " has no subgroup quad operations in compute shaders: use --stage fragment");
    if (context.info.subgroup_size % 4 != 0 || (HARNESS_RENDER_TILE * HARNESS_RENDER_TILE) % context.info.subgroup_size != 0)
        throw Error("the compute render lays 2x2 quads over subgroups of " +
                    std::to_string(context.info.subgroup_size) + " invocations, which it cannot do");
}

VkPipeline create_render_pipeline(const VulkanContext& context, RenderKind kind, VkPipelineLayout layout,
                                  FilterVariant filter, uint32_t width, uint32_t height, Cleanup& cleanup,
                                  TextureFormat format)
{
    if (filter.minimal != MinimalPass::none && kind != RenderKind::compute)
        throw Error("the bench's minimal pass is a compute shader: it needs --stage compute");
    if (kind == RenderKind::compute) {
        const HarnessShader shader = filter.minimal == MinimalPass::no_texture  ? HarnessShader::minimal_comp
                                     : filter.minimal == MinimalPass::trilinear ? HarnessShader::minimal_trilinear_comp
                                                                                : HarnessShader::render_comp;
        return create_compute_pipeline(context, harness_shader(shader, format), layout, filter, cleanup);
    }

    GraphicsPipelineDesc desc;
    desc.color_format = render_color_format;
    desc.width = width;
    desc.height = height;
    if (kind == RenderKind::fragment) {
        desc.vertex = harness_shader(HarnessShader::render_vert, format);
        desc.fragment = harness_shader(HarnessShader::render_frag, format);
        return create_graphics_pipeline(context, desc, layout, filter, cleanup);
    }
    VkVertexInputBindingDescription binding{0, sizeof(MeshVertex), VK_VERTEX_INPUT_RATE_VERTEX};
    VkVertexInputAttributeDescription attributes[2] = {
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, uint32_t(offsetof(MeshVertex, position))},
        {1, 0, VK_FORMAT_R32G32_SFLOAT, uint32_t(offsetof(MeshVertex, uv))}};
    VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertex_input.vertexBindingDescriptionCount = 1;
    vertex_input.pVertexBindingDescriptions = &binding;
    vertex_input.vertexAttributeDescriptionCount = 2;
    vertex_input.pVertexAttributeDescriptions = attributes;
    desc.vertex = harness_shader(HarnessShader::mesh_vert, format);
    desc.fragment = harness_shader(HarnessShader::mesh_frag, format);
    desc.vertex_input = &vertex_input;
    desc.depth_format = render_depth_format;
    return create_graphics_pipeline(context, desc, layout, filter, cleanup);
}

VkPipeline cached_render_pipeline(const VulkanContext& context, RenderPipelineCache& cache, RenderKind kind,
                                  VkPipelineLayout layout, FilterVariant filter, uint32_t width, uint32_t height,
                                  TextureFormat format)
{
    const bool integer = format_info(format).integer;
    const bool sized = kind != RenderKind::compute; // graphics pipelines fix their viewport
    for (const RenderPipelineCache::Entry& e : cache.entries)
        if (e.kind == kind && e.filter == filter && e.integer == integer &&
            (!sized || (e.width == width && e.height == height)))
            return e.pipeline;
    const VkPipeline pipeline = create_render_pipeline(context, kind, layout, filter, width, height, cache.cleanup, format);
    cache.entries.push_back({kind, filter, width, height, integer, pipeline});
    return pipeline;
}

} // namespace tf
