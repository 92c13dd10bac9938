#pragma once
// The CPU reference applied to whole scenes and lookup lists (multithreaded over rows / chunks).
#include "reference/reference.h"
#include "reference/scene_cast.h"
#include <glm/vec4.hpp>
#include <vector>

namespace tf {

Image reference_render(const SceneParams& scene, const MipChain& chain, const SamplerOptions& options,
                       const RenderOptions& render);

// rows (--stochastic): the lookup index whose random numbers lookup i draws (gpu_sample: its row in the whole
// list); null: i itself.
std::vector<glm::dvec4> reference_sample_all(const MipChain& chain, const std::vector<Lookup>& lookups,
                                             const SamplerOptions& options, const std::vector<uint32_t>* rows = nullptr);

} // namespace tf
