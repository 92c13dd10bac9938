// EWA (elliptical weighted average), written from the definition in double precision: see
// shaders/texfilter/ewa.glsl for the filter's contract. Where the shader scans row spans in float with
// overflow guards and accumulates centred moments, this scans each level's whole bounding box in double,
// tests every texel and solves the weighted least-squares normal equations directly.
//
//   J = [dUV/dx dUV/dy] in level-0 texels; the footprint ellipse J·Jᵀ has its minor semi-axis grown
//   to major / max_aniso; lambda = max(log2 minor - 1/2, log2(major / ((K-3)/(4R)))) + bias, clamped.
//   Level l: M = S·(clamped J·Jᵀ)·S + c·I, S = diag(w_l/w_0, h_l/h_0) (s² = its determinant), the first
//   term shrunk so that the support's bounding box half-extents R·sqrt(M.xx), R·sqrt(M.yy) stay
//   <= (K-1)/2 - 1/64 with c = 1; c = (3s² - 1)/(12v), v the weight's variance in units of M: the
//   Gaussian-pixel truth's bilinear tent on level 0 (1/6 level-0 texel²) less the box average the level's
//   texels already are ((1 - s²)/12 level texel²), raised to lift M's smaller eigenvalue to kEwaSmallest,
//   at most 1.
//   Texels with r² = xᵀM⁻¹x < R² (R² = 2) weigh exp(-alpha r²) - exp(-alpha R²) (continuous at the edge).
//   Manual taps: the weighted least-squares fit b + g·d over the texels (d = texel centre - centre),
//   evaluated at d = 0 and clamped to the range of the texels read (a line fitted across a step can
//   overshoot it): it reproduces a linear texture exactly, whichever texels the support catches.
//   Hardware taps: texels in 2x2 blocks at even indices, one exact bilinear lookup per block at its
//   weight centroid less the taps' common centroid offset (so that their weighted mean position is the
//   centre), weighted by the block's total weight: exact on a linear texture too. One bilinear lookup
//   weighs a block's texels by the product of its row and column shares; where that misweighs the block's
//   alternating part (t00 - t10 - t01 + t11) by more than kTwistLimit of the level's weight, the block is
//   two lookups instead, one for each pair of texels along the ellipse's longer extent, each exact.
#include "texture/error.h"
#include "reference/reference.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <glm/common.hpp>

