#pragma once
// Procedural test textures by name: checker, zoneplate, grid, noise, mipcolors, dynamic.
#include "texture/mip.h"
#include <string>
#include <vector>

namespace tf {

const std::vector<std::string>& procedural_names();
bool is_procedural(const std::string& name);

// A size x size texture with its full MIP chain. For "mipcolors" every level is a flat distinct colour
// (not a downsample). Throws tf::Error for an unknown name or a size outside [1, 16384].
MipChain make_procedural(const std::string& name, int size);

// "dynamic" at frame `frame` (make_procedural gives frame 0): a checker scrolling 3 texels right and 2 down
// a frame, rings around a centre that circles, and a fine XOR pattern, from integer arithmetic only, so
// that the GPU's generator (shaders/harness/dynamic_texture.comp.glsl, rebuilt every frame by bench
// --gpu-build and the viewer with --build gpu) writes the same floats bit for bit. Size as make_procedural.
Image dynamic_texture(int size, int frame);

} // namespace tf
