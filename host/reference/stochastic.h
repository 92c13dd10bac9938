#pragma once
// The CPU reference of --stochastic (shaders/texfilter/stochastic.glsl), from the math in double: the
// one-texel estimator for given random numbers (the GPU's choice rules, so the same xi picks the same texel
// up to float-vs-double at a boundary), and the estimator's distribution: its expectation (the deterministic
// filter for bilinear, trilinear and aniso; for ewa the Gaussian-weighted mean of each level's support,
// blended: see stochastic.glsl) and its per-channel variance sum p_i t_i² - mean².
#include "core/stochastic_noise.h"
#include "reference/reference.h"
#include "reference/scene_cast.h"
#include "texture/image.h"

namespace tf {

// The value one frame's lookup returns under xi. options.taps hardware: the tap forms (one exact bilinear or
// trilinear tap); ewa's tap form has no reference here (throws tf::Error). Non-finite uv: (0,0,0,0).
glm::dvec4 reference_stochastic_sample(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup, Xi xi);

struct StochasticMoments {
    glm::dvec4 mean{0.0};
    glm::dvec4 variance{0.0}; // of ONE frame's value; the mean of N frames has variance / N
};
StochasticMoments reference_stochastic_moments(const MipChain& chain, const SamplerOptions& options,
                                               const Lookup& lookup);

// reference_render with options.stochastic: each pixel the mean of options.accumulate frames (frames
// stochastic_first.., stochastic_xi of the pixel, frame and lookup 0), as the GPU's gpu_render.
Image reference_render_stochastic(const SceneParams& scene, const MipChain& chain, const SamplerOptions& options,
                                  const RenderOptions& render);

// reference_sample_all with options.stochastic (texfilter sample): lookup i the mean of options.accumulate
// frames, stochastic_xi of pixel (0, 0), frame stochastic_first + f and lookup i, as the GPU's gpu_sample.
std::vector<glm::dvec4> reference_sample_stochastic(const MipChain& chain, const std::vector<Lookup>& lookups,
                                                    const SamplerOptions& options);

} // namespace tf
