#pragma once
// The CPU reference: every filter written from the Vulkan spec's texel-filtering math in double
// precision, independently of the GLSL. Goldens come from here and nowhere else.
#include "core/filter.h"
#include "core/lookup.h"
#include "texture/mip.h"

#include <array>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace tf {

// The degenerate-input rules every family shares (docs/API.md, "Degenerate input"); the shaders see float
// input, so the reference reads any value past float range (|x| > FLT_MAX) as the ±Inf a float holds:
// - finite_footprint: every gradient component finite and within float range, and every footprint entry
//   (gradient · level-0 size) within it too (below 2^128 - 2^103, where float rounds to Inf); otherwise
//   the footprint is non-finite (the coarsest level allowed; aniso one probe; ewa M = I);
// - finite_uv: u and v finite and within float range, else the result is (0,0,0,0);
// - reduce_uv: uv moved by whole periods of 2 into [-1, 1] (repeat, mirror; [-1, 1] itself unchanged) or
//   clamped to [-1, 2] (clamp), before any texel coordinate is formed: the same texels, no overflow.
bool finite_footprint(const MipChain& chain, const Lookup& lookup);
bool finite_uv(const Lookup& lookup);
double reduce_uv(double u, Wrap wrap);

// Integer texel coordinate wrapped into [0, size) (Vulkan repeat, clamp-to-edge, mirrored repeat).
int wrap_texel(long long i, int size, Wrap wrap);

// Where a family reads texel (i, j) of level `level` of its chain, i and j any integers (outside the level
// too). The default (read null) is the 2D rule: the level's texel at wrap_texel of each coordinate by the
// sampler's wrap mode. Environment maps pass their own seamless rule (reference/environment.h,
// docs/ENVIRONMENT.md): the same families then run on a face or a lat-long texture. A plain function
// pointer: the 2D default costs one predictable branch a texel, no indirect call.
struct TexelSource {
    glm::dvec4 (*read)(const void* map, int level, long long i, long long j) = nullptr;
    const void* map = nullptr; // what `read` reads (a cube face, a lat-long chain)
    // A hardware tap (the _hw forms' textureLod, `--taps hardware`): the device's bilinear filter at uv of
    // `level`. Null: bilinear through `read`, which is what a 2D sampler does; a cube's device instead
    // re-projects a tap past a face edge onto the adjacent face and filters there (environment.cpp).
    glm::dvec4 (*tap)(const void* map, int level, double u, double v) = nullptr;
};

// Unclamped LOD: log2(rho) + bias, rho = max(|J e_x|, |J e_y|) with J in level-0 texels.
// Zero gradients give -inf; non-finite gradients give +inf (the coarsest level: safe, never a hang).
double reference_lod(const MipChain& chain, const Lookup& lookup, const SamplerOptions& options);

// Nearest / bilinear on one level (u_l = u * w_l; linear uses i0 = floor(u_l - 0.5), alpha = frac).
glm::dvec4 reference_nearest(const Image& level, double u, double v, Wrap wrap);
glm::dvec4 reference_bilinear(const Image& level, double u, double v, Wrap wrap);
// The same on level `level` (clamped to the chain's levels) of `chain`, its texels read through `texels`.
glm::dvec4 reference_nearest(const MipChain& chain, int level, double u, double v, Wrap wrap,
                             const TexelSource& texels);
glm::dvec4 reference_bilinear(const MipChain& chain, int level, double u, double v, Wrap wrap,
                              const TexelSource& texels);

// The LOD clamps every family shares: lambda to [lod_min, lod_max], then to the levels [0, levels-1]. NaN
// follows the shaders' rule (tfi_clamp_lod in shaders/texfilter/lod.glsl; docs/API.md, "Degenerate
// input"): a NaN lambda counts as +inf (blur fully: the coarsest level the clamps allow), a NaN bound as
// no bound. -inf (zero gradients) ends on the finest level allowed.
double clamp_lod(const MipChain& chain, double lambda, const SamplerOptions& options);

// The two-level blend every family that blends MIP levels shares (trilinear, brilinear, aniso probes, ewa):
// (1 - w) * level_value(lo) + w * level_value(lo + 1), w the coarser level's weight in [0, 1]; a level
// that weighs 0 is not evaluated (so lo + 1 may be past the last level when w == 0).
template <typename LevelValue>
glm::dvec4 blend_levels(int lo, double w, LevelValue level_value) {
    if (w == 0.0) return level_value(lo);
    if (w == 1.0) return level_value(lo + 1);
    return (1.0 - w) * level_value(lo) + w * level_value(lo + 1);
}

// One hardware tap (texels.tap, else reference_bilinear through texels) on level `level`.
glm::dvec4 reference_hardware_tap(const MipChain& chain, int level, double u, double v, Wrap wrap,
                                  const TexelSource& texels);

