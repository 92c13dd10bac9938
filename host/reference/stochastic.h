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
// trilinear tap); ewa's tap form has no reference here (throws tf::Error). Non-finite uv: (0,0,0,0). `texels`:
// the environment maps' texel rule and taps (reference/environment.h); empty for a 2D texture.
glm::dvec4 reference_stochastic_sample(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup, Xi xi,
                                       const TexelSource& texels = {});

struct StochasticMoments {
    glm::dvec4 mean{0.0};
    glm::dvec4 variance{0.0}; // of ONE frame's value; the mean of N frames has variance / N
};
StochasticMoments reference_stochastic_moments(const MipChain& chain, const SamplerOptions& options,
                                               const Lookup& lookup, const TexelSource& texels = {});

// reference_render with options.stochastic: each pixel the mean of options.accumulate frames (frames
// stochastic_first.., stochastic_xi of the pixel, frame and lookup 0), as the GPU's gpu_render.
Image reference_render_stochastic(const SceneParams& scene, const MipChain& chain, const SamplerOptions& options,
                                  const RenderOptions& render);

// Throws tf::Error where the options have no stochastic reference: check_stochastic's cases, ewa's tap form.
void check_reference_stochastic(const SamplerOptions& options);

// The mean of options.accumulate frames of one lookup: frames stochastic_first.., the numbers
// stochastic_xi(noise, px, py, frame, lookup_index). render: the pixel and lookup 0; sample (reference_sample_all):
// pixel (0, 0) and the row, as the GPU's gpu_sample. Check the options first (check_reference_stochastic).
glm::dvec4 reference_stochastic_mean(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup, int px,
                                     int py, uint32_t lookup_index, const TexelSource& texels = {});

} // namespace tf