namespace tf {

namespace {

// TF_EWA_MAX_TEXELS's default in ewa.glsl: the loop cap K (texels per row and per column of a level).
constexpr int kMaxTexels = 95;
constexpr double kSupport = 2.0;                                  // R²: the weight's support is r² < R²
constexpr double kHalfBox = 0.5 * (kMaxTexels - 1) - 1.0 / 64.0; // largest bounding-box half-extent
// Largest major semi-axis (M's, without R) on the LOD's level: the support then fits the cap there.
const double kMajorTexels = (kMaxTexels - 3) / (4.0 * std::sqrt(kSupport));
constexpr double kMaxAlpha = 64.0;
// M's smallest eigenvalue on a level, unless the footprint's own is below kEwaSmallest - 1 (then M = S·J·Jᵀ·S + I).
constexpr double kEwaSmallest = 2.5;
constexpr double kTwistLimit = 0.005; // a block's 4|w00 w11 - w10 w01| / w over the level's weight
constexpr double kMaxTexel = 4503599627370496.0; // 2^52: beyond it doubles have no fraction

struct Sym { // symmetric 2x2 matrix
    double xx = 0, xy = 0, yy = 0;
};

// The footprint of a lookup: clamped covariance in level-0 texels² and the LOD before level clamps.
struct Footprint {
    Sym cov;          // all zero for zero or non-finite gradients (M = I on every level)
    double lambda = 0;
};

Footprint footprint(const MipChain& chain, const SamplerOptions& options, const Lookup& l) {
    Footprint fp;
    if (!finite_footprint(chain, l)) { // NaN/±Inf, or past float range (docs/API.md, degenerate input)
        fp.lambda = INFINITY;
        return fp;
    }
    const double w0 = chain.levels[0].width, h0 = chain.levels[0].height;
    const double ax = l.dudx * w0, ay = l.dvdx * h0; // J e_x
    const double bx = l.dudy * w0, by = l.dvdy * h0; // J e_y
    const Sym jj{ax * ax + bx * bx, ax * ay + bx * by, ay * ay + by * by};
    // Eigen-decomposition of J·Jᵀ: eigenvalues from trace and determinant, major axis at angle theta.
    const double half_trace = 0.5 * (jj.xx + jj.yy);
    const double det = (ax * by - ay * bx) * (ax * by - ay * bx);
    const double major2 = half_trace + std::hypot(0.5 * (jj.xx - jj.yy), jj.xy);
    if (major2 <= 0.0) {
        fp.lambda = -INFINITY;
        return fp;
    }
    const double e = options.max_aniso >= 1.0f ? double(options.max_aniso) : 1.0;
    const double minor2 = std::max(det / major2, major2 / (e * e));
    const double theta = 0.5 * std::atan2(2.0 * jj.xy, jj.xx - jj.yy);
    const double c = std::cos(theta), s = std::sin(theta);
    // R diag(major2, minor2) Rᵀ with R = [c -s; s c].
    fp.cov = {major2 * c * c + minor2 * s * s, (major2 - minor2) * c * s, major2 * s * s + minor2 * c * c};
    // The minor semi-axis spans sqrt(2) texels of level lambda (ewa.glsl, Math: where M needs no lift).
    fp.lambda = std::max(0.5 * std::log2(minor2) - 0.5, 0.5 * std::log2(major2) - std::log2(kMajorTexels)) +
                double(options.lod_bias);
    return fp;
}

// The ellipse on one level. The centre uv·size is split into an integer texel `base` and a fraction, so
// that texel offsets stay exact however far uv is from [0, 1]; for repeat and mirror, base moves by a
// multiple of 2·size (both repeat every 2·size texels, and block parity is kept), for clamp it moves
// at most to 2K texels past an edge (every texel there reads the edge).
struct LevelEllipse {
    Sym m;                    // M, level texels²
    long long bx = 0, by = 0; // base texel
    double fx = 0, fy = 0;    // centre - base, in [0, 1)
};

long long reduce_base(long long base, int size, Wrap wrap) {
    if (wrap != Wrap::clamp) {
        const long long period = 2LL * size;
        return ((base % period) + period) % period;
    }
    const long long far = 2LL * kMaxTexels + 2; // even
    if (base > size + far) return size + far + ((base - size - far) & 1); // same parity as base
    if (base < -far) return -far - (base & 1);
    return base;
}

LevelEllipse level_ellipse(const MipChain& chain, int level, const Footprint& fp, const Lookup& l, Wrap wrap,
                           double alpha) {
    const Image& img = chain.levels[size_t(level)];
    const EwaLevelShape m = reference_ewa_level_shape(chain, level, fp.cov.xx, fp.cov.xy, fp.cov.yy, alpha);
    LevelEllipse e;
    e.m = {m.xx, m.xy, m.yy};
    const double cx = std::clamp(l.u * img.width, -kMaxTexel, kMaxTexel);
    const double cy = std::clamp(l.v * img.height, -kMaxTexel, kMaxTexel);
    e.fx = cx - std::floor(cx), e.fy = cy - std::floor(cy);
    e.bx = reduce_base((long long)std::floor(cx), img.width, wrap);
    e.by = reduce_base((long long)std::floor(cy), img.height, wrap);
    return e;
}

// Offset of texel (i, j)'s centre from the lookup's centre, level texels.
void offset(const LevelEllipse& e, double i, double j, double& dx, double& dy) {
    dx = i - double(e.bx) + 0.5 - e.fx, dy = j - double(e.by) + 0.5 - e.fy;
}

// Weight of the texel with integer index (i, j): exp(-alpha r²) - exp(-alpha R²) inside the support,
// 0 outside; scaled by exp(alpha R²)/alpha, i.e. expm1(alpha (R² - r²))/alpha (alpha 0: its limit R² - r²),
// which the normalisation cancels.
double weight(const LevelEllipse& e, long long i, long long j, double alpha) {
    double dx, dy;
    offset(e, double(i), double(j), dx, dy);
    const double det = e.m.xx * e.m.yy - e.m.xy * e.m.xy;
    const double r2 = (e.m.yy * dx * dx - 2.0 * e.m.xy * dx * dy + e.m.xx * dy * dy) / det;
    if (!(r2 < kSupport)) return 0.0;
    return alpha > 0.0 ? std::expm1(alpha * (kSupport - r2)) / alpha : kSupport - r2;
}

// Weighted least squares: minimise sum w (t - b - g·d)² per channel, return b.
struct Fit {
    double w = 0, x = 0, y = 0, xx = 0, xy = 0, yy = 0; // sums of w, w·d, w·d·dᵀ
    glm::dvec4 t{0.0}, tx{0.0}, ty{0.0};                // sums of w·t, w·dx·t, w·dy·t
    glm::dvec4 lo{INFINITY}, hi{-INFINITY};             // the values' range, per channel
    void add(double wt, double dx, double dy, const glm::dvec4& value) {
        w += wt, x += wt * dx, y += wt * dy, xx += wt * dx * dx, xy += wt * dx * dy, yy += wt * dy * dy;
        t += wt * value, tx += wt * dx * value, ty += wt * dy * value;
        lo = glm::min(lo, value), hi = glm::max(hi, value);
    }
    // The fit clamped to the values' range: a line fitted across a step can overshoot it; a linear
    // texture's value at the centre is inside the range (the 4 texel centres around it are in the support).
    glm::dvec4 value() const { return glm::clamp(unclamped(), lo, hi); }
    glm::dvec4 unclamped() const {
        // Normal equations A·(b, gx, gy) = (t, tx, ty), A = [w x y; x xx xy; y xy yy]: Cramer's rule.
        const double a11 = xx, a22 = yy;
        const double det = w * (a11 * a22 - xy * xy) - x * (x * a22 - xy * y) + y * (x * xy - a11 * y);
        if (!(det > 0.0)) return t / w; // a single sample (cannot happen with R² = 2; kept for safety)
        // b = det([t x y; tx a11 xy; ty xy a22]) / det, per channel.
        const glm::dvec4 num = t * (a11 * a22 - xy * xy) - x * (tx * a22 - xy * ty) + y * (tx * xy - a11 * ty);
        return num / det;
    }
};

// First and last texel index whose centre can lie within half-extent h of base + f.
void box_range(long long base, double f, double h, long long& first, long long& last) {
    first = base + (long long)std::floor(f - h - 0.5) - 1;
    last = base + (long long)std::ceil(f + h - 0.5) + 1;
}

long long floor_div2(long long i) { return i >= 0 ? i / 2 : -((1 - i) / 2); }

glm::dvec4 ewa_level(const MipChain& chain, int level, const Footprint& fp, const Lookup& l, double alpha,
                     Wrap wrap, bool hardware, const TexelSource& texels) {
    const Image& img = chain.levels[size_t(level)];
    // ewa.glsl reads a 1x1 level once; the 2D wrap makes every texel that one, an environment rule would not.
    if (texels.read && img.width == 1 && img.height == 1) return texels.read(texels.map, level, 0, 0);
    const LevelEllipse e = level_ellipse(chain, level, fp, l, wrap, alpha);
    long long i0, i1, j0, j1;
    box_range(e.bx, e.fx, std::sqrt(kSupport * e.m.xx), i0, i1); // the support's bounding box
    box_range(e.by, e.fy, std::sqrt(kSupport * e.m.yy), j0, j1);
    Fit fit;
    if (!hardware) {
        for (long long j = j0; j <= j1; ++j)
            for (long long i = i0; i <= i1; ++i)
                if (const double w = weight(e, i, j, alpha); w > 0.0) {
                    double dx, dy;
                    offset(e, double(i), double(j), dx, dy);
                    fit.add(w, dx, dy,
                            texels.read ? texels.read(texels.map, level, i, j)
                                        : glm::dvec4(img.at(wrap_texel(i, img.width, wrap),
                                                            wrap_texel(j, img.height, wrap))));
                }
    } else {
        struct Block {
            long long i, j;          // its first texel
            double w00, w10, w01, w11, w;
        };
        struct Tap {
            double w, x, y; // weight; position in level texels (texel index + 1/2 + fraction)
        };
        std::vector<Block> blocks;
        double w_sum = 0, x_sum = 0, y_sum = 0;
        for (long long bj = floor_div2(j0); bj <= floor_div2(j1); ++bj)
            for (long long bi = floor_div2(i0); bi <= floor_div2(i1); ++bi) {
                const long long i = 2 * bi, j = 2 * bj;
                Block b{i, j, weight(e, i, j, alpha), weight(e, i + 1, j, alpha), weight(e, i, j + 1, alpha),
                        weight(e, i + 1, j + 1, alpha), 0.0};
                b.w = b.w00 + b.w10 + b.w01 + b.w11;
                if (b.w <= 0.0) continue;
                blocks.push_back(b);
                // The block's weight centroid (one tap there, or its two pairs' taps, average to it).
                w_sum += b.w, x_sum += b.w10 + b.w11, y_sum += b.w01 + b.w11;
                x_sum += b.w * (double(i) + 0.5), y_sum += b.w * (double(j) + 0.5);
            }
        if (!(w_sum > 0.0)) throw Error("ewa: no texel weighs anything (cannot happen: the nearest has r² <= 1/2)");
        const bool columns = e.m.yy > e.m.xx; // pairs along the longer extent
        std::vector<Tap> taps;
        for (const Block& b : blocks) {
            const double x = double(b.i) + 0.5, y = double(b.j) + 0.5;
            if (4.0 * std::abs(b.w00 * b.w11 - b.w10 * b.w01) / b.w <= kTwistLimit * w_sum) {
                // Texel coordinate 2b + 1/2 + a puts bilinear's i0 at 2b with fraction a: the weight centroid.
                taps.push_back({b.w, x + (b.w10 + b.w11) / b.w, y + (b.w01 + b.w11) / b.w});
            } else if (columns) {
                if (const double t = b.w00 + b.w01; t > 0.0) taps.push_back({t, x, y + b.w01 / t});
                if (const double t = b.w10 + b.w11; t > 0.0) taps.push_back({t, x + 1.0, y + b.w11 / t});
            } else {
                if (const double t = b.w00 + b.w10; t > 0.0) taps.push_back({t, x + b.w10 / t, y});
                if (const double t = b.w01 + b.w11; t > 0.0) taps.push_back({t, x + b.w11 / t, y + 1.0});
            }
        }
        // Every tap moved by the same offset, so that their weighted mean position is the lookup's centre.
        const double sx = x_sum / w_sum - (double(e.bx) + e.fx), sy = y_sum / w_sum - (double(e.by) + e.fy);
        glm::dvec4 sum(0.0);
        for (const Tap& t : taps)
            sum += t.w * reference_hardware_tap(chain, level, (t.x - sx) / img.width, (t.y - sy) / img.height, wrap,
                                                texels);
        return sum / w_sum;
    }
    if (!(fit.w > 0.0)) throw Error("ewa: no texel weighs anything (cannot happen: the nearest has r² <= 1/2)");
    return fit.value();
}

} // namespace

EwaLevelShape reference_ewa_level_shape(const MipChain& chain, int level, double cov_xx, double cov_xy, double cov_yy,
                                        double alpha) {
    const Image& base = chain.levels[0];
    const Image& img = chain.levels[size_t(level)];
    const double sx = double(img.width) / base.width, sy = double(img.height) / base.height;
    Sym d{sx * sx * cov_xx, sx * sy * cov_xy, sy * sy * cov_yy};
    const double widest = std::max(d.xx, d.yy);
    if (kSupport * (widest + 1.0) > kHalfBox * kHalfBox) { // the loop cap: shrink, same shape
        const double k = (kHalfBox * kHalfBox / kSupport - 1.0) / widest;
        d = {k * d.xx, k * d.xy, k * d.yy};
    }
    // The level's own reconstruction c·I (ewa.glsl, Math): the truth's bilinear tent on level 0 (1/6 level-0
    // texel² per axis) less the box this level already averages ((1 - s²)/12), in units of the weight's
    // variance; at least what lifts M's smaller eigenvalue to kEwaSmallest, at most 1 (the loop cap's bound).
    const double minor = 0.5 * (d.xx + d.yy) - std::hypot(0.5 * (d.xx - d.yy), d.xy);
    const double wanted = (3.0 * sx * sy - 1.0) / (12.0 * reference_ewa_weight_variance(alpha));
    const double c = std::min(std::max(wanted, kEwaSmallest - std::max(minor, 0.0)), 1.0);
    return {d.xx + c, d.xy, d.yy + c};
}

double reference_ewa_alpha(const SamplerOptions& options) {
    return options.alpha >= 0.0f ? std::min(double(options.alpha), kMaxAlpha) : 0.0; // NaN and negative: 0
}

glm::dvec4 reference_ewa(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup,
                         const TexelSource& texels) {
    if (chain.levels.empty()) throw Error("reference_ewa: empty MIP chain");
    const double alpha = reference_ewa_alpha(options);
    const bool hardware = options.taps == Taps::hardware;
    const Footprint fp = footprint(chain, options, lookup);
    const double lambda = clamp_lod(chain, fp.lambda, options);
    const int lo = int(std::floor(lambda));
    return blend_levels(lo, lambda - lo,
                        [&](int level) {
                            return ewa_level(chain, level, fp, lookup, alpha, options.wrap, hardware, texels);
                        });
}

double reference_ewa_weight_variance(double alpha) {
    // E[x²] of the radial weight over the disc r² < R², by Simpson's rule in u = r² (the weight's own
    // definition, not a closed form): per axis, E[x²] = E[r²]/2, and the disc's area element is π du.
    const double a = std::max(alpha, 1.0 / 64.0);
    thread_local double cached_alpha = -1, cached_variance = 0; // one alpha a render: quadrature once
    if (a == cached_alpha) return cached_variance;
    constexpr int kIntervals = 8192; // alpha 64: 64 steps to the weight's e-fold, ~1e-9 relative error
    double mass = 0, moment = 0;
    for (int i = 0; i <= kIntervals; ++i) {
        const double u = kSupport * i / kIntervals;
        const double w = std::exp(-a * u) - std::exp(-a * kSupport);
        const double simpson = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        mass += simpson * w;
        moment += simpson * w * u;
    }
    cached_alpha = a;
    cached_variance = 0.5 * moment / mass;
    return cached_variance;
}

std::array<glm::dvec2, 4> reference_ewa_spread(const MipChain& chain, const SamplerOptions& options,
                                               const Lookup& lookup) {
    const double alpha = reference_ewa_alpha(options);
    const double k = std::sqrt(reference_ewa_weight_variance(alpha));
    glm::dvec2 a(lookup.dudx + lookup.dudy, lookup.dvdx + lookup.dvdy);
    glm::dvec2 b(lookup.dudx - lookup.dudy, lookup.dvdx - lookup.dvdy);
    // No spread unless (|dudx| + |dudy|)·width and (|dvdx| + |dvdy|)·height are within float range (below
    // 2^128 - 2^103, where float rounds to Inf; false for NaN): the shader's one test on its float input.
    const double overflow = 0x1p128 - 0x1p103;
    const double sx = (std::abs(lookup.dudx) + std::abs(lookup.dudy)) * chain.levels[0].width;
    const double sy = (std::abs(lookup.dvdx) + std::abs(lookup.dvdy)) * chain.levels[0].height;
    if (!(sx < overflow && sy < overflow)) a = b = glm::dvec2(0.0);
    return {k * a, -k * a, k * b, -k * b};
}

glm::dvec4 reference_ewa_magnified(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup,
                                   const TexelSource& texels) {
    glm::dvec4 sum(0.0);
    for (const glm::dvec2 offset : reference_ewa_spread(chain, options, lookup))
        sum += reference_magnified(chain, lookup.u + offset.x, lookup.v + offset.y, options.wrap, options.magnify,
                                   options.taps, texels);
    return 0.25 * sum;
}

} // namespace tf

namespace tf {

EwaFootprint reference_ewa_footprint(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup) {
    if (chain.levels.empty()) throw Error("reference_ewa: empty MIP chain");
    const Footprint fp = footprint(chain, options, lookup);
    return {fp.cov.xx, fp.cov.xy, fp.cov.yy, clamp_lod(chain, fp.lambda, options)};
}

} // namespace tf
