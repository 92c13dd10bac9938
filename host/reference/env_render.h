#pragma once
// The CPU reference applied to the environment scenes (skybox, reflect): each pixel's direction lookup
// (reference/env_cast.h) filtered from the cube or lat-long map (reference/environment.h), or the ground truth
// over the pixel's directions. Multithreaded over rows; double precision.
#include "core/environment.h"
#include "scene/scene.h"

namespace tf {

// One lookup of the map (reference_cube_sample or reference_latlong_sample).
glm::dvec4 reference_environment_sample(const EnvironmentMap& env, const SamplerOptions& options,
                                        const EnvLookup& lookup);

// The whole image (--stochastic: each pixel the mean of its frames). render.view must be color (the debug views are the 2D scenes'); ground-truth integrates
// level 0 over the pixel (options.truth_side, pixel_filter, the sample range) as reference_ground_truth does.
Image reference_render_environment(const SceneParams& scene, const EnvironmentMap& env, const SamplerOptions& options,
                                   const RenderOptions& render);

} // namespace tf
