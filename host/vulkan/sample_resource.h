#pragma once
// `sample --resource`: point lookups through the harness variant of a resource kind (harness_variant.h)
// on the images of resource_images.h, with the layer, the bindless index and the depth comparison passed
// as push constants. Results and stats as gpu_sample's (backend.h).
#include "core/lookup.h"
#include "core/lookup_stats.h"
#include "core/resource.h"
#include "vulkan/pipeline.h"
#include "vulkan/resource_images.h"
#include <glm/vec4.hpp>
#include <vector>

namespace tf {

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
// spirv_module.h against the kind's bindings); none (null words): the built-in one.
std::vector<glm::vec4> gpu_sample_resource(const VulkanContext& context, const GpuResources& resources,
                                           const std::vector<Lookup>& lookups, const SamplerOptions& options,
                                           const ResourceOptions& resource, std::vector<LookupStats>* stats = nullptr,
                                           ShaderCode shader = {nullptr, 0});

} // namespace tf
