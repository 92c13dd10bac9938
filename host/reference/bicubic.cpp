// Cubic reconstruction (reference.h): the kernels as functions of the distance to a texel centre, in double,
// summed over the texels within their support. Written from the kernels' definitions (Mitchell and
// Netravali's two-parameter family: B-spline B = 1, C = 0; Catmull-Rom B = 0, C = 1/2), not from
// shaders/texfilter/bicubic.glsl's per-fraction weight polynomials or its merged hardware taps.
#include "reference/reference.h"
#include "texture/error.h"
#include <algorithm>
#include <cmath>
#include <vector>

namespace tf {

namespace {

constexpr double kMaxTexel = 4503599627370496.0; // 2^52, as reference.cpp: conversions stay defined

// Mitchell-Netravali's cubic k_{B,C}(d), support |d| < 2.
double mitchell_netravali(double d, double b, double c) {
    d = std::abs(d);
    if (d < 1)
        return ((12 - 9 * b - 6 * c) * d * d * d + (-18 + 12 * b + 6 * c) * d * d + (6 - 2 * b)) / 6;
    if (d < 2)
        return ((-b - 6 * c) * d * d * d + (6 * b + 30 * c) * d * d + (-12 * b - 48 * c) * d + (8 * b + 24 * c)) / 6;
    return 0;
}

// Where a cubic lookup works: the level (clamped to the chain's), and x = u·w_l, y = v·h_l after the uv
// reduction, within +-2^52 so that conversions stay defined.
struct CubicSite {
    int level;
    const Image* image;
    double x, y;
};
CubicSite cubic_site(const MipChain& chain, int level, double u, double v, Wrap wrap) {
    const int l = std::clamp(level, 0, int(chain.levels.size()) - 1);
    const Image& image = chain.levels[size_t(l)];
    return {l, &image, std::clamp(reduce_uv(u, wrap) * image.width, -kMaxTexel, kMaxTexel),
            std::clamp(reduce_uv(v, wrap) * image.height, -kMaxTexel, kMaxTexel)};
}

} // namespace

double cubic_kernel(double d, Reconstruction kernel) {
    switch (kernel) {
    case Reconstruction::bspline: return mitchell_netravali(d, 1.0, 0.0);
    case Reconstruction::catmull_rom: return mitchell_netravali(d, 0.0, 0.5);
    case Reconstruction::bilinear: return std::max(0.0, 1.0 - std::abs(d)); // the tent: Vulkan LINEAR
    }
    throw Error("cubic_kernel: invalid reconstruction");
}

glm::dvec4 reference_cubic(const MipChain& chain, int level, double u, double v, Wrap wrap, Reconstruction kernel,
                           const TexelSource& texels) {
    if (chain.levels.empty()) throw Error("reference_cubic: empty MIP chain");
    if (kernel == Reconstruction::bilinear) return reference_bilinear(chain, level, u, v, wrap, texels);
    if (!finite_uv({u, v})) return glm::dvec4(0.0);
    const auto [l, level_image, x, y] = cubic_site(chain, level, u, v, wrap);
    const Image& image = *level_image;
    // Texel i's centre is at i + 1/2: the texels within distance 2 of x = u·w are i = floor(x - 1/2) - 1 .. + 2.
    const auto i0 = (long long)std::floor(x - 0.5) - 1, j0 = (long long)std::floor(y - 0.5) - 1;
    glm::dvec4 sum(0.0);
    for (long long j = j0; j < j0 + 4; ++j) {
        const double wy = cubic_kernel(y - (double(j) + 0.5), kernel);
        for (long long i = i0; i < i0 + 4; ++i) {
            const double w = cubic_kernel(x - (double(i) + 0.5), kernel) * wy;
            const glm::dvec4 texel = texels.read ? texels.read(texels.map, l, i, j)
                                                 : glm::dvec4(image.at(wrap_texel(i, image.width, wrap),
                                                                       wrap_texel(j, image.height, wrap)));
            sum += w * texel;
        }
    }
    return sum;
}

namespace {

struct AxisTap {
    double position; // in texels of the level: texel i's centre is at i + 1/2
    double weight;
};

// One axis of reference_cubic_taps: the four texels i0 .. i0 + 3 around x, grouped into runs of one sign.
std::vector<AxisTap> axis_taps(double x, Reconstruction kernel) {
    const double i0 = std::floor(x - 0.5) - 1;
    double w[4];
    for (int k = 0; k < 4; ++k) w[k] = cubic_kernel(x - (i0 + k + 0.5), kernel);
    struct Run {
        int first, count;
    };
    // B-spline weights are all positive: two pairs (a tap covers two texels). Catmull-Rom's outer weights are
    // <= 0 and its middle ones >= 0: a tap cannot mix signs, so the outer texels are taps of their own.
    const std::vector<Run> runs = kernel == Reconstruction::bspline ? std::vector<Run>{{0, 2}, {2, 2}}
                                                                    : std::vector<Run>{{0, 1}, {1, 2}, {3, 1}};
    std::vector<AxisTap> taps;
    for (const Run& r : runs) {
        const double sum = r.count == 2 ? w[r.first] + w[r.first + 1] : w[r.first];
        // Bilinear between centres c and c + 1 at c + t blends them (1 - t, t): t = w_second / sum.
        const double t = r.count == 2 && sum != 0 ? w[r.first + 1] / sum : 0.0;
        taps.push_back({i0 + r.first + 0.5 + t, sum});
    }
    return taps;
}

} // namespace

glm::dvec4 reference_cubic_taps(const MipChain& chain, int level, double u, double v, Wrap wrap,
                                Reconstruction kernel, const TexelSource& texels) {
    if (chain.levels.empty()) throw Error("reference_cubic_taps: empty MIP chain");
    if (kernel == Reconstruction::bilinear) return reference_hardware_tap(chain, level, u, v, wrap, texels);
    if (!finite_uv({u, v})) return glm::dvec4(0.0);
    const CubicSite site = cubic_site(chain, level, u, v, wrap);
    const double w = site.image->width, h = site.image->height;
    glm::dvec4 sum(0.0);
    for (const AxisTap& ty : axis_taps(site.y, kernel))
        for (const AxisTap& tx : axis_taps(site.x, kernel))
            sum += tx.weight * ty.weight *
                   reference_hardware_tap(chain, site.level, tx.position / w, ty.position / h, wrap, texels);
    return sum;
}

glm::dvec4 reference_magnified(const MipChain& chain, double u, double v, Wrap wrap, Reconstruction kernel, Taps taps,
                               const TexelSource& texels) {
    return taps == Taps::hardware ? reference_cubic_taps(chain, 0, u, v, wrap, kernel, texels)
                                  : reference_cubic(chain, 0, u, v, wrap, kernel, texels);
}

double magnified_share(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup) {
    return 1.0 - std::min(1.0, clamp_lod(chain, reference_lod(chain, lookup, options), options));
}

} // namespace tf
