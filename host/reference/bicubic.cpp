// Cubic reconstruction (reference.h): the kernels as functions of the distance to a texel centre, in double,
// summed over the texels within their support. Written from the kernels' definitions (Mitchell and
// Netravali's two-parameter family: B-spline B = 1, C = 0; Catmull-Rom B = 0, C = 1/2), not from
// shaders/texfilter/bicubic.glsl's per-fraction weight polynomials or its merged hardware taps.
#include "reference/reference.h"
#include "texture/error.h"
#include <algorithm>
#include <cmath>

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
    const int l = std::clamp(level, 0, int(chain.levels.size()) - 1);
    const Image& image = chain.levels[size_t(l)];
    u = reduce_uv(u, wrap), v = reduce_uv(v, wrap);
    // Texel i's centre is at i + 1/2: the texels within distance 2 of x = u·w are i = floor(x - 1/2) - 1 .. + 2.
    const double x = std::clamp(u * image.width, -kMaxTexel, kMaxTexel);
    const double y = std::clamp(v * image.height, -kMaxTexel, kMaxTexel);
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

double magnified_share(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup) {
    return 1.0 - std::min(1.0, clamp_lod(chain, reference_lod(chain, lookup, options), options));
}

} // namespace tf
