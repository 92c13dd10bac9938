#pragma once
// The CPU reference for environment lookups (cube maps and lat-long maps), in double, written from
// docs/ENVIRONMENT.md: a direction lookup becomes a 2D lookup on one texture (a cube face, or the
// lat-long texture) and runs the 2D family of the same name (reference/reference.h) on it, its texels
// read through the map's own seamless rule instead of the sampler's wrap mode (which is ignored).
#include "core/filter.h"
#include "core/lookup.h"
#include "texture/mip.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace tf {

// The full filter on a cube map / lat-long map for one lookup. Filters: nearest, bilinear (level 0),
// nearest-mip, bilinear-mip, trilinear, aniso (gpu and feline), ewa; with --taps hardware, aniso's probes and
// ewa's blocks are the device's taps (a cube's re-projected onto the face they hit, docs/ENVIRONMENT.md);
// hw-nearest/hw-bilinear/hw-trilinear as the manual formula of the same mode; none: the unit direction as
// colour, 0.5·d/|d| + 0.5 (the baseline). brilinear, sat, sat-assembly (no environment form), hw-aniso
// (implementation-defined) and ground-truth throw tf::Error. A zero or non-finite direction returns
// (0,0,0,0); non-finite derivatives are the 2D families' non-finite footprint.
glm::dvec4 reference_cube_sample(const CubeMap& cube, const SamplerOptions& options, const EnvLookup& lookup);
glm::dvec4 reference_latlong_sample(const MipChain& chain, const SamplerOptions& options, const EnvLookup& lookup);

// --stochastic on the maps (cube.glsl's and latlong.glsl's tf_X_stochastic_*): the mean of options.accumulate
// frames of one lookup (frames stochastic_first.., the numbers of pixel (px, py), lookup 0, as the GPU's
// environment render draws them), and the estimator's moments (reference/stochastic.h); the 2D family's on the
// lookup's face or lat-long uv, every texel and tap read by the map's rule as the deterministic filters read
// them. options.stochastic need not be set for the moments; the filter must be bilinear, trilinear, aniso or ewa
// (ewa with manual taps), else tf::Error. A zero or non-finite direction returns (0,0,0,0) (moments: zero).
glm::dvec4 reference_cube_stochastic_mean(const CubeMap& cube, const SamplerOptions& options, const EnvLookup& lookup,
                                          int px, int py);
glm::dvec4 reference_latlong_stochastic_mean(const MipChain& chain, const SamplerOptions& options,
                                             const EnvLookup& lookup, int px, int py);
struct StochasticMoments;
StochasticMoments reference_cube_stochastic_moments(const CubeMap& cube, const SamplerOptions& options,
                                                    const EnvLookup& lookup);
StochasticMoments reference_latlong_stochastic_moments(const MipChain& chain, const SamplerOptions& options,
                                                       const EnvLookup& lookup);

// Level-0 bilinear through the map's off-texture rule: what the ground truth integrates. A zero or
// non-finite direction returns (0,0,0,0).
glm::dvec4 reference_cube_bilinear0(const CubeMap& cube, const glm::dvec3& dir);
glm::dvec4 reference_latlong_bilinear0(const MipChain& chain, const glm::dvec3& dir);

// The 2D lookup a direction lookup becomes: the face of the direction (`face`, Vulkan's face selection),
// uv = (s, t) on it and the direction derivatives projected onto that face; the lat-long u, v and their
// analytic gradients (the Jacobian of the mapping: non-finite at the poles, where rho = 0). Meant for a
// finite non-zero direction (the sample functions check that first).
Lookup cube_face_lookup(const EnvLookup& lookup, int& face);
Lookup latlong_lookup(const EnvLookup& lookup);

// The seamless texel reads of docs/ENVIRONMENT.md, any i, j (far outside the face or texture too):
// - cube: inside the face its texel; one coordinate outside, or both and not a corner's diagonal
//   neighbour, the texel the direction through (i, j)'s centre on the face's extended plane hits; both one
//   past a corner (i in {-1, N}, j in {-1, N}), the mean of the three texels that meet there.
// - lat-long: column i mod W in rows 0..H-1; past a pole the row mirrored and the column moved by W/2;
//   rows repeat every 2H (past both poles, back to the start).
// Throw tf::Error for a face outside 0..5 or a level the map lacks.
glm::dvec4 cube_texel(const CubeMap& cube, int face, int level, long long i, long long j);
glm::dvec4 latlong_texel(const MipChain& chain, int level, long long i, long long j);

} // namespace tf
