#include "reference/debug_view.h"
#include "harness/config.h"
#include "texture/error.h"
#include <algorithm>
#include <cmath>

namespace tf {

namespace {

// host/core/procedural.cpp's mipcolors levels (tests/test_debug_views.cpp checks them against its texels).
const glm::dvec3 mip_colors[12] = {{1.0, 0.0, 0.0}, {1.0, 0.5, 0.0}, {1.0, 1.0, 0.0}, {0.5, 1.0, 0.0},
                                   {0.0, 1.0, 0.0}, {0.0, 1.0, 0.5}, {0.0, 1.0, 1.0}, {0.0, 0.5, 1.0},
                                   {0.0, 0.0, 1.0}, {0.5, 0.0, 1.0}, {1.0, 0.0, 1.0}, {1.0, 0.0, 0.5}};
const glm::dvec3 anisotropy_stops[5] = {
    {0.2, 0.2, 0.2}, {0.05, 0.25, 1.0}, {0.05, 0.8, 0.2}, {1.0, 0.85, 0.05}, {1.0, 0.05, 0.05}};
const glm::dvec3 heat_stops[5] = {{0.0, 0.0, 0.0}, {0.1, 0.1, 0.9}, {0.9, 0.1, 0.3}, {1.0, 0.8, 0.0}, {1.0, 1.0, 1.0}};

glm::dvec3 ramp(const glm::dvec3 (&stops)[5], double t)
{
    const double x = 4.0 * std::clamp(t, 0.0, 1.0);
    const int i = std::min(int(x), 3);
    const double f = x - i;
    return (1.0 - f) * stops[i] + f * stops[i + 1];
}

} // namespace

glm::dvec3 debug_lod_color(double lod)
{
    const double d = std::isnan(lod) ? 0.0 : std::clamp(lod, 0.0, 4096.0);
    const double lo = std::floor(d), f = d - lo;
    const int i = int(lo) % 12;
    return (1.0 - f) * mip_colors[i] + f * mip_colors[(i + 1) % 12];
}

glm::dvec3 debug_anisotropy_color(double ratio) { return ramp(anisotropy_stops, ratio > 1.0 ? 0.25 * std::log2(ratio) : 0.0); }

glm::dvec3 debug_heat(double value, double max_value)
{
    const double t = value / max_value;
    return ramp(heat_stops, std::isnan(t) ? 0.0 : t);
}

void check_reference_view(DebugView view)
{
    if (view == DebugView::fetches)
        throw Error("--view fetches: the CPU reference counts no texel fetches (use --backend vulkan, or --view data "
                    "for the LOD and anisotropy)");
}

glm::vec4 reference_view_pixel(DebugView view, const PixelFootprint& f)
{
    switch (view) {
    case DebugView::lod: return glm::vec4(glm::vec3(debug_lod_color(f.lod)), 1.0f);
    case DebugView::anisotropy: return glm::vec4(glm::vec3(debug_anisotropy_color(f.anisotropy)), 1.0f);
    case DebugView::data: return glm::vec4(float(f.lod), float(f.anisotropy), -1.0f, 1.0f);
    case DebugView::color:
    case DebugView::fetches: break;
    }
    throw Error("reference_view_pixel: the reference does not draw --view " + to_string(view));
}

} // namespace tf
