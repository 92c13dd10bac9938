#pragma once
// An environment map in host memory (docs/ENVIRONMENT.md): a cube map, or a lat-long 2D texture with its MIP
// chain. What the environment scenes (skybox, reflect) read, on both backends.
#include "core/filter.h"
#include "core/lookup.h"
#include "texture/mip.h"

namespace tf {

struct EnvironmentMap {
    EnvMap map = EnvMap::cube;
    CubeMap cube;    // map == cube
    MipChain latlong; // map == latlong
};

// Level 0's width: a cube's face side, a lat-long map's width (what make_scene scales the scene by).
int environment_size(const EnvironmentMap& env);

EnvMap parse_env_map(const std::string& name); // "cube", "latlong"; throws tf::Error listing them
std::string to_string(EnvMap map);

// The filters the environment maps have (every family of cube.glsl / latlong.glsl, the hw-* modes, the
// ground truth, none; --stochastic as in 2D, check_stochastic): brilinear and the SAT filters throw tf::Error
// naming the filter.
void check_environment_filter(const SamplerOptions& options);
bool has_environment_form(const SamplerOptions& options); // check_environment_filter would not throw

// The lat-long image (width x width/2) of a cube map's level 0: texel (i, j) takes the cube texel its centre's
// direction hits (nearest, no filtering), so that --env latlong renders the same procedural environment as
// --env cube. Throws tf::Error for a width below 2 or odd.
Image latlong_from_cube(const CubeMap& cube, int width);

} // namespace tf
