// CPU reference for brilinear and anisotropic (probe) filtering, in double, from the math in
// shaders/texfilter/brilinear.glsl and aniso.glsl's headers (DESIGN.md section 3), not from their code:
// the SVD here goes through the eigenvectors of J J^T, the shader uses a closed-form rotation split.
// Both taps (manual, hardware) have this one reference: exact trilinear probes.
#include "reference/reference.h"

#include "texture/error.h"

#include <algorithm>
#include <cmath>

namespace tf {

namespace {

constexpr int kMaxProbes = 16;

// N = min(ceil(ratio - 1/64), max_n), at least 1; ratio = +inf (zero minor axis) gives max_n. The 1/64 slack
// keeps isotropic footprints at one probe whatever float noise their derivatives carry.
constexpr double ratio_slack = 1.0 / 64.0;
int probe_count(double ratio, int max_n) { return ratio >= max_n ? max_n : std::max(1, int(std::ceil(ratio - ratio_slack))); }

AnisoProbes gpu_probes(const MipChain& chain, const SamplerOptions& options, const Lookup& l, int max_n) {
    AnisoProbes p;
    const double w = chain.levels[0].width, h = chain.levels[0].height;
    const double px = std::hypot(l.dudx * w, l.dvdx * h), py = std::hypot(l.dudy * w, l.dvdy * h);
    const double pmax = std::max(px, py), pmin = std::min(px, py);
    if (pmax > 0) p.count = pmin > 0 ? probe_count(pmax / pmin, max_n) : max_n;
    // lambda = log2(Pmax / N) + bias; reference_lod is log2(Pmax) + bias (and handles zero gradients).
    p.lod = clamp_lod(chain, reference_lod(chain, l, options) - std::log2(double(p.count)), options);
    if (p.count > 1) {
        const bool x_major = px >= py;
        p.axis = x_major ? glm::dvec2(l.dudx, l.dvdx) : glm::dvec2(l.dudy, l.dvdy);
    }
    return p;
}

AnisoProbes feline_probes(const MipChain& chain, const SamplerOptions& options, const Lookup& l, int max_n) {
    AnisoProbes p;
    p.gaussian = true;
    const double w = chain.levels[0].width, h = chain.levels[0].height;
    // J = [a b; c d], columns d(u,v)/dx and d(u,v)/dy in level-0 texels.
    const double a = l.dudx * w, b = l.dudy * w, c = l.dvdx * h, d = l.dvdy * h;
    // J J^T = [s t; t r]: its eigenvalues are sigma1^2 >= sigma2^2, its first eigenvector is J's major axis.
    const double s = a * a + b * b, t = a * c + b * d, r = c * c + d * d;
    const double mean = 0.5 * (s + r), dev = std::hypot(0.5 * (s - r), t);
    const double sigma1 = std::sqrt(mean + dev);
    if (sigma1 == 0) { // zero gradients: one probe on the finest level
        p.lod = clamp_lod(chain, -INFINITY, options);
        return p;
    }
    const double sigma2 = std::abs(a * d - b * c) / sigma1; // |det J| = sigma1 sigma2, no cancellation
    p.count = sigma2 > 0 ? probe_count(sigma1 / sigma2, max_n) : max_n;
    p.lod = clamp_lod(chain, std::log2(std::max(sigma2, sigma1 / p.count)) + options.lod_bias, options);
    if (p.count > 1) {
        const double theta = 0.5 * std::atan2(2 * t, s - r); // direction of the largest eigenvalue
        p.axis = glm::dvec2(sigma1 * std::cos(theta) / w, sigma1 * std::sin(theta) / h);
    }
    return p;
}

} // namespace

glm::dvec4 reference_brilinear(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup) {
    if (chain.levels.empty()) throw Error("reference_brilinear: empty MIP chain");
    const double d = clamp_lod(chain, reference_lod(chain, lookup, options), options);
    const int lo = int(std::floor(d));
    const double f = d - lo;
    // Weight of level lo+1: a ramp of slope 1/B centred on f = 1/2; B = 0 is the step of the nearest level
    // (Vulkan mipmapMode NEAREST, ceil(d + 1/2) - 1: f = 1/2 stays on the finer level).
    const double band = std::min(double(options.band), 1.0);
    const double weight = band > 0 ? std::clamp((f - (1 - band) / 2) / band, 0.0, 1.0) : (f > 0.5 ? 1.0 : 0.0);
    // weight > 0 needs f > 0, so lo < levels-1 wherever level lo + 1 is read.
    return blend_levels(lo, weight, [&](int level) {
        return reference_bilinear(chain.levels[size_t(level)], lookup.u, lookup.v, options.wrap);
    });
}

AnisoProbes reference_aniso_probes(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup) {
    if (chain.levels.empty()) throw Error("reference_aniso: empty MIP chain");
    const int max_n = std::clamp(options.probes, 1, kMaxProbes);
    if (!finite_footprint(chain, lookup)) { // NaN/±Inf or past float range (reference.h): one probe, coarsest level
        AnisoProbes p;
        p.lod = clamp_lod(chain, INFINITY, options);
        return p;
    }
    return options.aniso_shape == AnisoShape::feline ? feline_probes(chain, options, lookup, max_n)
                                                     : gpu_probes(chain, options, lookup, max_n);
}

double reference_aniso_centre(double u, double axis, Wrap wrap) {
    if (wrap != Wrap::clamp) return reduce_uv(u, wrap);
    const double h = 0.5 * std::abs(axis);
    return std::clamp(u, -1.0 - h, 2.0 + h);
}

glm::dvec4 reference_aniso(const MipChain& chain, const SamplerOptions& options, const Lookup& given,
                           const TexelSource& texels) {
    const AnisoProbes p = reference_aniso_probes(chain, options, given);
    Lookup lookup = given;
    lookup.u = reference_aniso_centre(given.u, p.axis.x, options.wrap);
    lookup.v = reference_aniso_centre(given.v, p.axis.y, options.wrap);
    glm::dvec4 sum(0.0);
    double weights = 0;
    for (int k = 0; k < p.count; ++k) {
        const double t = (k + 0.5) / p.count - 0.5;
        const double weight = p.gaussian ? std::exp(-2 * (2 * t) * (2 * t)) : 1.0;
        const double u = lookup.u + t * p.axis.x, v = lookup.v + t * p.axis.y;
        sum += weight * (options.taps == Taps::hardware // the device's trilinear: two of its taps
                             ? reference_hardware_trilinear(chain, p.lod, u, v, options.wrap, texels, options.magnify)
                             : reference_trilinear_at(chain, p.lod, u, v, options.wrap, texels, options.magnify));
        weights += weight;
    }
    return sum / weights;
}

} // namespace tf
