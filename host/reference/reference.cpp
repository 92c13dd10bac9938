#include "reference/reference.h"

#include "texture/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace tf {

namespace {

// Beyond 2^52 every double is an integer and fractions vanish; clamping there keeps the
// conversion to long long defined for any finite uv (e.g. 1e30) without changing the result's form.
constexpr double kMaxTexel = 4503599627370496.0; // 2^52

double clamp_texel(double x) { return std::clamp(x, -kMaxTexel, kMaxTexel); }

glm::dvec4 fetch(const Image& level, long long i, long long j, Wrap wrap) {
    return glm::dvec4(level.at(wrap_texel(i, level.width, wrap), wrap_texel(j, level.height, wrap)));
}

int clamp_level(const MipChain& chain, int l) { return std::clamp(l, 0, int(chain.levels.size()) - 1); }

// Texel (i, j) of level `l` (`image`): through the texel source when there is one, else wrapped.
glm::dvec4 read_texel(const Image& image, int l, long long i, long long j, Wrap wrap, const TexelSource& texels) {
    return texels.read ? texels.read(texels.map, l, i, j) : fetch(image, i, j, wrap);
}

glm::dvec4 nearest_on(const Image& level, int l, double u, double v, Wrap wrap, const TexelSource& texels) {
    if (!finite_uv({u, v})) return glm::dvec4(0.0);
    u = reduce_uv(u, wrap), v = reduce_uv(v, wrap);
    const auto i = (long long)std::floor(clamp_texel(u * level.width));
    const auto j = (long long)std::floor(clamp_texel(v * level.height));
    return read_texel(level, l, i, j, wrap, texels);
}

glm::dvec4 bilinear_on(const Image& level, int l, double u, double v, Wrap wrap, const TexelSource& texels) {
    if (!finite_uv({u, v})) return glm::dvec4(0.0);
    u = reduce_uv(u, wrap), v = reduce_uv(v, wrap);
    const double x = clamp_texel(u * level.width - 0.5), y = clamp_texel(v * level.height - 0.5);
    const double fx = std::floor(x), fy = std::floor(y);
    const double a = x - fx, b = y - fy;
    const auto i0 = (long long)fx, j0 = (long long)fy;
    return (1 - a) * (1 - b) * read_texel(level, l, i0, j0, wrap, texels) +
           a * (1 - b) * read_texel(level, l, i0 + 1, j0, wrap, texels) +
           (1 - a) * b * read_texel(level, l, i0, j0 + 1, wrap, texels) +
           a * b * read_texel(level, l, i0 + 1, j0 + 1, wrap, texels);
}

} // namespace

double clamp_lod(const MipChain& chain, double lambda, const SamplerOptions& options) {
    if (chain.levels.empty()) throw Error("clamp_lod: empty MIP chain");
    double d = std::isnan(lambda) ? INFINITY : lambda; // e.g. -inf + inf bias: blur fully, like non-finite input
    if (!std::isnan(options.lod_min)) d = std::max(d, double(options.lod_min));
    if (!std::isnan(options.lod_max)) d = std::min(d, double(options.lod_max));
    return std::clamp(d, 0.0, double(chain.levels.size() - 1)); // d is not NaN here
}

bool finite_uv(const Lookup& l) {
    const double fmax = std::numeric_limits<float>::max();
    return std::abs(l.u) <= fmax && std::abs(l.v) <= fmax; // false for NaN too
}

bool finite_footprint(const MipChain& chain, const Lookup& l) {
    if (chain.levels.empty()) throw Error("finite_footprint: empty MIP chain");
    const double fmax = std::numeric_limits<float>::max();
    const double overflow = 0x1p128 - 0x1p103; // float rounds |x| >= this to Inf
    const double w0 = chain.levels[0].width, h0 = chain.levels[0].height;
    for (double g : {l.dudx, l.dvdx, l.dudy, l.dvdy})
        if (!(std::abs(g) <= fmax)) return false;
    return std::abs(l.dudx * w0) < overflow && std::abs(l.dudy * w0) < overflow && std::abs(l.dvdx * h0) < overflow &&
           std::abs(l.dvdy * h0) < overflow;
}

double reduce_uv(double u, Wrap wrap) {
    if (wrap == Wrap::clamp) return std::clamp(u, -1.0, 2.0);
    return u - 2.0 * std::nearbyint(0.5 * u); // repeat and mirror: whole periods of 2 (ties to even), into [-1, 1]
}

