#include "vulkan/pipeline.h"
#include "harness/config.h"
#include "vulkan/resources.h"
#include "vulkan/specialize_spirv.h"

namespace tf {

namespace {

// The variant's spec_constants as a VkSpecializationInfo (shaders that declare only some ignore the others);
// info points into the struct, so keep it alive until the pipeline is made.
struct FilterSpecialization {
    std::array<int32_t, 7> values;
    std::array<VkSpecializationMapEntry, 7> entries;
    VkSpecializationInfo info;

    explicit FilterSpecialization(FilterVariant variant)
    {
        const std::array<SpecConstant, 7> constants = spec_constants(variant);
        for (size_t k = 0; k < constants.size(); ++k) {
            values[k] = constants[k].value;
            entries[k] = {constants[k].id, uint32_t(k * sizeof(int32_t)), sizeof(int32_t)};
        }
        info = {uint32_t(entries.size()), entries.data(), sizeof(values), values.data()};
    }
    FilterSpecialization(const FilterSpecialization&) = delete;
};

VkPipelineShaderStageCreateInfo shader_stage(VkShaderStageFlagBits stage, VkShaderModule module,
                                             const VkSpecializationInfo* specialization)
{
    VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage = stage;
    info.module = module;
    info.pName = "main";
    info.pSpecializationInfo = specialization;
    return info;
}

// The stage's module specialised on the host (specialize_spirv.h), or, where the optimiser refused it, the
// module as embedded with `specialization` for the driver to apply. Destroyed by `modules`.
struct SpecializedModule {
    VkShaderModule module = VK_NULL_HANDLE;
    const VkSpecializationInfo* info = nullptr;
};
SpecializedModule specialized_module(const VulkanContext& context, ShaderCode code, FilterVariant variant,
                                     const FilterSpecialization& specialization, Cleanup& modules)
{
    const std::vector<uint32_t> words = specialize_spirv(code, variant);
    SpecializedModule m;
    m.module = words.empty() ? create_shader_module(context, code.words, code.bytes)
                             : create_shader_module(context, words.data(), words.size() * sizeof(uint32_t));
    m.info = words.empty() ? &specialization.info : nullptr;
    VkDevice device = context.device;
    VkShaderModule module = m.module;
    modules.add([=] { vkDestroyShaderModule(device, module, nullptr); });
    return m;
}

} // namespace

VkPipeline create_compute_pipeline(const VulkanContext& context, ShaderCode code, VkPipelineLayout layout,
                                   FilterVariant filter, Cleanup& cleanup)
{
    VkDevice device = context.device;
    Cleanup modules; // a pipeline keeps what it needs of its modules: they go once it is made
    FilterSpecialization specialization(filter);
    const SpecializedModule stage = specialized_module(context, code, filter, specialization, modules);
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = shader_stage(VK_SHADER_STAGE_COMPUTE_BIT, stage.module, stage.info);
    info.layout = layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    TF_VK(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    cleanup.add([=] { vkDestroyPipeline(device, pipeline, nullptr); });
    return pipeline;
}

VkPipeline create_graphics_pipeline(const VulkanContext& context, const GraphicsPipelineDesc& desc,
                                    VkPipelineLayout layout, FilterVariant filter, Cleanup& cleanup)
{
    VkDevice device = context.device;
    Cleanup modules;
    VkShaderModule vert = create_shader_module(context, desc.vertex.words, desc.vertex.bytes);
    modules.add([=] { vkDestroyShaderModule(device, vert, nullptr); });
    FilterSpecialization specialization(filter);
    const SpecializedModule frag = specialized_module(context, desc.fragment, filter, specialization, modules);
    VkPipelineShaderStageCreateInfo stages[2] = {
        shader_stage(VK_SHADER_STAGE_VERTEX_BIT, vert, nullptr),
        shader_stage(VK_SHADER_STAGE_FRAGMENT_BIT, frag.module, frag.info)};

    const bool depth = desc.depth_format != VK_FORMAT_UNDEFINED;
    VkPipelineVertexInputStateCreateInfo no_vertices{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkViewport viewport{0.0f, 0.0f, float(desc.width), float(desc.height), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, {desc.width, desc.height}};
    VkPipelineViewportStateCreateInfo viewport_state{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport_state.viewportCount = 1;
    viewport_state.scissorCount = 1;
    const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    const bool fixed_viewport = desc.width && desc.height;
    if (fixed_viewport) {
        viewport_state.pViewports = &viewport;
        viewport_state.pScissors = &scissor;
    } else {
        dynamic.dynamicStateCount = 2;
        dynamic.pDynamicStates = dynamic_states;
    }
    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = VK_CULL_MODE_NONE;
    raster.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo depth_state{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depth_state.depthTestEnable = depth_state.depthWriteEnable = depth ? VK_TRUE : VK_FALSE;
    depth_state.depthCompareOp = VK_COMPARE_OP_LESS;
    VkPipelineColorBlendAttachmentState blend_attachment{};
    blend_attachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                      VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = 1;
    blend.pAttachments = &blend_attachment;
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachmentFormats = &desc.color_format;
    rendering.depthAttachmentFormat = desc.depth_format;

    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.pNext = desc.render_pass ? nullptr : &rendering;
    info.renderPass = desc.render_pass;
    info.pDynamicState = fixed_viewport ? nullptr : &dynamic;
    info.stageCount = 2;
    info.pStages = stages;
    info.pVertexInputState = desc.vertex_input ? desc.vertex_input : &no_vertices;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewport_state;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth_state;
    info.pColorBlendState = &blend;
    info.layout = layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    TF_VK(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    cleanup.add([=] { vkDestroyPipeline(device, pipeline, nullptr); });
    return pipeline;
}

} // namespace tf
