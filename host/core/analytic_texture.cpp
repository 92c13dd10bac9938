#include "core/analytic_texture.h"
#include "texture/error.h"
#include <algorithm>
#include <cmath>
#include <numbers>

namespace tf {

namespace {

constexpr int kMaxSize = 16384; // make_procedural's limit

// The levels as procedural.cpp stores them (floats), so that a texel centre gives the texel exactly.
constexpr double kCheckerLight = double(0.9f), kCheckerDark = double(0.05f);
const glm::dvec4 kGridBackground(double(0.02f), double(0.03f), double(0.08f), 1.0);
const glm::dvec4 kGridLine(double(0.9f), double(0.85f), double(0.6f), 1.0);

// The largest double below 1: clamp and mirror keep u = 1 in the last cell, as clamp-to-edge keeps the
// last texel.
const double kBelowOne = std::nextafter(1.0, 0.0);

double wrap_unit(double u, Wrap wrap)
{
    switch (wrap) {
    case Wrap::repeat:
        u -= std::floor(u);
        break;
    case Wrap::mirror: {
        const double t = u - 2.0 * std::floor(u / 2.0); // [0, 2): one period of the mirrored pattern
        u = t <= 1.0 ? t : 2.0 - t;
        break;
    }
    case Wrap::clamp:
        break;
    }
    return std::clamp(u, 0.0, kBelowOne); // also catches a fractional part that rounded up to 1
}

double checker(glm::dvec2 uv)
{
    const double cells = std::floor(8.0 * uv.x) + std::floor(8.0 * uv.y);
    return std::fmod(cells, 2.0) == 0.0 ? kCheckerLight : kCheckerDark;
}

double zoneplate(glm::dvec2 uv, int size)
{
    // In texels from the centre, as procedural.cpp writes it: phase pi r^2 / size.
    const double dx = uv.x * size - size / 2.0, dy = uv.y * size - size / 2.0;
    return 0.5 + 0.5 * std::cos(std::numbers::pi * (dx * dx + dy * dy) / size);
}

// A line covers the first `width` texels of each of the 16 cells: frac(16 u) * size / 16 < width.
bool on_grid_line(double u, int size)
{
    const int width = size >= 512 ? 2 : 1;
    const double f = 16.0 * u - std::floor(16.0 * u);
    return f * size < 16.0 * width;
}

} // namespace

bool has_analytic_definition(const std::string& name)
{
    return name == "checker" || name == "zoneplate" || name == "grid";
}

AnalyticTexture analytic_texture(const std::string& name, int size)
{
    if (!has_analytic_definition(name))
        throw Error("texture '" + name + "' has no analytic definition (--truth analytic needs checker, zoneplate or grid)");
    if (size < 1 || size > kMaxSize)
        throw Error("analytic texture '" + name + "': size " + std::to_string(size) + " out of range [1, " +
                    std::to_string(kMaxSize) + "]");
    const AnalyticKind kind = name == "checker" ? AnalyticKind::checker
                              : name == "zoneplate" ? AnalyticKind::zoneplate
                                                    : AnalyticKind::grid;
    return {kind, size};
}

glm::dvec4 analytic_value(const AnalyticTexture& texture, glm::dvec2 uv, Wrap wrap)
{
    const glm::dvec2 st(wrap_unit(uv.x, wrap), wrap_unit(uv.y, wrap));
    switch (texture.kind) {
    case AnalyticKind::checker: {
        const double v = checker(st);
        return {v, v, v, 1.0};
    }
    case AnalyticKind::zoneplate: {
        const double v = zoneplate(st, texture.size);
        return {v, v, v, 1.0};
    }
    case AnalyticKind::grid:
        return on_grid_line(st.x, texture.size) || on_grid_line(st.y, texture.size) ? kGridLine : kGridBackground;
    case AnalyticKind::none:
        break;
    }
    throw Error("analytic_value: no analytic texture (kind none)");
}

Truth parse_truth(const std::string& name)
{
    if (name == "texels")
        return Truth::texels;
    if (name == "analytic")
        return Truth::analytic;
    throw Error("unknown truth '" + name + "' (expected one of: texels, analytic)");
}

std::string to_string(Truth truth) { return truth == Truth::analytic ? "analytic" : "texels"; }

std::string to_string(AnalyticKind kind)
{
    switch (kind) {
    case AnalyticKind::checker: return "checker";
    case AnalyticKind::zoneplate: return "zoneplate";
    case AnalyticKind::grid: return "grid";
    case AnalyticKind::none: break;
    }
    return "none";
}

void resolve_analytic_truth(SamplerOptions& options, const std::string& texture_name)
{
    options.analytic = options.truth == Truth::analytic ? analytic_texture(texture_name, 1).kind : AnalyticKind::none;
}

void check_analytic_truth(const SamplerOptions& options)
{
    if (options.filter == Filter::ground_truth && options.truth == Truth::analytic && options.analytic == AnalyticKind::none)
        throw Error("ground truth: --truth analytic without an analytic texture (resolve_analytic_truth sets it from "
                    "the texture's name)");
}

void check_environment_truth(const SamplerOptions& options)
{
    if (options.filter == Filter::ground_truth && options.truth == Truth::analytic)
        throw Error("--truth analytic: the environment scenes (skybox, reflect) read a cube or lat-long map, which has "
                    "no analytic definition (use --truth texels)");
}

} // namespace tf
