#include "vulkan/pipelines.h"
#include "core/resource.h"
#include "harness/config.h"
#include "texture/error.h"
#include "vulkan/memory.h"
#include <cstring>
#include <map>
#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>
#include <unordered_map>

#include "mesh_frag.h"
#include "mesh_vert.h"
#include "minimal_comp.h"
#include "minimal_trilinear_comp.h"
#include "render_comp.h"
#include "render_frag.h"
#include "render_vert.h"
#include "sample_comp.h"

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

// The stage's module specialised on the host (specialize_spirv), or, where the optimiser refused it, the
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

namespace {

// The fixed-function state of the harness's graphics pipelines: no culling or blending, a depth test where
// there is a depth target, the viewport fixed to the description's size (or dynamic, size 0), dynamic
// rendering unless a render pass is given. Filled in place (fill_graphics_states): the infos point at members.
struct GraphicsStates {
    VkPipelineVertexInputStateCreateInfo no_vertices{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    VkViewport viewport{};
    VkRect2D scissor{};
    VkPipelineViewportStateCreateInfo viewport_state{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    VkDynamicState dynamic_states[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    VkPipelineDepthStencilStateCreateInfo depth_state{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    VkPipelineColorBlendAttachmentState blend_attachment{};
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    bool fixed_viewport = false;
};

void fill_graphics_states(const GraphicsPipelineDesc& desc, GraphicsStates& s)
{
    s.assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    s.viewport = {0.0f, 0.0f, float(desc.width), float(desc.height), 0.0f, 1.0f};
    s.scissor = {{0, 0}, {desc.width, desc.height}};
    s.viewport_state.viewportCount = 1;
    s.viewport_state.scissorCount = 1;
    s.fixed_viewport = desc.width && desc.height;
    if (s.fixed_viewport) {
        s.viewport_state.pViewports = &s.viewport;
        s.viewport_state.pScissors = &s.scissor;
    } else {
        s.dynamic.dynamicStateCount = 2;
        s.dynamic.pDynamicStates = s.dynamic_states;
    }
    s.raster.polygonMode = VK_POLYGON_MODE_FILL;
    s.raster.cullMode = VK_CULL_MODE_NONE;
    s.raster.lineWidth = 1.0f;
    s.multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    const bool depth = desc.depth_format != VK_FORMAT_UNDEFINED;
    s.depth_state.depthTestEnable = s.depth_state.depthWriteEnable = depth ? VK_TRUE : VK_FALSE;
    s.depth_state.depthCompareOp = VK_COMPARE_OP_LESS;
    s.blend_attachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                        VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    s.blend.attachmentCount = 1;
    s.blend.pAttachments = &s.blend_attachment;
    s.rendering.colorAttachmentCount = 1;
    s.rendering.pColorAttachmentFormats = &desc.color_format;
    s.rendering.depthAttachmentFormat = desc.depth_format;
}

} // namespace

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
    GraphicsStates states;
    fill_graphics_states(desc, states);

    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.pNext = desc.render_pass ? nullptr : &states.rendering;
    info.renderPass = desc.render_pass;
    info.pDynamicState = states.fixed_viewport ? nullptr : &states.dynamic;
    info.stageCount = 2;
    info.pStages = stages;
    info.pVertexInputState = desc.vertex_input ? desc.vertex_input : &states.no_vertices;
    info.pInputAssemblyState = &states.assembly;
    info.pViewportState = &states.viewport_state;
    info.pRasterizationState = &states.raster;
    info.pMultisampleState = &states.multisample;
    info.pDepthStencilState = &states.depth_state;
    info.pColorBlendState = &states.blend;
    info.layout = layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    TF_VK(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    cleanup.add([=] { vkDestroyPipeline(device, pipeline, nullptr); });
    return pipeline;
}

std::vector<uint32_t> specialize_spirv(ShaderCode code, FilterVariant variant)
{
    // The variant's spec_constants; a module without one of the ids keeps it absent.
    std::unordered_map<uint32_t, std::vector<uint32_t>> values;
    for (const SpecConstant& c : spec_constants(variant))
        values[c.id] = {uint32_t(c.value)};
    spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_2); // the harness targets Vulkan 1.2's SPIR-V 1.5
    optimizer.SetMessageConsumer([](spv_message_level_t, const char*, const spv_position_t&, const char*) {});
    optimizer.RegisterPass(spvtools::CreateSetSpecConstantDefaultValuePass(values))
        .RegisterPass(spvtools::CreateFreezeSpecConstantValuePass())
        .RegisterPass(spvtools::CreateFoldSpecConstantOpAndCompositePass())
        .RegisterPass(spvtools::CreateDeadBranchElimPass())
        .RegisterPass(spvtools::CreateEliminateDeadFunctionsPass());
    spvtools::OptimizerOptions options;
    options.set_run_validator(false);
    std::vector<uint32_t> out;
    if (!optimizer.Run(code.words, code.bytes / sizeof(uint32_t), &out, options))
        out.clear();
    return out;
}

ShaderCode harness_shader_uint(HarnessShader shader)
{
    auto code = [](SpirvWords w) { return ShaderCode{w.words, w.bytes}; };
    switch (shader) {
    case HarnessShader::render_frag: return code(render_frag_spirv_uint());
    case HarnessShader::render_comp: return code(render_comp_spirv_uint());
    case HarnessShader::mesh_frag: return code(mesh_frag_spirv_uint());
    case HarnessShader::sample_comp: return code(sample_comp_spirv_uint());
    case HarnessShader::render_vert: // the vertex stages read no texture: one build serves every binding
    case HarnessShader::mesh_vert:
    case HarnessShader::minimal_comp:
        break;
    case HarnessShader::minimal_trilinear_comp: // reads a float sampler2D: the bench runs it on float formats only
        throw Error("the minimal trilinear pass reads a float texture, not an integer one");
        break;
    }
    return harness_shader(shader, TextureFormat::rgba32f);
}

ShaderCode harness_shader(HarnessShader shader, TextureFormat format)
{
    if (format_info(format).integer)
        return harness_shader_uint(shader);
    switch (shader) {
    case HarnessShader::render_vert: return {render_vert, sizeof(render_vert)};
    case HarnessShader::render_frag: return {render_frag, sizeof(render_frag)};
    case HarnessShader::render_comp: return {render_comp, sizeof(render_comp)};
    case HarnessShader::mesh_vert: return {mesh_vert, sizeof(mesh_vert)};
    case HarnessShader::mesh_frag: return {mesh_frag, sizeof(mesh_frag)};
    case HarnessShader::sample_comp: return {sample_comp, sizeof(sample_comp)};
    case HarnessShader::minimal_comp: return {minimal_comp, sizeof(minimal_comp)};
    case HarnessShader::minimal_trilinear_comp: return {minimal_trilinear_comp, sizeof(minimal_trilinear_comp)};
    }
    return {sample_comp, sizeof(sample_comp)};
}

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

namespace {

constexpr uint32_t kMagic = 0x07230203;

// The few opcodes, decorations and storage classes read here (SPIR-V specification, section 3).
enum : uint32_t {
    OpEntryPoint = 15, OpTypeImage = 25, OpTypeSampler = 26, OpTypeSampledImage = 27, OpTypeArray = 28,
    OpTypeRuntimeArray = 29, OpTypeStruct = 30, OpTypePointer = 32, OpVariable = 59, OpDecorate = 71,
    OpMemberDecorate = 72,
    DecorationBufferBlock = 3, DecorationOffset = 35, DecorationBinding = 33, DecorationDescriptorSet = 34,
    StorageUniformConstant = 0, StorageUniform = 2, StoragePushConstant = 9, StorageStorageBuffer = 12,
    ExecutionModelGLCompute = 5,
};

// A descriptor as the module declares it: its type, and for an image whether it is a 2D array.
struct Declared {
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM; // MAX_ENUM: a resource of no kind the pass binds
    bool layered = false;
};
std::string to_string(VkDescriptorType type, bool layered)
{
    const std::string image = layered ? " (2D array)" : " (2D)";
    switch (type) {
    case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER: return "a combined image sampler" + image;
    case VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE: return "a sampled image" + image;
    case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE: return "a storage image";
    case VK_DESCRIPTOR_TYPE_SAMPLER: return "a sampler";
    case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER: return "a storage buffer";
    case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER: return "a uniform buffer";
    default: break;
    }
    return "a resource of another kind";
}

struct Instruction {
    uint32_t opcode;
    const uint32_t* operands; // after the opcode word
    uint32_t count;           // operands
};

// The module's instructions (the validator has checked their word counts).
std::vector<Instruction> instructions(const std::vector<uint32_t>& words)
{
    std::vector<Instruction> all;
    for (size_t i = 5; i < words.size();) {
        const uint32_t n = words[i] >> 16;
        all.push_back({words[i] & 0xffffu, &words[i + 1], n - 1});
        i += n;
    }
    return all;
}

// The interface the sample pass of `resource` gives the shader (see the header); throws naming the first mismatch.
// What check_interface reads of a module: its decorations, the types resources are declared with, and
// whether it has the entry point.
struct ModuleInterface {
    std::map<uint32_t, uint32_t> binding, set, type_of_pointer, storage_of_pointer;
    std::map<uint32_t, Instruction> types;
    std::map<uint32_t, uint32_t> largest_offset; // struct id -> largest member Offset
    std::map<uint32_t, bool> buffer_block;
    bool entry = false;
};

ModuleInterface read_interface(const std::vector<Instruction>& module)
{
    ModuleInterface m;
    auto& [binding, set, type_of_pointer, storage_of_pointer, types, largest_offset, buffer_block, entry] = m;
    for (const Instruction& in : module) {
        if (in.opcode == OpEntryPoint && in.count >= 3 && in.operands[0] == ExecutionModelGLCompute &&
            std::strncmp(reinterpret_cast<const char*>(&in.operands[2]), "main", 5) == 0)
            entry = true;
        if (in.opcode == OpDecorate && in.count >= 3 && in.operands[1] == DecorationBinding)
            binding[in.operands[0]] = in.operands[2];
        if (in.opcode == OpDecorate && in.count >= 3 && in.operands[1] == DecorationDescriptorSet)
            set[in.operands[0]] = in.operands[2];
        if (in.opcode == OpDecorate && in.count >= 2 && in.operands[1] == DecorationBufferBlock)
            buffer_block[in.operands[0]] = true;
        if (in.opcode == OpMemberDecorate && in.count >= 4 && in.operands[2] == DecorationOffset)
            largest_offset[in.operands[0]] = std::max(largest_offset[in.operands[0]], in.operands[3]);
        if (in.opcode == OpTypeImage || in.opcode == OpTypeSampler || in.opcode == OpTypeSampledImage ||
            in.opcode == OpTypeArray || in.opcode == OpTypeRuntimeArray || in.opcode == OpTypeStruct)
            types.insert({in.operands[0], in});
        if (in.opcode == OpTypePointer && in.count >= 3) {
            storage_of_pointer[in.operands[0]] = in.operands[1];
            type_of_pointer[in.operands[0]] = in.operands[2];
        }
    }
    return m;
}

// The descriptor type (and 2D array or not) a resource variable of `storage` and pointee `type` declares.
Declared declared_resource(const ModuleInterface& m, uint32_t storage, uint32_t type)
{
    const std::map<uint32_t, Instruction>& types = m.types;
    auto t = types.find(type);
    while (t != types.end() && (t->second.opcode == OpTypeArray || t->second.opcode == OpTypeRuntimeArray))
        t = types.find(t->second.operands[1]);
    const uint32_t op = t == types.end() ? 0 : t->second.opcode;
    // OpTypeImage's operands: result, sampled type, Dim, Depth, Arrayed (4), MS, Sampled (6: 1 sampled, 2 storage)
    auto layered = [&](uint32_t image) {
        auto i = types.find(image);
        return i != types.end() && i->second.opcode == OpTypeImage && i->second.count > 4 && i->second.operands[4] == 1;
    };
    if (storage == StorageUniformConstant && op == OpTypeSampledImage)
        return {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, layered(t->second.operands[1])};
    if (storage == StorageUniformConstant && op == OpTypeImage)
        return {t->second.count > 6 && t->second.operands[6] == 2 ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE
                                                                   : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE,
                layered(t->first)};
    if (storage == StorageUniformConstant && op == OpTypeSampler)
        return {VK_DESCRIPTOR_TYPE_SAMPLER};
    if (op == OpTypeStruct && storage == StorageStorageBuffer)
        return {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER};
    if (op == OpTypeStruct && storage == StorageUniform) {
        auto block = m.buffer_block.find(t->first);
        return {block != m.buffer_block.end() && block->second ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER
                                                               : VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER};
    }
    return {};
}

void check_interface(const std::vector<uint32_t>& words, const std::string& name, Resource resource)
{
    const std::vector<Instruction> module = instructions(words);
    ModuleInterface m = read_interface(module);
    auto& [binding, set, type_of_pointer, storage_of_pointer, types, largest_offset, buffer_block, entry] = m;
    if (!entry)
        throw Error(name + ": has no GLCompute entry point named 'main' (the sample pass's compute shader)");
    const std::map<uint32_t, PassBinding> expected_bindings = sample_pass_bindings(resource);
    const std::string pass = "the sample pass of --resource " + to_string(resource);
    const std::string build = " (--resource " + to_string(resource) +
                              " runs shaders/harness/sample.comp.glsl compiled with -DHARNESS_RESOURCE=" +
                              std::to_string(int(resource)) + ")";
    for (const Instruction& in : module) {
        if (in.opcode != OpVariable || in.count < 3)
            continue;
        const uint32_t id = in.operands[1], storage = in.operands[2];
        const uint32_t pointee = type_of_pointer[in.operands[0]];
        if (storage == StoragePushConstant && largest_offset[pointee] >= HARNESS_PUSH_SIZE)
            throw Error(name + ": a push constant at byte " + std::to_string(largest_offset[pointee]) +
                        ", beyond the " + std::to_string(HARNESS_PUSH_SIZE) + " bytes the sample pass pushes");
        if (!binding.count(id))
            continue;
        const std::string where = "binding " + std::to_string(binding[id]);
        if (set[id] != 0)
            throw Error(name + ": a resource in descriptor set " + std::to_string(set[id]) + "; " + pass +
                        " binds set 0 only");
        const auto expected = expected_bindings.find(binding[id]);
        if (expected == expected_bindings.end())
            throw Error(name + ": a resource at " + where + ", which " + pass + " does not bind" + build);
        const Declared found = declared_resource(m, storage, pointee);
        const PassBinding& want = expected->second;
        if (found.type != want.type || found.layered != want.layered)
            throw Error(name + ": " + where + " is " + to_string(found.type, found.layered) + "; " + pass +
                        " binds " + to_string(want.type, want.layered) + " there" + build);
    }
}

} // namespace

std::vector<uint32_t> check_sample_spirv(const std::string& bytes, const std::string& name, Resource resource)
{
    if (bytes.empty())
        throw Error(name + ": empty (expected a SPIR-V module)");
    if (bytes.size() % 4 != 0)
        throw Error(name + ": " + std::to_string(bytes.size()) +
                    " bytes, not a whole number of 32-bit words: not a SPIR-V module");
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), bytes.size());
    if (words[0] != kMagic)
        throw Error(name + ": not a SPIR-V module (" +
                    std::string(__builtin_bswap32(words[0]) == kMagic ? "the other byte order than this machine's"
                                                                      : "no SPIR-V magic number") + ")");
    spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_2); // the harness's target (texfilter_add_shaders: vulkan1.2)
    std::string first;
    tools.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t&, const char* message) {
        if (first.empty())
            first = message;
    });
    if (!tools.Validate(words))
        throw Error(name + ": not valid SPIR-V for Vulkan 1.2 (" + (first.empty() ? "the validator says no more" : first) +
                    ")");
    check_interface(words, name, resource);
    return words;
}

