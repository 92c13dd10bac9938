// CPU reference for ewa-fast, in double, from the math in shaders/texfilter/ewa_fast.glsl's header (not from its
// code: the axes and √S come from the eigen-decomposition of J·Jᵀ by atan2, the shader uses ewa.glsl's projector
// and a closed-form square root). Probes are exact trilinear lookups (reference_hardware_trilinear).
#include "reference/reference.h"

#include "texture/error.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/glm.hpp>

namespace tf {

namespace {

// The filter's definition (ewa_fast.glsl): the pixel's Gaussian variance k², the largest probe spacing c in texels
// of the probes' level, the row's weight profile rho = h / 1.5 and at most 2·4 + 1 probes, the triangle up to
// A/B = 1.5, and one probe where the triangle's (tr √S)² is below 1e-6 texels².
constexpr double pixel_variance = 0.25;
constexpr double spacing = 1.0;
constexpr double profile = 1.5;
constexpr int max_half = 4;
constexpr double row_from = 1.5;
constexpr double one_probe = 1e-6;

} // namespace

double reference_ewa_fast_weight(int t, int h) { return std::exp(-0.5 * (profile * t / h) * (profile * t / h)); }

EwaFastProbes reference_ewa_fast_probes(const MipChain& chain, const SamplerOptions& options, const Lookup& l) {
    if (chain.levels.empty()) throw Error("reference_ewa_fast: empty MIP chain");
    EwaFastProbes p;
    if (!finite_footprint(chain, l)) { // NaN/±Inf or past float range: one lookup, the coarsest level
        p.lod = clamp_lod(chain, INFINITY, options);
        return p;
    }
    const double w = chain.levels[0].width, h = chain.levels[0].height;
    const double ja = l.dudx * w, jb = l.dudy * w, jc = l.dvdx * h, jd = l.dvdy * h; // J in level-0 texels
    const double s = ja * ja + jb * jb, t = ja * jc + jb * jd, r = jc * jc + jd * jd; // J·Jᵀ = [s t; t r]
    const double mean = 0.5 * (s + r), dev = std::hypot(0.5 * (s - r), t);
    const double major2 = mean + dev;
    if (major2 == 0) { // zero gradients: one lookup, the finest level
        p.lod = clamp_lod(chain, -INFINITY, options);
        return p;
    }
    const double minor2 = (ja * jd - jb * jc) * (ja * jd - jb * jc) / major2; // det² / sigma1²
    const double theta = 0.5 * std::atan2(2 * t, s - r);                       // the major axis
    // e1's sign by ewa_fast.glsl's rule, dot(e1, (0.8, 0.6)) >= 0: the zigzag is not symmetric under e1 -> -e1.
    const double sign = 0.8 * std::cos(theta) + 0.6 * std::sin(theta) >= 0 ? 1.0 : -1.0;
    const glm::dvec2 e1(sign * std::cos(theta), sign * std::sin(theta)), e2(-e1.y, e1.x);
    const glm::dvec2 to_uv(1.0 / w, 1.0 / h);
    // Target k²·J·Jᵀ + I/6 a axis pair; a trilinear lookup at LOD lambda has 4^lambda/4 - 1/12 a axis, so the
    // layout's points carry (A - 4^lambda)/4 along e1 and (B - 4^lambda)/4 along e2.
    const double A = 4 * pixel_variance * major2 + 1, B = 4 * pixel_variance * minor2 + 1;
    if (A > std::numeric_limits<float>::max()) { // past float range (the shader's +Inf): one lookup, coarsest
        p.lod = clamp_lod(chain, INFINITY, options);
        return p;
    }
    double v9 = 0, w9 = 0; // the 9-probe row's weighted index variance V(4)
    for (int k = -max_half; k <= max_half; ++k) {
        w9 += reference_ewa_fast_weight(k, max_half);
        v9 += reference_ewa_fast_weight(k, max_half) * k * k;
    }
    v9 /= w9;
    p.triangle = A < row_from * B;
    const double c2 = spacing * spacing;
    // The row's LOD from the triangle's where they meet (A = 1.5 B) down to its own at A = 3 B (continuous).
    const double meet = std::clamp(2 - A / (row_from * B), 0.0, 1.0);
    const double target = p.triangle ? A / (1 + 4 * c2 / 6)
                                     : std::max({B / (1 + c2), A / (1 + 4 * v9 * c2), meet * A / (1 + 4 * c2 / 6)});
    p.lod = clamp_lod(chain, 0.5 * std::log2(target) + options.lod_bias, options);
    const double texel = std::exp2(p.lod), t2 = texel * texel, reach = spacing * texel;
    const double along = std::max(A - t2, 0.0), across = std::max(B - t2, 0.0); // 4 × the variances to carry
    if (p.triangle) {
        // √S = ½(√along e1e1ᵀ + √across e2e2ᵀ); the vertices √2·√S·(cos, sin)(90°, 210°, 330°), pairwise √6·s
        // apart for S = s²I: shrunk so that √(3 tr S) stays within the spacing.
        const double r1 = 0.5 * std::sqrt(along), r2 = 0.5 * std::sqrt(across);
        if ((r1 + r2) * (r1 + r2) <= one_probe * t2) {
            p.triangle = false;
            return p;
        }
        const double shrink = std::min(1.0, reach / std::sqrt(3 * (r1 * r1 + r2 * r2)));
        for (int k = 0; k < 3; ++k) {
            const double angle = 3.14159265358979323846 * (0.5 + 2.0 * k / 3.0);
            const glm::dvec2 q(std::cos(angle), std::sin(angle));
            const glm::dvec2 x = std::sqrt(2.0) * shrink * (r1 * glm::dot(e1, q) * e1 + r2 * glm::dot(e2, q) * e2);
            p.offsets[size_t(k)] = x * to_uv;
        }
        return p;
    }
    const double spread = 0.5 * std::sqrt(along);
    p.half = int(std::clamp(std::ceil(2 * spread / reach - 0.3), 0.0, double(max_half)));
    if (p.half == 0) return p;
    double weights = 0, moment = 0, alternating = 0;
    for (int k = -p.half; k <= p.half; ++k) {
        weights += reference_ewa_fast_weight(k, p.half);
        moment += reference_ewa_fast_weight(k, p.half) * k * k;
        alternating += reference_ewa_fast_weight(k, p.half) * (k % 2 == 0 ? 1 : -1);
    }
    p.zigzag_mean = alternating / weights;
    const double delta = std::min(spread / std::sqrt(moment / weights), reach);
    // Zigzag amplitude d: its variance d²(1 - mean²) across the row, d at most half the spacing.
    const double d = std::min(0.5 * std::sqrt(across / (1 - p.zigzag_mean * p.zigzag_mean)), 0.5 * reach);
    p.step = delta * e1 * to_uv;
    p.zigzag = d * e2 * to_uv;
    return p;
}

glm::dvec4 reference_ewa_fast(const MipChain& chain, const SamplerOptions& options, const Lookup& given,
                              const TexelSource& texels) {
    return reference_ewa_fast_layout(chain, options, given, reference_ewa_fast_probes(chain, options, given), texels);
}

glm::dvec4 reference_ewa_fast_layout(const MipChain& chain, const SamplerOptions& options, const Lookup& given,
                                     const EwaFastProbes& p, const TexelSource& texels) {
    auto probe = [&](glm::dvec2 centre, glm::dvec2 offset) {
        return reference_hardware_trilinear(chain, p.lod, reduce_uv(centre.x + offset.x, options.wrap),
                                            reduce_uv(centre.y + offset.y, options.wrap), options.wrap, texels);
    };
    // The centre first (reference_aniso_centre), with the layout's extent: clamp keeps every probe past the edge
    // it was past.
    glm::dvec2 extent(0.0);
    if (p.triangle) {
        extent = 2.0 * (glm::abs(p.offsets[0]) + glm::abs(p.offsets[1] - p.offsets[2]) * 0.5);
    } else {
        extent = 2.0 * p.half * glm::abs(p.step) + 4.0 * glm::abs(p.zigzag);
    }
    const glm::dvec2 centre(reference_aniso_centre(given.u, extent.x, options.wrap),
                            reference_aniso_centre(given.v, extent.y, options.wrap));
    if (p.triangle)
        return (probe(centre, p.offsets[0]) + probe(centre, p.offsets[1]) + probe(centre, p.offsets[2])) / 3.0;
    glm::dvec4 sum(0.0);
    double weights = 0;
    for (int t = -p.half; t <= p.half; ++t) {
        const double weight = p.half == 0 ? 1.0 : reference_ewa_fast_weight(t, p.half);
        sum += weight * probe(centre, double(t) * p.step + ((t % 2 == 0 ? 1.0 : -1.0) - p.zigzag_mean) * p.zigzag);
        weights += weight;
    }
    return sum / weights;
}

} // namespace tf
