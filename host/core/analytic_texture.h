#pragma once
// The procedural textures' analytic definitions: the continuous functions on [0,1)^2 whose samples at texel
// centres are the texels core/procedural.cpp writes, so that the ground truth (`--filter ground-truth
// --truth analytic`) can integrate the function itself instead of its bilinear texels and judge a
// magnification filter. The GPU's twin is shaders/harness/analytic_texture.glsl (float; the same formulas).
//
//   checker   8x8 cells: 0.9 where floor(8u) + floor(8v) is even, else 0.05 (RGB; alpha 1). Its texels are
//             this at their centres when the size is a multiple of 8.
//   zoneplate 0.5 + 0.5 cos(pi size ((u - 1/2)^2 + (v - 1/2)^2)): a chirp whose frequency depends on the size;
//             the texels are this at their centres for every size.
//   grid      16 cells a side, each with a line `width` texels wide at its start in u and in v (width 2 at
//             size >= 512, else 1): a line where frac(16u) size < 16 width (or the same in v). The texels are
//             this at their centres when the size is a multiple of 16.
// Every other texture (noise, mipcolors, dynamic, image files, cube and lat-long maps) has none.
//
// Cost: a few floating-point operations a sample (the zoneplate a cos).
// Example: analytic_value(analytic_texture("checker", 256), {0.01, 0.2}, Wrap::repeat) -> (0.9, 0.9, 0.9, 1).
#include "core/filter.h"
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <string>

namespace tf {

struct AnalyticTexture {
    AnalyticKind kind = AnalyticKind::none;
    int size = 0; // level 0's side in texels (the zoneplate's frequency, the grid's line width)
};

// The definition of procedural texture `name` at `size`. Throws tf::Error naming the texture when it has
// none ("texture 'noise' has no analytic definition (--truth analytic needs checker, zoneplate or grid)"),
// and for a size outside 1..16384.
AnalyticTexture analytic_texture(const std::string& name, int size);
bool has_analytic_definition(const std::string& name);

// The function at uv, after the wrap mode maps uv into [0,1)^2 (repeat: the fractional part; clamp: the
// nearest point of the square; mirror: reflected every other period), in double.
glm::dvec4 analytic_value(const AnalyticTexture& texture, glm::dvec2 uv, Wrap wrap);

// --truth: "texels" or "analytic" (throws tf::Error listing them).
Truth parse_truth(const std::string& name);
std::string to_string(Truth truth);
std::string to_string(AnalyticKind kind); // "checker", "zoneplate", "grid"; "none"

// With Truth::analytic, sets options.analytic from the texture's name (throws as analytic_texture does,
// before any work); with Truth::texels, sets it to none.
void resolve_analytic_truth(SamplerOptions& options, const std::string& texture_name);
// Where a truth is rendered: throws tf::Error for a ground truth with Truth::analytic and no kind (a caller
// that did not resolve it), so that it is never the texels' truth under the analytic name.
void check_analytic_truth(const SamplerOptions& options);
// The environment scenes (cube and lat-long maps) have no analytic definition: throws tf::Error for a
// ground truth with Truth::analytic.
void check_environment_truth(const SamplerOptions& options);

} // namespace tf