// Cubic reconstruction of level `level` (reference/bicubic.cpp): sum over the texels i, j within the kernel's
// support of k(x - (i + 1/2)) k(y - (j + 1/2)) texel(i, j), x = u·w_l. cubic_kernel is k: the B-spline, Catmull-Rom
// (Mitchell-Netravali B = 1, C = 0 and B = 0, C = 1/2) or, for bilinear, the tent (then reference_cubic is
// reference_bilinear).
double cubic_kernel(double d, Reconstruction kernel);
glm::dvec4 reference_cubic(const MipChain& chain, int level, double u, double v, Wrap wrap, Reconstruction kernel,
                           const TexelSource& texels = {});
// The same sum as the hardware-tap forms read it (--taps hardware): per axis, neighbouring texels whose
// weights share a sign become one bilinear tap at their weighted centre, weighted by their sum (B-spline: two
// pairs; Catmull-Rom: the middle pair and the two outer texels alone), each tap read by reference_hardware_tap.
// Through a 2D sampler that is reference_cubic again (a tap blends its pair by the same ratio); a cube's taps
// past a face edge are re-projected and filtered there, a lat-long sampler clamps at the poles (environment.cpp),
// so near those the tap form differs from the texel sum, as the device's does. Bilinear: one tap.
glm::dvec4 reference_cubic_taps(const MipChain& chain, int level, double u, double v, Wrap wrap,
                                Reconstruction kernel, const TexelSource& texels = {});
// Level 0 under `kernel` as a filter with `taps` reads it: reference_cubic_taps for hardware taps, else
// reference_cubic.
glm::dvec4 reference_magnified(const MipChain& chain, double u, double v, Wrap wrap, Reconstruction kernel, Taps taps,
                               const TexelSource& texels = {});
// The share of level 0 in trilinear at this lookup's LOD, 1 - clamp(lambda, 0, 1): how far ewa moves towards
// the magnification filter of level 0 (bilinear, or --magnify's cubic; shaders/texfilter/ewa.glsl).
double magnified_share(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup);
// ewa's magnification filter: the mean of reference_magnified at the four points uv + reference_ewa_spread:
// the reconstruction convolved with a spread of the ellipse's own covariance (to second moments).
glm::dvec4 reference_ewa_magnified(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup,
                                   const TexelSource& texels = {});
// The per-axis variance of ewa's weight exp(-alpha r²) - exp(-alpha R²) over r² < R² (R² = 2), in units
// of its ellipse's M: 0.21 at alpha 2, 1/3 as alpha goes to 0 (alpha below 1/64 counts as 1/64).
double reference_ewa_weight_variance(double alpha);
// ewa's alpha as the shader clamps it: [0, 64], NaN and negative read as 0.
double reference_ewa_alpha(const SamplerOptions& options);
// The four offsets of ewa's magnification points, k·J·(1, 1), -k·J·(1, 1), k·J·(1, -1), -k·J·(1, -1) (J the
// lookup's gradients, k² = reference_ewa_weight_variance(alpha)): their covariance is k²·J·Jᵀ. All zero unless
// (|dudx| + |dudy|)·width and (|dvdx| + |dvdy|)·height are within float range (NaN, ±Inf, huge: none).
std::array<glm::dvec2, 4> reference_ewa_spread(const MipChain& chain, const SamplerOptions& options,
                                               const Lookup& lookup);

// Trilinear at a given LOD (clamped to [0, levels-1]): the building block of probes and hardware taps. Level 0
// reconstructed by `finest` (--magnify), the others bilinearly.
glm::dvec4 reference_trilinear_at(const MipChain& chain, double lod, double u, double v, Wrap wrap,
                                  const TexelSource& texels = {}, Reconstruction finest = Reconstruction::bilinear);
// The device's trilinear tap at a given LOD (clamped): two of its bilinear taps blended, each through the texel
// source's tap (a cube's re-projected taps); level 0 through `finest`'s hardware taps (reference_magnified).
// Without a tap in the source: reference_trilinear_at (a 2D sampler's tap is the bilinear blend itself).
glm::dvec4 reference_hardware_trilinear(const MipChain& chain, double lod, double u, double v, Wrap wrap,
                                        const TexelSource& texels, Reconstruction finest = Reconstruction::bilinear);

// The filter families of reference/aniso.cpp, reference/ewa.cpp and reference/sat.cpp (see those files
// and the matching shaders/texfilter/*.glsl headers for the math). uv is finite when these are called.
glm::dvec4 reference_brilinear(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup);
glm::dvec4 reference_aniso(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup,
                           const TexelSource& texels = {});

