#include "reference/footprint.h"
#include "reference/reference.h"
#include "reference/scene_cast.h"
#include "texture/error.h"
#include <cmath>

namespace tf {

namespace {

// J·Jᵀ in level-0 texels² and its eigen-decomposition: sigma1² >= sigma2² and the major direction.
struct Covariance {
    double xx = 0, xy = 0, yy = 0;
};

struct Axes {
    double major2 = 0, minor2 = 0;
    glm::dvec2 direction{1.0, 0.0}; // unit, texel space
};

Axes eigen(const Covariance& c)
{
    Axes a;
    const double mean = 0.5 * (c.xx + c.yy), dev = std::hypot(0.5 * (c.xx - c.yy), c.xy);
    a.major2 = mean + dev;
    a.minor2 = std::max(mean - dev, 0.0);
    if (dev > 0) {
        const double theta = 0.5 * std::atan2(2.0 * c.xy, c.xx - c.yy);
        a.direction = {std::cos(theta), std::sin(theta)};
    }
    return a;
}

Covariance texel_covariance(const MipChain& chain, const Lookup& l)
{
    const double w = chain.levels[0].width, h = chain.levels[0].height;
    const double a = l.dudx * w, b = l.dudy * w, c = l.dvdx * h, d = l.dvdy * h; // J = [a b; c d]
    return {a * a + b * b, a * c + b * d, c * c + d * d};
}

glm::dvec2 perpendicular(glm::dvec2 v) { return {-v.y, v.x}; }

} // namespace

double footprint_anisotropy(const MipChain& chain, const Lookup& l)
{
    if (chain.levels.empty()) throw Error("footprint_anisotropy: empty MIP chain");
    if (!finite_footprint(chain, l)) return 1.0;
    const double w = chain.levels[0].width, h = chain.levels[0].height;
    const double a = l.dudx * w, b = l.dudy * w, c = l.dvdx * h, d = l.dvdy * h;
    const double sigma1 = std::sqrt(eigen(texel_covariance(chain, l)).major2);
    if (sigma1 == 0) return 1.0;
    const double sigma2 = std::abs(a * d - b * c) / sigma1; // |det J| = sigma1 sigma2
    return sigma2 > 0 ? sigma1 / sigma2 : INFINITY;
}

PixelFootprint lookup_footprint(const MipChain& chain, const SamplerOptions& options, const Lookup& l)
{
    if (chain.levels.empty()) throw Error("lookup_footprint: empty MIP chain");
    PixelFootprint f;
    f.hit = true;
    f.uv = {l.u, l.v};
    f.duv_dx = {l.dudx, l.dvdx};
    f.duv_dy = {l.dudy, l.dvdy};
    f.anisotropy = footprint_anisotropy(chain, l);
    const glm::dvec2 size(chain.levels[0].width, chain.levels[0].height);
    const bool finite = finite_footprint(chain, l);
    glm::dvec2 along = finite ? eigen(texel_covariance(chain, l)).direction : glm::dvec2(1.0, 0.0);
    glm::dvec2 line(0.0); // aniso: the probes' whole axis, texels
    if (options.filter == Filter::ewa) {
        const EwaFootprint e = reference_ewa_footprint(chain, options, l);
        f.lod = e.lod;
        const Axes axes = eigen({e.xx, e.xy, e.yy});
        if (axes.major2 > 0) {
            f.major = 0.5 * std::sqrt(axes.major2) * axes.direction / size;
            f.minor = 0.5 * std::sqrt(axes.minor2) * perpendicular(axes.direction) / size;
            return f;
        }
    } else if (options.filter == Filter::aniso) {
        const AnisoProbes p = reference_aniso_probes(chain, options, l);
        f.lod = p.lod;
        line = p.axis * size;
        for (int k = 0; k < p.count; ++k)
            f.probes.push_back(f.uv + ((k + 0.5) / p.count - 0.5) * p.axis);
    } else {
        f.lod = clamp_lod(chain, reference_lod(chain, l, options), options);
    }
    const double texel = 0.5 * std::exp2(f.lod); // half the sampled level's texel, level-0 texels
    const double length = std::hypot(line.x, line.y);
    if (length > 0) along = line / length;
    f.major = std::max(0.5 * length, texel) * along / size;
    f.minor = texel * perpendicular(along) / size;
    return f;
}

PixelFootprint pixel_footprint(const SceneParams& scene, const MipChain& chain, const SamplerOptions& options,
                               const RenderOptions& render, glm::ivec2 pixel)
{
    const PixelLookup p = reference_pixel_lookup(scene, render.gradients, render.rasterize, pixel.x, pixel.y);
    PixelFootprint f = lookup_footprint(chain, options, p.lookup);
    f.hit = p.hit;
    return f;
}

} // namespace tf
