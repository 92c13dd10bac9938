#pragma once
// The body every `sample` pass shares (sample.cpp): the lookups, results and stats buffers, the pass
// that make_pass builds around them, the compute pipeline of `code` specialised to the filter, the
// dispatch (one invocation, or for hw-* one subgroup, a lookup) and the readback. adjust_push fills in
// what the pass's textures add to the push constants (the SAT's range, a layer, a comparison); prelude,
// when given, is recorded into the same command buffer before the dispatch (a GPU build of the texture).
#include "core/filter.h"
#include "core/lookup.h"
#include "core/lookup_stats.h"
#include "scene/shader_interface.h"
#include "vulkan/pass.h"
#include "vulkan/pipeline.h"
#include <functional>
#include <glm/vec4.hpp>
#include <vector>

namespace tf {

using MakeSamplePass = std::function<Pass(const std::vector<PassBuffer>& buffers, Cleanup& cleanup)>;

std::vector<glm::vec4> run_sample_pass(const VulkanContext& context, const std::vector<Lookup>& lookups,
                                       const SamplerOptions& options, std::vector<LookupStats>* stats,
                                       ShaderCode code, const MakeSamplePass& make_pass,
                                       const std::function<void(PushConstants&)>& adjust_push,
                                       const std::function<void(VkCommandBuffer)>& prelude = {});

} // namespace tf
