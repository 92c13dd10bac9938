#pragma once
// The hardware sampler's level of detail, as Vulkan bounds it and as the device under test takes it.
//
// Vulkan lets a device approximate the scale factor ("Scale Factor Operation"): any f_x with
// max(|m_ux|, |m_vx|) <= f_x <= sqrt(2) (|m_ux| + |m_vx|) (the same for y), then λ = log2(max(f_x, f_y)),
// computed to mipmapPrecisionBits. So λ may sit from ~0.5 below to 1 above the exact log2(ρ): a lavapipe keeps
// within 0.04 of it, an NVIDIA H200 does not (2026-12-04). Tests that hold a manual filter to the hardware's
// therefore take the hardware's λ as measured (device_lods: hw-trilinear on mipcolors, each level one colour),
// check that it lies within Vulkan's bounds (so a harness that hands the sampler other gradients still
// fails), and allow the filter's change between the exact λ and the measured one.
#include "core/lookup.h"
#include "texture/image.h"

#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

namespace tf::test {

// Vulkan's bounds on log2 of the scale factor (no bias, no clamp) for a lookup on a width x height level 0;
// -inf for zero gradients.
struct LodRange {
    double lo = 0, hi = 0;
};
LodRange spec_lod_range(const Lookup& lookup, double width, double height);

// λ of a colour that blends two neighbouring levels of `mipcolors` (make_procedural("mipcolors", n)): the
// finer level plus the coarser one's weight, in [0, levels - 1]. `residual` is the colour's distance from the
// nearest such blend (0 for a sampler's exact blend; large for a colour that is none).
double mipcolors_lod(const MipChain& mipcolors, const glm::dvec4& color, double& residual);

// The device's λ at each lookup, clamped to [0, levels - 1] as its sampler clamps it: `texfilter sample
// --filter hw-trilinear` on mipcolors of size x size, decoded. Checks that every colour is a blend of two
// neighbouring levels and every λ lies within spec_lod_range (clamped) widened by two mipmapPrecisionBits
// steps (the LOD's accuracy and the blend fraction's quantisation).
std::vector<double> device_lods(const std::string& lookups_csv, const std::vector<Lookup>& lookups, int size);

// The λ at which a function piecewise linear in λ between whole levels (trilinear, one PCF level pair)
// takes its extremes over [min(a, b) - e, max(a, b) + e]: the ends (first, in that order) and the whole levels
// inside.
std::vector<double> lod_probes(double a, double b, double e);

} // namespace tf::test