// aniso's probes (reference/aniso.cpp): probe k at uv + ((k + 1/2)/count - 1/2) * axis, all on `lod`
// (biased and clamped), weighted equally or (feline) by exp(-2 (2 t_k)^2). The debug views and the
// viewer's footprint (reference/footprint.h) read the same numbers the filter uses.
struct AnisoProbes {
    int count = 1;
    double lod = 0;
    glm::dvec2 axis{0.0}; // the whole major axis, uv units (zero for one probe)
    bool gaussian = false;
};
AnisoProbes reference_aniso_probes(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup);
// The probes' centre on one axis, before their offsets: u by whole periods (repeat, mirror), or clamped to
// [-1 - h, 2 + h] with h = |axis|/2 (clamp): every probe past the edge it was past, the rest unmoved, and
// none past float range (reduce_uv's [-1, 2] would move a long footprint that reaches into the texture).
double reference_aniso_centre(double u, double axis, Wrap wrap);

// ewa-fast's layout (reference/ewa_fast.cpp; shaders/texfilter/ewa_fast.glsl): all probes on `lod` (biased and
// clamped). A triangle of 3 equal-weight probes at uv + offsets[k], or a row of 2·half + 1 probes at
// uv + t·step + ((-1)^t - zigzag_mean)·zigzag, t = -half..half, weighted reference_ewa_fast_weight(t, half).
struct EwaFastProbes {
    double lod = 0;
    bool triangle = false;
    std::array<glm::dvec2, 3> offsets{}; // triangle: uv units
    int half = 0;
    glm::dvec2 step{0.0}, zigzag{0.0}; // row: along the major axis and across it, uv units
    double zigzag_mean = 0;
};
double reference_ewa_fast_weight(int t, int half); // exp(-t² / (2 (half / 1.5)²))
EwaFastProbes reference_ewa_fast_probes(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup);
glm::dvec4 reference_ewa_fast(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup,
                              const TexelSource& texels = {});
// The filter with a given layout (its lod changed, for the tests' bound on the device's level blend).
glm::dvec4 reference_ewa_fast_layout(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup,
                                     const EwaFastProbes& probes, const TexelSource& texels = {});

// ewa's footprint (reference/ewa.cpp): the covariance J·Jᵀ in level-0 texels² with its minor axis grown to
// major / max_aniso (all zero for zero or non-finite gradients), and the LOD it reads, biased and clamped.
struct EwaFootprint {
    double xx = 0, xy = 0, yy = 0;
    double lod = 0;
};
EwaFootprint reference_ewa_footprint(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup);
// ewa's M on one level (level texels², the support is xᵀM⁻¹x < R²) for a footprint covariance (level-0
// texels²): the covariance scaled to the level (shrunk to the loop cap) plus the level's reconstruction c·I.
struct EwaLevelShape {
    double xx = 0, xy = 0, yy = 0;
};
EwaLevelShape reference_ewa_level_shape(const MipChain& chain, int level, double cov_xx, double cov_xy, double cov_yy,
                                        double alpha);
// With a texel source (environment maps) a 1x1 level is its one texel (0, 0), whatever the ellipse, as
// ewa.glsl reads it; under the 2D wrap every texel of a 1x1 level is that texel anyway.
glm::dvec4 reference_ewa(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup,
                         const TexelSource& texels = {});

// sat averages each channel quantised to 16 bits over the whole texture's range (reference/sat.cpp): that
// range is found once a batch (reference_render, reference_sample_all), not once a lookup. Throws tf::Error
// for a NaN or ±Inf texel.
struct SatLevels {
    glm::dvec4 lo{0.0};   // per channel: the smallest texel value (quantisation level 0)
    glm::dvec4 span{0.0}; // largest minus lo, rounded up to float; 0 for a constant channel
};
SatLevels reference_sat_levels(const Image& level0);
glm::dvec4 reference_sat(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup,
                         const SatLevels& levels);

// The full filter. hw-* filters map to the spec formula of the same mode (hw-nearest = nearest, ...);
// hw-aniso throws tf::Error (its footprint is implementation-defined). Non-finite uv returns (0,0,0,0).
// `sat`: the texture's SatLevels when the caller has them (null: found here, for this one lookup).
glm::dvec4 reference_sample(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup,
                            const SatLevels* sat = nullptr);
// The families that read through any texel source: nearest, bilinear, nearest-mip, bilinear-mip,
// trilinear, aniso, ewa, and hw-nearest/hw-bilinear/hw-trilinear as their manual formula. The lookup as
// reference_sample takes it (non-finite uv: (0,0,0,0); uv reduced by options.wrap here). Any other filter
// throws tf::Error. reference_sample runs these with the 2D default; environment maps with their rule.
glm::dvec4 reference_sample_texels(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup,
                                   const TexelSource& texels);

} // namespace tf
