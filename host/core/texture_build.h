#pragma once
// --build cpu|gpu: where the MIP chain and the summed-area table are built. cpu: tf::build_mip_chain and
// tf::build_sat on the host, every level uploaded (the reference). gpu: level 0 uploaded, the rest built by
// the device (shaders/texfilter/build_mip.glsl, build_sat.glsl).
#include "core/texture_format.h"
#include <string>

namespace tf {

enum class TextureBuild { cpu, gpu };

TextureBuild parse_texture_build(const std::string& name); // throws tf::Error naming the choices
std::string to_string(TextureBuild build);

// Throws tf::Error when the device cannot build this texture: integer formats (r16ui, r32ui: their chains
// round codes on the host) and a procedural texture whose levels are not a downsample (mipcolors).
void check_gpu_build(TextureFormat format, const std::string& texture_name);

} // namespace tf
