// --stochastic on the CPU reference (see reference/stochastic.h and shaders/texfilter/stochastic.glsl). Each
// family is written twice from the same rule: `pick` follows the GPU's choice for one xi, `visit` walks every
// outcome with its probability (the moments). ewa's support is scanned here in double over the bounding box,
// with reference_ewa_footprint's covariance and LOD and ewa.glsl's level ellipse and weight.
#include "reference/stochastic.h"
#include "texture/error.h"
#include "texture/threads.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <vector>

namespace tf {

namespace {

using Visit = std::function<void(double p, const glm::dvec4& value)>;

constexpr double kEwaSupport = 2.0; // R²

// Texel (i, j) of `level`: through the texel source where it has a rule (the environment maps), else wrapped.
glm::dvec4 texel(const MipChain& chain, int level, long long i, long long j, Wrap wrap, const TexelSource& texels)
{
    if (texels.read) return texels.read(texels.map, level, i, j);
    const Image& img = chain.levels[size_t(level)];
    return glm::dvec4(img.at(wrap_texel(i, img.width, wrap), wrap_texel(j, img.height, wrap)));
}

// Bilinear on one level: texel i0 + 1 with probability frac(x) per axis (x = u·w − ½).
struct BilinearSplit {
    long long i0, j0;
    double a, b;
};
BilinearSplit split(const MipChain& chain, int level, double u, double v)
{
    const Image& img = chain.levels[size_t(level)];
    const double x = u * img.width - 0.5, y = v * img.height - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    return {(long long)fx, (long long)fy, x - fx, y - fy};
}
glm::dvec4 pick_bilinear(const MipChain& chain, int level, double u, double v, Wrap wrap, Xi xi,
                         const TexelSource& texels)
{
    const BilinearSplit s = split(chain, level, u, v);
    return texel(chain, level, s.i0 + (xi.x < s.a ? 1 : 0), s.j0 + (xi.y < s.b ? 1 : 0), wrap, texels);
}
void visit_bilinear(const MipChain& chain, int level, double u, double v, Wrap wrap, double p, const Visit& visit,
                    const TexelSource& texels)
{
    const BilinearSplit s = split(chain, level, u, v);
    for (int dj = 0; dj < 2; ++dj)
        for (int di = 0; di < 2; ++di)
            visit(p * (di ? s.a : 1.0 - s.a) * (dj ? s.b : 1.0 - s.b),
                  texel(chain, level, s.i0 + di, s.j0 + dj, wrap, texels));
}

// The two-level choice at a clamped lod: the coarser with probability frac(lod); `rest` is xi's unused part.
int pick_level(double lod, double xi, double& rest)
{
    const double lo = std::floor(lod), f = lod - lo;
    const bool coarser = xi < f;
    rest = std::clamp(coarser ? xi / f : (xi - f) / (1.0 - f), 0.0, 0.99999994);
    return int(lo) + (coarser ? 1 : 0);
}
template <typename PerLevel>
void visit_levels(double lod, double p, PerLevel per_level)
{
    const double lo = std::floor(lod), f = lod - lo;
    if (f < 1.0) per_level(int(lo), p * (1.0 - f));
    if (f > 0.0) per_level(int(lo) + 1, p * f);
}

// One trilinear probe at lod: a level, then a texel (manual) or that level's exact bilinear tap (hardware).
glm::dvec4 pick_trilinear(const MipChain& chain, double lod, double u, double v, Wrap wrap, Xi xi, bool hardware,
                          const TexelSource& texels)
{
    double rest;
    const int level = pick_level(lod, xi.z, rest);
    return hardware ? reference_hardware_tap(chain, level, u, v, wrap, texels)
                    : pick_bilinear(chain, level, u, v, wrap, xi, texels);
}
void visit_trilinear(const MipChain& chain, double lod, double u, double v, Wrap wrap, double p, bool hardware,
                     const Visit& visit, const TexelSource& texels)
{
    visit_levels(lod, p, [&](int level, double q) {
        if (hardware)
            visit(q, reference_hardware_tap(chain, level, u, v, wrap, texels));
        else
            visit_bilinear(chain, level, u, v, wrap, q, visit, texels);
    });
}

// aniso's probes: t_k and weights (equal, or feline's exp(−8 t²)), normalised.
std::vector<std::pair<double, double>> probe_weights(const AnisoProbes& probes)
{
    std::vector<std::pair<double, double>> out;
    double total = 0;
    for (int k = 0; k < probes.count; ++k) {
        const double t = (k + 0.5) / probes.count - 0.5;
        const double w = probes.gaussian ? std::exp(-8.0 * t * t) : 1.0;
        out.push_back({t, w});
        total += w;
    }
    for (auto& [t, w] : out) w /= total;
    return out;
}

// ewa: the support of one level, every texel with its weight (unnormalised), level texel indices.
struct WeightedTexel {
    long long i, j;
    double w;
};
std::vector<WeightedTexel> ewa_support(const MipChain& chain, int level, const EwaFootprint& fp, double u, double v,
                                       double alpha)
{
    const Image& img = chain.levels[size_t(level)];
    if (img.width == 1 && img.height == 1) return {{0, 0, 1.0}};
    const EwaLevelShape m = reference_ewa_level_shape(chain, level, fp.xx, fp.xy, fp.yy, alpha);
    const double mxx = m.xx, mxy = m.xy, myy = m.yy, det = mxx * myy - mxy * mxy;
    const double cx = u * img.width, cy = v * img.height;
    const double hx = std::sqrt(kEwaSupport * mxx), hy = std::sqrt(kEwaSupport * myy);
    std::vector<WeightedTexel> out;
    for (long long j = (long long)std::floor(cy - hy - 0.5) - 1; j <= (long long)std::ceil(cy + hy - 0.5) + 1; ++j)
        for (long long i = (long long)std::floor(cx - hx - 0.5) - 1; i <= (long long)std::ceil(cx + hx - 0.5) + 1; ++i) {
            const double dx = i + 0.5 - cx, dy = j + 0.5 - cy;
            const double r2 = (myy * dx * dx - 2.0 * mxy * dx * dy + mxx * dy * dy) / det;
            if (r2 < kEwaSupport)
                out.push_back({i, j, alpha > 0.0 ? std::expm1(alpha * (kEwaSupport - r2)) / alpha : kEwaSupport - r2});
        }
    return out;
}

void check_reference_taps(const SamplerOptions& options)
{
    if (options.filter == Filter::ewa && options.taps == Taps::hardware)
        throw Error("--stochastic ewa --taps hardware has no CPU reference (its block taps are the GPU's only): "
                    "use --taps manual or --backend vulkan");
}

// Both halves of every family: pick (xi given) or visit (xi null). uv is finite and reduced (reduced()).
glm::dvec4 run_family(const MipChain& chain, const SamplerOptions& o, const Lookup& l, const Xi* xi, const Visit* visit,
                      const TexelSource& texels)
{
    const bool hw = o.taps == Taps::hardware;
    switch (o.filter) {
    case Filter::bilinear:
        if (hw) { // the hardware's bilinear tap itself
            const glm::dvec4 t = reference_hardware_tap(chain, 0, l.u, l.v, o.wrap, texels);
            if (visit) (*visit)(1.0, t);
            return t;
        }
        if (visit) {
            visit_bilinear(chain, 0, l.u, l.v, o.wrap, 1.0, *visit, texels);
            return {};
        }
        return pick_bilinear(chain, 0, l.u, l.v, o.wrap, *xi, texels);
    case Filter::trilinear: {
        const double lod = clamp_lod(chain, reference_lod(chain, l, o), o);
        if (visit) {
            visit_trilinear(chain, lod, l.u, l.v, o.wrap, 1.0, hw, *visit, texels);
            return {};
        }
        return pick_trilinear(chain, lod, l.u, l.v, o.wrap, *xi, hw, texels);
    }
    case Filter::aniso: {
        const AnisoProbes probes = reference_aniso_probes(chain, o, l);
        const auto weights = probe_weights(probes);
        const double cu = reference_aniso_centre(l.u, probes.axis.x, o.wrap), cv = reference_aniso_centre(l.v, probes.axis.y, o.wrap);
        auto at = [&](double t, double& u, double& v) {
            u = reduce_uv(cu + t * probes.axis.x, o.wrap), v = reduce_uv(cv + t * probes.axis.y, o.wrap);
        };
        if (visit) {
            for (const auto& [t, w] : weights) {
                double u, v;
                at(t, u, v);
                if (hw)
                    (*visit)(w, reference_hardware_trilinear(chain, probes.lod, u, v, o.wrap, texels));
                else
                    visit_trilinear(chain, probes.lod, u, v, o.wrap, w, false, *visit, texels);
            }
            return {};
        }
        Xi x = *xi;
        double t = 0.0;
        if (probes.count > 1) { // the GPU's rule: floor(xi·N) for equal weights, the CDF for feline's
            if (!probes.gaussian) {
                const double k = std::min(std::floor(double(x.z) * probes.count), probes.count - 1.0);
                t = (k + 0.5) / probes.count - 0.5;
                x.z = float(std::clamp(double(x.z) * probes.count - k, 0.0, 0.99999994));
            } else {
                double below = 0;
                for (const auto& [tk, w] : weights) {
                    t = tk;
                    const double rest = std::clamp((double(x.z) - below) / w, 0.0, 0.99999994);
                    if (x.z < below + w || &tk == &weights.back().first) {
                        x.z = float(rest);
                        break;
                    }
                    below += w;
                }
            }
        }
        double u, v;
        at(t, u, v);
        return hw ? reference_hardware_trilinear(chain, probes.lod, u, v, o.wrap, texels)
                  : pick_trilinear(chain, probes.lod, u, v, o.wrap, x, false, texels);
    }
    case Filter::ewa: {
        check_reference_taps(o);
        const EwaFootprint fp = reference_ewa_footprint(chain, o, l);
        const double alpha = reference_ewa_alpha(o);
        auto support_of = [&](int level) { return ewa_support(chain, level, fp, l.u, l.v, alpha); };
        // Magnification (ewa.glsl): level 0's trilinear share is the bilinear magnification filter's at four
        // points spread over the footprint (reference_ewa_spread), a quarter of the share each.
        const double share = magnified_share(chain, o, l);
        const std::array<glm::dvec2, 4> spread = reference_ewa_spread(chain, o, l);
        if (visit) {
            if (share > 0.0)
                for (const glm::dvec2 d : spread) // moved back by whole periods, as the shader does
                    visit_bilinear(chain, 0, reduce_uv(l.u + d.x, o.wrap), reduce_uv(l.v + d.y, o.wrap), o.wrap,
                                   0.25 * share, *visit, texels);
            if (share < 1.0) visit_levels(fp.lod, 1.0 - share, [&](int level, double q) {
                const std::vector<WeightedTexel> s = support_of(level);
                double total = 0;
                for (const WeightedTexel& t : s) total += t.w;
                for (const WeightedTexel& t : s) (*visit)(q * t.w / total, texel(chain, level, t.i, t.j, o.wrap, texels));
            });
            return {};
        }
        if (double(xi->z) < share) { // the point as the shader picks it, in float: floor(4·xi.z / share)
            const int point = int(std::min(std::floor(xi->z / float(share) * 4.0f), 3.0f));
            const glm::dvec2 d = spread[size_t(point)];
            return pick_bilinear(chain, 0, reduce_uv(l.u + d.x, o.wrap), reduce_uv(l.v + d.y, o.wrap), o.wrap, *xi,
                                 texels);
        }
        // The rest of xi.z, rescaled in float as the shader does.
        const float z = std::clamp((xi->z - float(share)) / (1.0f - float(share)), 0.0f, 0.99999994f);
        double rest;
        const int level = pick_level(fp.lod, z, rest);
        const std::vector<WeightedTexel> s = support_of(level);
        double total = 0;
        for (const WeightedTexel& t : s) total += t.w;
        const double target = double(xi->x) * total;
        double below = 0;
        for (const WeightedTexel& t : s) {
            if (target < below + t.w || &t == &s.back()) return texel(chain, level, t.i, t.j, o.wrap, texels);
            below += t.w;
        }
        return {};
    }
    default:
        break;
    }
    throw Error("--stochastic applies to bilinear, trilinear, aniso and ewa, not to --filter " + to_string(o.filter));
}

// uv by whole periods (clamp: to [-1, 2]); aniso places its centre itself (reference_aniso_centre).
Lookup reduced(const Lookup& lookup, const SamplerOptions& options)
{
    if (options.filter == Filter::aniso) return lookup;
    Lookup r = lookup;
    r.u = reduce_uv(lookup.u, options.wrap), r.v = reduce_uv(lookup.v, options.wrap);
    return r;
}

} // namespace

glm::dvec4 reference_stochastic_sample(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup, Xi xi,
                                       const TexelSource& texels)
{
    if (chain.levels.empty()) throw Error("reference_stochastic_sample: empty MIP chain");
    if (!finite_uv(lookup)) return glm::dvec4(0.0);
    return run_family(chain, options, reduced(lookup, options), &xi, nullptr, texels);
}

StochasticMoments reference_stochastic_moments(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup,
                                               const TexelSource& texels)
{
    if (chain.levels.empty()) throw Error("reference_stochastic_moments: empty MIP chain");
    StochasticMoments m;
    if (!finite_uv(lookup)) return m;
    glm::dvec4 sum2(0.0);
    const Visit visit = [&](double p, const glm::dvec4& t) {
        m.mean += p * t;
        sum2 += p * t * t;
    };
    run_family(chain, options, reduced(lookup, options), nullptr, &visit, texels);
    m.variance = glm::max(sum2 - m.mean * m.mean, glm::dvec4(0.0));
    return m;
}

void check_reference_stochastic(const SamplerOptions& options)
{
    check_stochastic(options);
    check_reference_taps(options);
}

glm::dvec4 reference_stochastic_mean(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup, int px,
                                     int py, uint32_t lookup_index, const TexelSource& texels)
{
    glm::dvec4 sum(0.0);
    for (int f = 0; f < options.accumulate; ++f)
        sum += reference_stochastic_sample(
            chain, options, lookup,
            stochastic_xi(options.noise, px, py, options.stochastic_first + uint32_t(f), lookup_index), texels);
    return sum / double(options.accumulate);
}

Image reference_render_stochastic(const SceneParams& scene, const MipChain& chain, const SamplerOptions& options,
                                  const RenderOptions& render)
{
    check_reference_stochastic(options);
    const int width = scene.kind_size.y, height = scene.kind_size.z;
    const std::vector<PixelLookup> lookups = reference_lookups(scene, render.gradients, render.rasterize);
    Image out = make_image(width, height);
    parallel_for(size_t(height), [&](size_t y) {
        for (int x = 0; x < width; ++x) {
            const size_t i = y * size_t(width) + size_t(x);
            if (!lookups[i].hit) {
                out.texels[i] = scene.background;
                continue;
            }
            out.texels[i] = glm::vec4(reference_stochastic_mean(chain, options, lookups[i].lookup, x, int(y), 0u));
        }
    });
    return out;
}

} // namespace tf
