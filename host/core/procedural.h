#pragma once
// Procedural test textures by name: checker, zoneplate, grid, noise, mipcolors.
#include "texture/mip.h"
#include <string>
#include <vector>

namespace tf {

const std::vector<std::string>& procedural_names();
bool is_procedural(const std::string& name);

// A size x size texture with its full MIP chain. For "mipcolors" every level is a flat distinct colour
// (not a downsample). Throws tf::Error for an unknown name or a size outside [1, 16384].
MipChain make_procedural(const std::string& name, int size);

} // namespace tf
