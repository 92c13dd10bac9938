#pragma once
// EWA's error against footprint size (the goal "ewa --taps hardware within 0.5 dB of the manual form at every
// footprint size"): the minify scene at 1 .. 64 level-0 texels a pixel, each form's PSNR against the
// Gaussian-pixel truth of that scene (the truth EWA approximates). EwaSweepPoint is in bench/bench.h.
#include "bench/bench.h"
#include "vulkan/textures.h"
#include <vector>

namespace tf {

// The sweep's footprint sizes.
const std::vector<double>& ewa_sweep_sizes();

// One point a size, rendered on `context` through `texture` (chain is its MIP chain, for the CPU truth when the
// bench asks for it).
std::vector<EwaSweepPoint> run_ewa_sweep(const VulkanContext& context, const GpuTexture& texture, const MipChain& chain,
                                         const BenchConfig& config);

} // namespace tf
