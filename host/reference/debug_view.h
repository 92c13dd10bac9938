#pragma once
// The debug views on the CPU: the palettes of shaders/texfilter/debug.glsl (the same stops, docs/API.md)
// and a pixel of each view from the reference's own footprint (reference/footprint.h). reference_render
// draws --view lod, anisotropy and data with these; it cannot count texel fetches.
#include "reference/footprint.h"
#include "scene/scene.h"
#include <glm/glm.hpp>

namespace tf {

// Level l's colour of the mipcolors texture (l % 12) mixed with level l+1's by fract(lod); NaN and lod < 0:
// level 0; lod past 4096: 4096.
glm::dvec3 debug_lod_color(double lod);
// t = log2(ratio)/4 through grey, blue, green, yellow, red (1 .. 16 and more); NaN and ratio <= 1: grey.
glm::dvec3 debug_anisotropy_color(double ratio);
// t = value/max through black, blue, red, yellow, white; NaN t: black.
glm::dvec3 debug_heat(double value, double max_value);

// Throws tf::Error for a view the reference cannot render (fetches: it counts no texel reads).
void check_reference_view(DebugView view);

// One pixel of `view` (lod, anisotropy or data) from its footprint. data: (LOD, anisotropy, -1, 1), the -1
// saying "not counted" where the GPU writes fetches + hardware lookups.
glm::vec4 reference_view_pixel(DebugView view, const PixelFootprint& footprint);

} // namespace tf
