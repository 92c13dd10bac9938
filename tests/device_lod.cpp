#include "device_lod.h"
#include "core/procedural.h"
#include "support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <glm/geometric.hpp>

namespace tf::test {

LodRange spec_lod_range(const Lookup& l, double width, double height)
{
    const double ux = std::abs(l.dudx) * width, vx = std::abs(l.dvdx) * height;
    const double uy = std::abs(l.dudy) * width, vy = std::abs(l.dvdy) * height;
    const double lo = std::max(std::max(ux, vx), std::max(uy, vy));
    const double hi = std::sqrt(2.0) * std::max(ux + vx, uy + vy);
    return {std::log2(lo), std::log2(hi)}; // log2(0) = -inf
}

double mipcolors_lod(const MipChain& mipcolors, const glm::dvec4& color, double& residual)
{
    const int top = int(mipcolors.levels.size()) - 1;
    auto level_color = [&](int level) { return glm::dvec4(mipcolors.levels[size_t(level)].at(0, 0)); };
    residual = glm::length(color - level_color(0));
    double lod = 0;
    for (int lo = 0; lo < top; ++lo) {
        const glm::dvec4 a = level_color(lo), d = level_color(lo + 1) - a;
        const double f = std::clamp(glm::dot(color - a, d) / glm::dot(d, d), 0.0, 1.0);
        const double r = glm::length(color - (a + f * d));
        if (r < residual) {
            residual = r;
            lod = lo + f;
        }
    }
    return lod;
}

std::vector<double> device_lods(const std::string& lookups_csv, const std::vector<Lookup>& lookups, int size)
{
    const MipChain colors = make_procedural("mipcolors", size);
    const std::vector<glm::dvec4> hw =
        run_sample("--texture mipcolors --texture-size " + std::to_string(size) + " --filter hw-trilinear",
                   lookups_csv, false)
            .colors;
    const double top = double(colors.levels.size() - 1);
    const double e = 2.0 * std::ldexp(1.0, -int(test_device_info().mipmap_precision_bits));
    std::vector<double> lods;
    int outside = 0, unblended = 0;
    double below = 0, above = 0; // the device's λ against the exact one, its extremes
    for (size_t i = 0; i < lookups.size(); ++i) {
        double residual = 0;
        const double lod = mipcolors_lod(colors, hw[i], residual);
        const LodRange range = spec_lod_range(lookups[i], size, size);
        const double lo = std::clamp(range.lo, 0.0, top) - e, hi = std::clamp(range.hi, 0.0, top) + e;
        const double exact = std::clamp(std::log2(std::max(std::hypot(lookups[i].dudx, lookups[i].dvdx),
                                                            std::hypot(lookups[i].dudy, lookups[i].dvdy)) * size),
                                        0.0, top);
        below = std::min(below, lod - exact);
        above = std::max(above, lod - exact);
        unblended += residual > 1e-3;
        outside += lod < lo || lod > hi;
        lods.push_back(lod);
    }
    std::printf("device LOD (hw-trilinear on mipcolors %d): %+.4f..%+.4f levels from the exact log2(rho), %d of %zu "
                "outside Vulkan's bounds, %d no blend of two levels\n",
                size, below, above, outside, lookups.size(), unblended);
    CHECK(outside == 0 && unblended == 0, std::to_string(outside) + " lookups' LOD outside Vulkan's scale-factor bounds, " +
                                              std::to_string(unblended) + " colours no blend of two mipcolors levels");
    return lods;
}

std::vector<double> lod_probes(double a, double b, double e)
{
    const double lo = std::min(a, b) - e, hi = std::max(a, b) + e;
    std::vector<double> probes = {lo, hi};
    for (double k = std::ceil(lo); k <= hi; ++k)
        probes.push_back(k);
    return probes;
}

} // namespace tf::test