int wrap_texel(long long i, int size, Wrap wrap) {
    if (size < 1) throw Error("wrap_texel: size " + std::to_string(size) + " < 1");
    const long long n = size;
    switch (wrap) {
    case Wrap::repeat:
        return int(((i % n) + n) % n);
    case Wrap::clamp:
        return int(std::clamp(i, 0LL, n - 1));
    case Wrap::mirror: {
        // Vulkan mirrored repeat: period 2n, second half reversed.
        const long long t = ((i % (2 * n)) + 2 * n) % (2 * n);
        return int(t < n ? t : 2 * n - 1 - t);
    }
    }
    throw Error("wrap_texel: invalid wrap mode");
}

double reference_lod(const MipChain& chain, const Lookup& lookup, const SamplerOptions& options) {
    if (chain.levels.empty()) throw Error("reference_lod: empty MIP chain");
    if (!finite_footprint(chain, lookup)) return INFINITY;
    const double w0 = chain.levels[0].width, h0 = chain.levels[0].height;
    const double rho_x = std::hypot(lookup.dudx * w0, lookup.dvdx * h0);
    const double rho_y = std::hypot(lookup.dudy * w0, lookup.dvdy * h0);
    const double rho = std::max(rho_x, rho_y);
    if (rho == 0.0) return -INFINITY;
    return std::log2(rho) + double(options.lod_bias);
}

glm::dvec4 reference_nearest(const Image& level, double u, double v, Wrap wrap) {
    return nearest_on(level, 0, u, v, wrap, TexelSource{});
}

glm::dvec4 reference_bilinear(const Image& level, double u, double v, Wrap wrap) {
    return bilinear_on(level, 0, u, v, wrap, TexelSource{});
}

glm::dvec4 reference_nearest(const MipChain& chain, int level, double u, double v, Wrap wrap,
                             const TexelSource& texels) {
    const int l = clamp_level(chain, level);
    return nearest_on(chain.levels[size_t(l)], l, u, v, wrap, texels);
}

glm::dvec4 reference_bilinear(const MipChain& chain, int level, double u, double v, Wrap wrap,
                              const TexelSource& texels) {
    const int l = clamp_level(chain, level);
    return bilinear_on(chain.levels[size_t(l)], l, u, v, wrap, texels);
}

glm::dvec4 reference_hardware_tap(const MipChain& chain, int level, double u, double v, Wrap wrap,
                                  const TexelSource& texels) {
    return texels.tap ? texels.tap(texels.map, level, u, v) : reference_bilinear(chain, level, u, v, wrap, texels);
}

glm::dvec4 reference_trilinear_at(const MipChain& chain, double lod, double u, double v, Wrap wrap,
                                  const TexelSource& texels, Reconstruction finest) {
    const double d = std::clamp(lod, 0.0, double(chain.levels.size() - 1));
    const int lo = int(std::floor(d));
    const double f = d - lo; // 0 on the last level: level lo + 1 is never read
    return blend_levels(lo, f, [&](int level) {
        return level == 0 ? reference_cubic(chain, 0, u, v, wrap, finest, texels)
                          : reference_bilinear(chain, level, u, v, wrap, texels);
    });
}

glm::dvec4 reference_hardware_trilinear(const MipChain& chain, double lod, double u, double v, Wrap wrap,
                                        const TexelSource& texels, Reconstruction finest) {
    if (!texels.tap) return reference_trilinear_at(chain, lod, u, v, wrap, texels, finest);
    const double d = std::clamp(lod, 0.0, double(chain.levels.size() - 1));
    const int lo = int(std::floor(d));
    return blend_levels(lo, d - lo, [&](int level) {
        return level == 0 ? reference_magnified(chain, u, v, wrap, finest, Taps::hardware, texels)
                          : reference_hardware_tap(chain, level, u, v, wrap, texels);
    });
}

