#pragma once
// Descriptors and pipelines: the descriptor layout and push constants every harness pass shares, shader
// modules specialised to a filter, the harness's embedded SPIR-V and its variants (a resource kind, an
// environment kind, the GPU build's), a SPIR-V module from outside checked before use, and the plain objects
// a compute pass makes.
#include "core/filter.h"
#include "core/resource.h"
#include "core/texture_format.h"
#include "harness/config.h"
#include "scene/scene.h"
#include "vulkan/cleanup.h"
#include "vulkan/device.h"
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace tf {

// Pipelines from embedded SPIR-V, each specialised to one filter (the harness shaders' specialization
// constants HARNESS_SPEC_FILTER, HARNESS_SPEC_MAGNIFY and HARNESS_SPEC_STOCHASTIC) and, for render, to one
// debug view, one gradient form, a number of lookups a pixel and one scene kind (HARNESS_SPEC_VIEW,
// HARNESS_SPEC_GRADIENTS, HARNESS_SPEC_LOOKUPS, HARNESS_SPEC_SCENE), so that a pipeline holds the
// code of one filter only and a frame runs only what it shows.
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
// VkSpecializationInfo and the host-side specialisation (specialize_spirv below).
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

// The harness's SPIR-V specialised on the host before the driver sees it: its specialization constants
// (spec_constants above) frozen to one FilterVariant and the code they rule out removed.
//
// Why: the harness shaders hold every filter behind those constants (240 KB of SPIR-V for render.frag). A
// driver may inline every function before it folds them: lavapipe (Mesa 22.3) spent ~0.9 s of NIR work a
// pipeline on the whole module, against ~0.1 s on the specialised one, on every pipeline even with a warm
// shader cache. The passes (SPIRV-Tools: set and freeze the constants, fold what depends on them, drop dead
// branches and uncalled functions) change no instruction that is kept, so the pipeline computes the same values.
//
// Use: std::vector<uint32_t> words = specialize_spirv(code, variant); an empty result means "not
// specialised" (the optimiser refused the module): use `code` with a VkSpecializationInfo instead.
// Cost: ~0.1 s for the largest harness module, no validation pass (the module came from glslang).
std::vector<uint32_t> specialize_spirv(ShaderCode code, FilterVariant variant);

// Embedded SPIR-V variants, each by its own object library (host/vulkan/CMakeLists.txt, tf_spirv_variant)
// whose one source, spirv_embed.cpp, defines the function under the variant's name. The harness's
// sample.comp.glsl once a resource kind (-DHARNESS_RESOURCE=N):
struct SpirvWords {
    const uint32_t* words;
    size_t bytes;
};

SpirvWords sample_spirv_separate();
SpirvWords sample_spirv_array();
SpirvWords sample_spirv_separate_array();
SpirvWords sample_spirv_bindless();
SpirvWords sample_spirv_shadow();
SpirvWords sample_spirv_atlas();
SpirvWords sample_spirv_virtual();
// render_env.frag.glsl once an environment map kind (-DHARNESS_ENV=HARNESS_ENV_CUBE / _LATLONG).
SpirvWords env_spirv_cube();
SpirvWords env_spirv_latlong();

// build_sat.comp.glsl compiled with -DTF_SAT_NO_FP64 (devices without shaderFloat64).
SpirvWords build_sat_spirv_fp32();
// pack_level.comp.glsl with each integer view format.
SpirvWords pack_spirv_rgba8ui();
SpirvWords pack_spirv_rgba16ui();
SpirvWords pack_spirv_r8ui();
SpirvWords pack_spirv_r16ui();
SpirvWords pack_spirv_r32ui();

// The harness shaders' SPIR-V for the way a texture is bound: the combined sampler2D build (every float
// format) or the HARNESS_RESOURCE_UINT build (usampler2D u_texture: r16ui, r32ui), the same sources
// compiled with -DHARNESS_RESOURCE=HARNESS_RESOURCE_UINT (host/vulkan/CMakeLists.txt).
enum class HarnessShader { render_vert, render_frag, render_comp, mesh_vert, mesh_frag, sample_comp,
                           minimal_comp, minimal_trilinear_comp }; // the last two: the bench's minimal pass

ShaderCode harness_shader(HarnessShader shader, TextureFormat format);

// The HARNESS_RESOURCE_UINT build: the four shaders that read the texture, each embedded as a variant.
ShaderCode harness_shader_uint(HarnessShader shader);
SpirvWords render_frag_spirv_uint();
SpirvWords render_comp_spirv_uint();
SpirvWords mesh_frag_spirv_uint();
SpirvWords sample_comp_spirv_uint();

// Which harness shader a resource kind runs and what it binds at HARNESS_BINDING_TEXTURE (and, for the
// kinds with a separate sampler, HARNESS_BINDING_SAMPLER): the one place that choice is made, so that a
// kind chosen by something else (an integer format's HARNESS_RESOURCE_UINT) is one more case here.
//
// Use: HarnessVariant v = harness_variant(resource, textures); create the pass with v's descriptors
// (sample.h), the pipeline from v.sample. Cost: none (tables).
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
// the sampler as sample.cpp (combined: render.cpp's create_pass) makes them, the buffers of
// run_sample_pass (sample.h) and, for the texel sources, HARNESS_BINDING_SOURCE. A sample shader from
// elsewhere (`sample --spirv`, check_sample_spirv below) is held to it.
struct PassBinding {
    VkDescriptorType type;
    bool layered = false; // an image binding: a 2D array image
};
std::map<uint32_t, PassBinding> sample_pass_bindings(Resource resource);

// How many textures the harness's bindless variant declares (HARNESS_BINDLESS_COUNT): --layers for bindless.
constexpr int bindless_texture_count = HARNESS_BINDLESS_COUNT;

// A SPIR-V module from outside the build (`texfilter sample --spirv FILE`: the harness's sample.comp.glsl
// compiled by another compiler, e.g. Slang's slangc), checked before any work as every input is: SPIR-V at
// all, valid for Vulkan 1.2, and shaped to take the place of the built-in sample shader (its entry point and
// the descriptor bindings and push constants the sample pass of its resource kind provides). What the driver
// would otherwise meet as undefined behaviour is one message naming the file.
//
// Use: std::vector<uint32_t> words = check_sample_spirv(bytes, path, Resource::combined); then
// ShaderCode{words.data(), bytes}.
// Cost: one SPIRV-Tools validation (~10 ms for the harness module).
// `bytes`: the file's contents; `name`: its path, for the message. Throws tf::Error naming `name` and the
// first thing wrong: empty, not whole 32-bit words, no SPIR-V magic number (or the other byte order), the
// validator's first complaint, no GLCompute entry point "main", a resource outside descriptor set 0 or at a
// binding (or of a descriptor type, or a 2D image where a 2D array is bound or the other way round) that the
// sample pass of `resource` does not bind (sample_pass_bindings above), a push constant member
// beyond HARNESS_PUSH_SIZE.
std::vector<uint32_t> check_sample_spirv(const std::string& bytes, const std::string& name, Resource resource);

// The plain Vulkan objects a compute pass of the GPU builds makes (gpu_build.cpp, gpu_build.cpp): a
// descriptor set layout, a pipeline layout with compute push constants, one descriptor set in a pool of its
// own, and a one-level view. Each is destroyed by `cleanup`.
VkDescriptorSetLayout create_set_layout(const VulkanContext& context,
                                        const std::vector<VkDescriptorSetLayoutBinding>& bindings, Cleanup& cleanup);
VkPipelineLayout create_push_layout(const VulkanContext& context, VkDescriptorSetLayout set_layout,
                                    uint32_t push_bytes, Cleanup& cleanup);
// `pool` receives the pool (destroyed by cleanup, which frees the set).
VkDescriptorSet allocate_set(const VulkanContext& context, VkDescriptorSetLayout layout,
                             const std::vector<VkDescriptorPoolSize>& sizes, VkDescriptorPool& pool, Cleanup& cleanup);
VkImageView create_level_view(const VulkanContext& context, VkImage image, VkFormat format, uint32_t level,
                              Cleanup& cleanup);

} // namespace tf