// The plain Vulkan objects of the GPU builds' compute passes.
VkDescriptorSetLayout create_set_layout(const VulkanContext& context,
                                        const std::vector<VkDescriptorSetLayoutBinding>& bindings, Cleanup& cleanup)
{
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = uint32_t(bindings.size());
    info.pBindings = bindings.data();
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    TF_VK(vkCreateDescriptorSetLayout(context.device, &info, nullptr, &layout));
    VkDevice device = context.device;
    cleanup.add([=] { vkDestroyDescriptorSetLayout(device, layout, nullptr); });
    return layout;
}

VkPipelineLayout create_push_layout(const VulkanContext& context, VkDescriptorSetLayout set_layout,
                                    uint32_t push_bytes, Cleanup& cleanup)
{
    VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, push_bytes};
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = 1;
    info.pSetLayouts = &set_layout;
    info.pushConstantRangeCount = 1;
    info.pPushConstantRanges = &range;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    TF_VK(vkCreatePipelineLayout(context.device, &info, nullptr, &layout));
    VkDevice device = context.device;
    cleanup.add([=] { vkDestroyPipelineLayout(device, layout, nullptr); });
    return layout;
}

VkDescriptorSet allocate_set(const VulkanContext& context, VkDescriptorSetLayout layout,
                             const std::vector<VkDescriptorPoolSize>& sizes, VkDescriptorPool& pool, Cleanup& cleanup)
{
    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = 1;
    pool_info.poolSizeCount = uint32_t(sizes.size());
    pool_info.pPoolSizes = sizes.data();
    TF_VK(vkCreateDescriptorPool(context.device, &pool_info, nullptr, &pool));
    VkDevice device = context.device;
    VkDescriptorPool created = pool;
    cleanup.add([=] { vkDestroyDescriptorPool(device, created, nullptr); }); // frees the set too
    VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocate.descriptorPool = pool;
    allocate.descriptorSetCount = 1;
    allocate.pSetLayouts = &layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    TF_VK(vkAllocateDescriptorSets(context.device, &allocate, &set));
    return set;
}

VkImageView create_level_view(const VulkanContext& context, VkImage image, VkFormat format, uint32_t level,
                              Cleanup& cleanup)
{
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = image;
    info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    info.format = format;
    info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, level, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    TF_VK(vkCreateImageView(context.device, &info, nullptr, &view));
    VkDevice device = context.device;
    cleanup.add([=] { vkDestroyImageView(device, view, nullptr); });
    return view;
}

} // namespace tf