glm::dvec4 reference_sample_texels(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup,
                                   const TexelSource& texels) {
    if (chain.levels.empty()) throw Error("reference_sample: empty MIP chain");
    if (!finite_uv(lookup)) return glm::dvec4(0.0);
    Lookup reduced = lookup; // whole periods first (the probes of aniso are reduced again, per probe)
    reduced.u = reduce_uv(lookup.u, options.wrap), reduced.v = reduce_uv(lookup.v, options.wrap);

    switch (options.filter) {
    case Filter::nearest:
    case Filter::hw_nearest:
        return reference_nearest(chain, 0, reduced.u, reduced.v, options.wrap, texels);
    case Filter::bilinear:
    case Filter::hw_bilinear:
        return reference_bilinear(chain, 0, reduced.u, reduced.v, options.wrap, texels);
    case Filter::nearest_mip:
    case Filter::bilinear_mip: {
        // Vulkan mipmapMode NEAREST: level = ceil(d + 1/2) - 1, so d = 0.5 still picks level 0.
        const double d = clamp_lod(chain, reference_lod(chain, reduced, options), options);
        const int level = int(std::ceil(d + 0.5)) - 1;
        return options.filter == Filter::nearest_mip
                   ? reference_nearest(chain, level, reduced.u, reduced.v, options.wrap, texels)
                   : reference_bilinear(chain, level, reduced.u, reduced.v, options.wrap, texels);
    }
    case Filter::trilinear:
    case Filter::hw_trilinear:
        return reference_trilinear_at(chain, clamp_lod(chain, reference_lod(chain, reduced, options), options),
                                      reduced.u, reduced.v, options.wrap, texels,
                                      options.filter == Filter::trilinear ? options.magnify : Reconstruction::bilinear);
    case Filter::aniso: // its centre is placed by reference_aniso_centre, each probe reduced again
        return reference_aniso(chain, options, lookup, texels);
    case Filter::ewa_fast: // as aniso's
        return reference_ewa_fast(chain, options, lookup, texels);
    case Filter::ewa: {
        // Magnification: level 0's trilinear share is the magnification filter's (bilinear or --magnify's cubic;
        // a bilinear hardware tap through the texel source's tap where it has one: the cube's device taps),
        // integrated over the pixel's footprint (reference_ewa_magnified).
        const double share = magnified_share(chain, options, reduced);
        if (share == 0.0) return reference_ewa(chain, options, reduced, texels);
        const glm::dvec4 magnified = reference_ewa_magnified(chain, options, reduced, texels);
        return share == 1.0 ? magnified
                            : (1.0 - share) * reference_ewa(chain, options, reduced, texels) + share * magnified;
    }
    case Filter::bspline:
        return reference_magnified(chain, reduced.u, reduced.v, options.wrap, Reconstruction::bspline, options.taps,
                                   texels);
    case Filter::catmull_rom:
        return reference_magnified(chain, reduced.u, reduced.v, options.wrap, Reconstruction::catmull_rom,
                                   options.taps, texels);
    case Filter::brilinear:
    case Filter::sat:
    case Filter::sat_assembly:
    case Filter::hw_aniso:
    case Filter::ground_truth:
    case Filter::none:
        break;
    }
    throw Error("reference_sample: " + to_string(options.filter) + " does not read through a texel source");
}

glm::dvec4 reference_sample(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup,
                            const SatLevels* sat) {
    if (chain.levels.empty()) throw Error("reference_sample: empty MIP chain");
    if (options.filter == Filter::hw_aniso)
        throw Error("hw-aniso has no CPU reference: anisotropic filtering is implementation-defined in Vulkan");
    if (options.filter == Filter::ground_truth)
        throw Error("ground-truth integrates over a pixel of a scene, not around one lookup: render it");
    if (!finite_uv(lookup)) return glm::dvec4(0.0);
    switch (options.filter) {
    case Filter::brilinear: {
        Lookup reduced = lookup; // whole periods first, as every family
        reduced.u = reduce_uv(lookup.u, options.wrap), reduced.v = reduce_uv(lookup.v, options.wrap);
        return reference_brilinear(chain, options, reduced);
    }
    case Filter::sat:
    case Filter::sat_assembly:
        return reference_sat(chain, options, lookup, sat ? *sat : reference_sat_levels(chain.levels[0]));
    case Filter::none: { // the baseline: the scene's uv as colour, no texture; blue 0.5 where the gradients
        // are finite (the shader consumes them so that their cost is in the baseline)
        const bool finite = std::isfinite(lookup.dudx) && std::isfinite(lookup.dvdx) && std::isfinite(lookup.dudy) &&
                            std::isfinite(lookup.dvdy);
        return glm::dvec4(lookup.u - std::floor(lookup.u), lookup.v - std::floor(lookup.v), finite ? 0.5 : 0.0, 1.0);
    }
    case Filter::nearest:
    case Filter::hw_nearest:
    case Filter::bilinear:
    case Filter::hw_bilinear:
    case Filter::nearest_mip:
    case Filter::bilinear_mip:
    case Filter::trilinear:
    case Filter::hw_trilinear:
    case Filter::aniso:
    case Filter::ewa:
    case Filter::ewa_fast:
    case Filter::bspline:
    case Filter::catmull_rom:
        return reference_sample_texels(chain, options, lookup, TexelSource{});
    case Filter::hw_aniso:
    case Filter::ground_truth:
        break;
    }
    throw Error("reference_sample: invalid filter");
}

} // namespace tf
