#pragma once
// Stochastic filtering in the bench: for each of bilinear, trilinear, aniso16 and ewa that the run
// has, with white and blue noise, on one 2D scene: the time of one stochastic frame (one texel a lookup) and the
// error of the mean of the first 1, 4, 16 and 64 frames against the scene's box and Gaussian truths, beside the
// deterministic filter's own row.
#include "bench/bench.h"
#include "vulkan/textures.h"
#include <vector>

namespace tf {

std::vector<StochasticRow> run_stochastic_rows(const VulkanContext& context, const GpuTexture& texture,
                                               const BenchConfig& config, SceneKind scene_kind,
                                               const SceneParams& scene, const Image& truth_box,
                                               const Image& truth_gaussian);

} // namespace tf
