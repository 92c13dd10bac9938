#pragma once
// Point lookups on the device: the sample pass every `sample` run shares, the pass of each resource kind,
// and gpu_sample / gpu_sample_resource around them.
#include "core/filter.h"
#include "core/lookup.h"
#include "core/lookup_stats.h"
#include "core/resource.h"
#include "scene/shader_interface.h"
#include "vulkan/pipelines.h"
#include "vulkan/render.h"
#include "vulkan/textures.h"
#include <functional>
#include <glm/vec4.hpp>
#include <vector>

namespace tf {

// The body every `sample` pass shares: the lookups, results and stats buffers, the pass
// that make_pass builds around them, the compute pipeline of `code` specialised to the filter, the
// dispatch (one invocation, or for hw-* one subgroup, a lookup) and the readback. adjust_push fills in
// what the pass's textures add to the push constants (the SAT's range, a layer, a comparison); prelude,
// when given, is recorded into the same command buffer before the dispatch (a GPU build of the texture).
using MakeSamplePass = std::function<Pass(const std::vector<PassBuffer>& buffers, Cleanup& cleanup)>;

std::vector<glm::vec4> run_sample_pass(const VulkanContext& context, const std::vector<Lookup>& lookups,
                                       const SamplerOptions& options, std::vector<LookupStats>* stats,
                                       ShaderCode code, const MakeSamplePass& make_pass,
                                       const std::function<void(PushConstants&)>& adjust_push,
                                       const std::function<void(VkCommandBuffer)>& prelude = {});

// The harness pass of one resource kind (`sample --resource`): the variant's descriptors at
// HARNESS_BINDING_TEXTURE (a combined image sampler, a sampled image, or an array of them) and, for the
// separate kinds, the sampler at HARNESS_BINDING_SAMPLER (shadow: a comparison sampler with compareOp),
// the summed-area table's placeholders, and the pass's own buffers (render.h).
// Everything made is destroyed by `cleanup`.
Pass create_resource_pass(const VulkanContext& context, const GpuResources& resources, const HarnessVariant& variant,
                          const SamplerOptions& options, const ResourceOptions& resource, VkShaderStageFlags stages,
                          const std::vector<PassBuffer>& buffers, Cleanup& cleanup);

// `sample --resource`: point lookups through the harness variant of a resource kind (pipelines.h)
// on the images of textures.h, with the layer, the bindless index and the depth comparison passed
// as push constants. Results and stats as gpu_sample's (backend.h).
// Throws tf::Error for what the kind cannot do (a summed-area table on anything but combined; bindless on
// a device without non-uniform indexing of sampled-image arrays; hardware taps or the SAT through a texel
// source, hw-* on a virtual texture), naming the flag and the reason.
void check_resource_options(const SamplerOptions& options, const ResourceOptions& resource);
void check_resource_device(const VulkanContext& context, const SamplerOptions& options,
                           const ResourceOptions& resource);
// atlas, virtual: the atlas or physical texture of a width x height texture fits the device's
// maxImageDimension2D (core/texel_sources.h's check_source_size).
void check_source_device(const VulkanContext& context, Resource kind, int width, int height);

// shader: the lookup shader to run instead of the kind's built-in variant (`sample --spirv`, checked by
// pipelines.h against the kind's bindings); none (null words): the built-in one.
std::vector<glm::vec4> gpu_sample_resource(const VulkanContext& context, const GpuResources& resources,
                                           const std::vector<Lookup>& lookups, const SamplerOptions& options,
                                           const ResourceOptions& resource, std::vector<LookupStats>* stats = nullptr,
                                           ShaderCode shader = {nullptr, 0});

} // namespace tf
