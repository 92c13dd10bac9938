#pragma once
// `texfilter sample --resource`: the flags that choose the kind of texture resource the lookups read
// (--resource, --layers, --layer, --compare, --dref), their parsing and checks, and the run on either
// backend (the CPU reference per layer, with PCF, or through a texel source's addressing; the GPU through
// the kind's harness variant).
#include "core/lookup.h"
#include "core/lookup_stats.h"
#include "core/resource.h"
#include "flags/args.h"
#include "flags/cli_common.h"
#include "vulkan/pipelines.h"
#include <glm/vec4.hpp>
#include <vector>

namespace tf {

std::vector<FlagSpec> resource_flags();
// Throws tf::Error naming the flag for a bad value or a flag the kind does not take.
ResourceOptions resource_options_from(const Args& args);

// The lookups filtered on the resource made from `chain` (core/resource_textures.h; atlas and virtual:
// core/texel_sources.h); gpu null: the CPU reference. Stats only on the GPU. shader: the GPU's lookup shader
// instead of the kind's built-in one (`sample --spirv`; null words: the built-in one).
std::vector<glm::dvec4> sample_resource(GpuSession* gpu, const MipChain& chain, const std::vector<Lookup>& lookups,
                                        const SamplerOptions& options, const ResourceOptions& resource,
                                        std::vector<LookupStats>* stats, ShaderCode shader = {nullptr, 0});

} // namespace tf
