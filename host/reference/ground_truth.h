#pragma once
// Ground truth: what a pixel should show. Each pixel integrates the level-0 texture, reconstructed
// bilinearly (options.truth texels), or the procedural texture's analytic definition at level 0's size
// (Truth::analytic, options.analytic; core/analytic_texture.h), over the scene itself under a pixel filter (a box over the pixel, or a Gaussian of
// sigma 0.5 px), by stratified supersampling: a side x side grid of strata, each jittered by an
// integer hash of (pixel, sample). The GPU (shaders/harness/ground_truth.glsl) uses the same pattern,
// so the two backends differ only by float vs double ray casts.
#include "core/filter.h"
#include "texture/image.h"
#include "texture/mip.h"
#include "reference/scene_cast.h"
#include <glm/vec2.hpp>

namespace tf {

// Sample i (0 <= i < side^2) of pixel (x, y), in pixel coordinates (the pixel spans [x, x+1)).
// box: uniform over the pixel; gaussian: centred on the pixel, sigma = ground_truth_sigma, by
// Box-Muller on the stratified unit square (strata in radius-quantile and angle).
glm::dvec2 ground_truth_sample(int x, int y, int i, int side, PixelFilter filter);

// The whole image on the CPU, in double, on every core; a progress bar on stderr when it is a terminal.
// Each pixel is the mean of samples [options.truth_first, + truth_count) of the grid (truth_range(); count
// 0 = the rest), so chunks weighted by their counts combine to the whole grid's mean. Throws tf::Error for
// a side outside 1..max_ground_truth_side, a range past the grid, or Truth::analytic with no analytic kind.
Image reference_ground_truth(const SceneParams& scene, const MipChain& chain, const SamplerOptions& options);

} // namespace tf
