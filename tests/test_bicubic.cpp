// Bicubic magnification (shaders/texfilter/bicubic.glsl, host/reference/bicubic.cpp): the kernels' defining
// facts, polynomial reproduction, --magnify's limits in trilinear, aniso and ewa on the CPU reference; the
// GPU's manual and hardware-tap forms and --magnify against the reference, on the test device, with bounds
// from float precision and the device's subTexelPrecisionBits. One line per check: measured and bound.
#include "core/filter.h"
#include "core/procedural.h"
#include "reference/reference.h"
#include "support.h"
#include "texture/image.h"
#include "texture/mip.h"
#include "vulkan/backend.h"
#include "vulkan/device.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>

using namespace tf;

namespace {

const Reconstruction kCubics[] = {Reconstruction::bspline, Reconstruction::catmull_rom};

double max_abs(const glm::dvec4& d) { return std::max({std::abs(d.r), std::abs(d.g), std::abs(d.b), std::abs(d.a)}); }

// A one-row-constant texture whose texel i (in x) holds p(i) = a + b·i + c·i², the same in every row.
MipChain polynomial_texture(int width, double a, double b, double c) {
    Image image = make_image(width, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < width; ++x) {
            const float value = float(a + b * x + c * double(x) * x);
            image.at(x, y) = glm::vec4(value, value, value, 1.0f);
        }
    MipChain chain;
    chain.levels.push_back(image);
    return chain;
}

SamplerOptions options_for(Filter filter, Wrap wrap, Reconstruction magnify = Reconstruction::bilinear,
                           Taps taps = Taps::manual) {
    SamplerOptions o;
    o.filter = filter;
    o.wrap = wrap;
    o.magnify = magnify;
    o.taps = taps;
    return o;
}

Filter filter_of(Reconstruction r) { return r == Reconstruction::bspline ? Filter::bspline : Filter::catmull_rom; }

// An isotropic lookup at (u, v) whose LOD on a size² texture is lambda (columns 2^lambda texels, orthogonal).
Lookup lookup_at_lod(double u, double v, double lambda, int size) {
    const double g = std::exp2(lambda) / size;
    return {u, v, g, 0.0, 0.0, g};
}

} // namespace

TEST_CASE("kernels") {
    // Partition of unity at every fraction, B-spline weights positive, Catmull-Rom interpolating; support 2.
    for (Reconstruction r : kCubics) {
        const std::string name = to_string(r);
        double unity = 0, negative = 0;
        for (int k = 0; k <= 100; ++k) {
            const double t = k / 100.0;
            double sum = 0;
            for (int i = -2; i <= 2; ++i) {
                const double w = cubic_kernel(t - i, r);
                sum += w;
                negative = std::min(negative, w);
            }
            unity = std::max(unity, std::abs(sum - 1.0));
        }
        // Five weights of magnitude < 1.2, each a cubic in double: a few ulp each.
        CHECK_LE(name + ": |sum of weights - 1| over 101 fractions", unity, 32 * 0x1p-52);
        CHECK_LE(name + ": k(2) and k(-2.5) (support |d| < 2)",
                 std::abs(cubic_kernel(2.0, r)) + std::abs(cubic_kernel(-2.5, r)), 0.0);
        if (r == Reconstruction::bspline) {
            CHECK_LE("bspline: the most negative weight (none: positive kernel)", -negative, 0.0);
            CHECK_LE("bspline: |k(0) - 2/3| and |k(1) - 1/6| (it smooths)",
                     std::abs(cubic_kernel(0, r) - 2.0 / 3) + std::abs(cubic_kernel(1, r) - 1.0 / 6), 1e-15);
        } else {
            CHECK_LE("catmull-rom: |k(0) - 1| + |k(1)| (it interpolates)",
                     std::abs(cubic_kernel(0, r) - 1.0) + std::abs(cubic_kernel(1, r)), 1e-15);
            CHECK(cubic_kernel(1.5, r) < 0.0, "catmull-rom: a negative lobe, k(1.5) = " + test::show(cubic_kernel(1.5, r)));
        }
    }
    CHECK_LE("bilinear: the tent's k(0.25) - 0.75", std::abs(cubic_kernel(0.25, Reconstruction::bilinear) - 0.75), 0.0);
}

TEST_CASE("polynomial-reproduction") {
    // Catmull-Rom reproduces quadratics (the sampled p at x - 1/2, texel centres at i + 1/2); the B-spline
    // reproduces lines and adds its variance, 1/3 texel², times p'' / 2 = c to a quadratic. Away from the edges
    // (clamp), on a 64-texel row: texels up to ~4000, so the bound is float rounding of the texels (2^-24 each).
    const int width = 64;
    const double a = 0.25, b = 1.5, c = 0.75;
    const MipChain quadratic = polynomial_texture(width, a, b, c), line = polynomial_texture(width, a, b, 0.0);
    auto p = [&](double x, double cc) { return a + b * x + cc * x * x; };
    double cr = 0, bs_line = 0, bs_quad = 0;
    for (int k = 0; k <= 200; ++k) {
        const double x = 8.0 + k * 0.2371; // texel coordinate, inside [8, 56)
        const double u = x / width, v = 0.5;
        cr = std::max(cr, std::abs(reference_cubic(quadratic, 0, u, v, Wrap::clamp, Reconstruction::catmull_rom).r -
                                   p(x - 0.5, c)));
        bs_line = std::max(bs_line, std::abs(reference_cubic(line, 0, u, v, Wrap::clamp, Reconstruction::bspline).r -
                                             p(x - 0.5, 0.0)));
        bs_quad = std::max(bs_quad, std::abs(reference_cubic(quadratic, 0, u, v, Wrap::clamp, Reconstruction::bspline).r -
                                             (p(x - 0.5, c) + c / 3.0)));
    }
    const double texel_rounding = 4.0 * 4096.0 * std::ldexp(1.0, -24); // 16 texels of |p| < 4096, weights sum ~1
    CHECK_LE("catmull-rom on a quadratic: |result - p(x - 1/2)|", cr, texel_rounding);
    CHECK_LE("bspline on a line: |result - p(x - 1/2)|", bs_line, texel_rounding);
    CHECK_LE("bspline on a quadratic: |result - (p(x - 1/2) + c/3)|", bs_quad, texel_rounding);
}

namespace {

// A tap source that answers each hardware tap with its own position (u, v, 1, 0) and counts the taps.
struct TapLog {
    int taps = 0;
};
glm::dvec4 position_tap(const void* map, int, double u, double v) {
    ++static_cast<TapLog*>(const_cast<void*>(map))->taps;
    return {u, v, 1.0, 0.0};
}

} // namespace

TEST_CASE("reference-tap-form") {
    // reference_cubic_taps, the merged taps the hardware forms read, against the texel sum they stand for:
    // (1) through a 2D texture (each tap a bilinear blend of its pair) it is reference_cubic: weights in
    // double, one product and sum per term, 16 texels of size <= 1: a few ulp. (2) Answering each tap with its
    // own position: both kernels reproduce constants and lines, so the taps' weights must sum to 1 and their
    // weighted positions to the lookup's own (x - 1/2 in texels, the centres at i + 1/2), with 4 taps for the
    // B-spline and 9 for Catmull-Rom. A tap off its pair's weighted centre or weighted wrongly fails (2).
    const int size = 16;
    MipChain chain = make_procedural("noise", size);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coord(-1.5, 2.5);
    for (Reconstruction r : kCubics) {
        double texel_sum = 0, unity = 0, moment = 0;
        int wrong_count = 0;
        for (Wrap wrap : {Wrap::repeat, Wrap::clamp, Wrap::mirror})
            for (int level : {0, 1})
                for (int k = 0; k < 200; ++k) {
                    const double u = coord(rng), v = coord(rng);
                    texel_sum = std::max(texel_sum, max_abs(reference_cubic_taps(chain, level, u, v, wrap, r) -
                                                            reference_cubic(chain, level, u, v, wrap, r)));
                    TapLog log;
                    const TexelSource positions{nullptr, &log, position_tap};
                    const glm::dvec4 p = reference_cubic_taps(chain, level, u, v, wrap, r, positions);
                    wrong_count += log.taps != (r == Reconstruction::bspline ? 4 : 9);
                    const double w = size >> level;
                    const double ur = reduce_uv(u, wrap), vr = reduce_uv(v, wrap);
                    unity = std::max(unity, std::abs(p.z - 1.0));
                    moment = std::max(moment, std::max(std::abs(p.x - ur), std::abs(p.y - vr)) * w);
                }
        const std::string name = to_string(r);
        CHECK_LE(name + ": |taps - texel sum| through a 2D texture (1200 lookups)", texel_sum, 64 * 0x1p-52);
        CHECK_LE(name + ": lookups with the wrong number of taps", wrong_count, 0.0);
        CHECK_LE(name + ": |sum of tap weights - 1|", unity, 16 * 0x1p-52);
        // Positions below 64 texels; each term rounds a few times (÷w, ×w, the product, the sum) and the
        // |weights| sum to < 1.3: 16 ulp of 64.
        CHECK_LE(name + ": |weighted tap position - lookup| in texels", moment, 16 * 64 * 0x1p-52);
    }
}

TEST_CASE("magnify-limits") {
    // --magnify swaps level 0's reconstruction: where only level 0 is read (lambda <= 0) trilinear and aniso
    // give the cubic itself, ewa the cubic's mean over four points of the footprint (the cubic itself for a
    // zero footprint); from lambda = 1 on (level 0 unread) nothing changes; just below lambda = 1 the
    // change is level 0's share (1 - lambda) times the cubic - bilinear difference: continuous.
    const int size = 64;
    const MipChain chain = make_procedural("noise", size);
    for (Reconstruction r : kCubics)
        for (Filter f : {Filter::trilinear, Filter::aniso, Filter::ewa}) {
            const std::string name = to_string(f) + " --magnify " + to_string(r);
            double at_magnification = 0, at_minification = 0, near_one = 0;
            for (int k = 0; k < 64; ++k) {
                const double u = 0.013 + k * 0.0347, v = 0.71 - k * 0.0213;
                const Lookup zoom = lookup_at_lod(u, v, -1.5 + 0.02 * k, size);
                const Lookup minify = lookup_at_lod(u, v, 1.0 + 0.05 * k, size);
                const Lookup below = lookup_at_lod(u, v, 1.0 - 1e-6, size);
                glm::dvec4 cubic = reference_cubic(chain, 0, u, v, Wrap::repeat, r);
                if (f == Filter::ewa) { // the cubic at u ± k·g·(1, ±1): J = g·I's diagonals, k² the weight's variance
                    const double k = std::sqrt(reference_ewa_weight_variance(SamplerOptions{}.alpha)) * zoom.dudx;
                    cubic = 0.25 * (reference_cubic(chain, 0, u + k, v + k, Wrap::repeat, r) +
                                    reference_cubic(chain, 0, u - k, v - k, Wrap::repeat, r) +
                                    reference_cubic(chain, 0, u + k, v - k, Wrap::repeat, r) +
                                    reference_cubic(chain, 0, u - k, v + k, Wrap::repeat, r));
                    const Lookup still{u, v, 0.0, 0.0, 0.0, 0.0}; // no footprint, no spread: the cubic itself
                    at_magnification = std::max(at_magnification,
                                                max_abs(reference_sample(chain, options_for(f, Wrap::repeat, r), still) -
                                                        reference_cubic(chain, 0, u, v, Wrap::repeat, r)));
                }
                at_magnification = std::max(
                    at_magnification, max_abs(reference_sample(chain, options_for(f, Wrap::repeat, r), zoom) - cubic));
                at_minification =
                    std::max(at_minification, max_abs(reference_sample(chain, options_for(f, Wrap::repeat, r), minify) -
                                                      reference_sample(chain, options_for(f, Wrap::repeat), minify)));
                near_one = std::max(near_one, max_abs(reference_sample(chain, options_for(f, Wrap::repeat, r), below) -
                                                      reference_sample(chain, options_for(f, Wrap::repeat), below)));
            }
            CHECK_LE(name + ": |result - cubic| at lambda <= 0", at_magnification, 1e-12);
            CHECK_LE(name + ": |result - bilinear form| at lambda >= 1", at_minification, 0.0);
            // 1e-6 of level 0's weight times a cubic-bilinear difference below 2 (texels in [0, 1)).
            CHECK_LE(name + ": |result - bilinear form| at lambda = 1 - 1e-6", near_one, 2e-6);
        }
    CHECK_THROWS_WITH(check_magnify(options_for(Filter::bilinear, Wrap::repeat, Reconstruction::bspline)),
                      "--filter bspline is that cubic alone");
    CHECK_THROWS_WITH(check_magnify(options_for(Filter::sat, Wrap::repeat, Reconstruction::catmull_rom)),
                      "applies to trilinear, aniso and ewa");
}

// ---------------------------------------------------------------- the device

namespace {

struct Gpu {
    VulkanContext context;
    Gpu() : context(create_context(test::test_context_options())) {}
    ~Gpu() {
        destroy_context(context);
        CHECK_LE("Vulkan validation messages (in-process)", double(validation_message_count()), 0.0);
    }
    std::vector<glm::dvec4> sample(const MipChain& chain, const std::vector<Lookup>& lookups,
                                   const SamplerOptions& options) {
        GpuTexture texture = upload_texture(context, chain, false);
        std::vector<glm::vec4> out;
        try {
            out = gpu_sample(context, texture, lookups, options, nullptr);
        } catch (...) {
            destroy_texture(context, texture);
            throw;
        }
        destroy_texture(context, texture);
        return {out.begin(), out.end()};
    }
};

// The largest |texel| and the largest difference of two texels in the 4x4 block a cubic lookup at uv reads.
void block_range(const Image& level, double u, double v, Wrap wrap, double& largest, double& range) {
    const auto i0 = (long long)std::floor(u * level.width - 0.5) - 1, j0 = (long long)std::floor(v * level.height - 0.5) - 1;
    glm::dvec4 lo(1e300), hi(-1e300);
    for (long long j = j0; j < j0 + 4; ++j)
        for (long long i = i0; i < i0 + 4; ++i) {
            const glm::dvec4 t(level.at(wrap_texel(i, level.width, wrap), wrap_texel(j, level.height, wrap)));
            lo = glm::min(lo, t), hi = glm::max(hi, t);
        }
    largest = std::max(max_abs(lo), max_abs(hi));
    range = max_abs(hi - lo);
}

// Sum of |weights| of one axis's hardware taps at fraction t: B-spline taps carry w0 + w1 and w2 + w3 (all
// positive: 1); Catmull-Rom's |w0|, w1 + w2, |w3|.
double tap_weight_sum(double t, Reconstruction r) {
    double sum = 0;
    for (int i = -1; i <= 2; ++i) sum += std::abs(cubic_kernel(t - i, r));
    return sum;
}

// The device, its sub-texel step, and the 64² noise texture both device cases filter.
struct DeviceCase {
    Gpu gpu;
    int bits = int(gpu.context.info.sub_texel_precision_bits);
    double step = std::ldexp(1.0, -bits);
    static constexpr int size = 64;
    MipChain chain = make_procedural("noise", size);
    DeviceCase() { std::printf("     device %s, subTexelPrecisionBits %d\n", gpu.context.info.name.c_str(), bits); }
};

// How far the device's cubic of level 0 at l may be from the reference's (bicubic.gpu-vs-reference says why):
// float rounding of the texel coordinate times the kernels' slopes, `roundings` roundings of the sum, and for
// hardware taps the sub-texel step times the taps' weight sums.
double cubic_bound(const DeviceCase& d, const Lookup& l, Wrap wrap, Reconstruction r, Taps taps, int roundings) {
    const double eps = std::ldexp(1.0, -24);
    const double u = reduce_uv(l.u, wrap), v = reduce_uv(l.v, wrap);
    double largest, range;
    block_range(d.chain.levels[0], u, v, wrap, largest, range);
    const double x = u * d.size - 0.5, y = v * d.size - 0.5;
    double bound = 4 * 2 * eps * (std::max(std::abs(x), std::abs(y)) + 0.5) * range + roundings * eps * largest;
    if (taps == Taps::hardware)
        bound += 2 * d.step * range * tap_weight_sum(x - std::floor(x), r) * tap_weight_sum(y - std::floor(y), r);
    return bound;
}

} // namespace

TEST_CASE("gpu-vs-reference") {
    // 512 random lookups a kernel and wrap mode on a 64² noise texture (uv in [-1, 2]), manual and hardware
    // taps. Manual bound: the GPU's texel coordinate x = u·w − ½ rounds twice in float (2 ulp of |x| + 1/2,
    // |x| <= 3w), which moves the weights by at most that times sum |k'| <= 2 an axis (4 for both), times the
    // block's texel range; plus 32 roundings of the weighted sum (2^-24 of the largest texel each). Hardware:
    // each bilinear tap's fraction rounds to subTexelPrecisionBits, a step s = 2^-bits an axis, moving the tap
    // by at most s times its texels' range across plus down; taps weighted by |g_x g_y|, so 2 s range times the
    // per-axis sums of |tap weights| (1 for the B-spline; Catmull-Rom's negative outer weights make it more).
    DeviceCase d;
    test::FootprintRanges ranges;
    ranges.texture_size = d.size;
    const std::vector<Lookup> lookups = test::as_float(test::random_footprint_lookups(512, 7, ranges));
    struct Form {
        Wrap wrap;
        Taps taps;
    };
    // Each wrap mode once a kernel (the 16 texels' wrap), both tap forms (a pipeline each: lavapipe compiles slowly).
    for (Reconstruction r : kCubics)
        for (Form form : {Form{Wrap::repeat, Taps::manual}, Form{Wrap::mirror, Taps::manual},
                          Form{Wrap::repeat, Taps::hardware}, Form{Wrap::clamp, Taps::hardware}}) {
                const Wrap wrap = form.wrap;
                const Taps taps = form.taps;
                const SamplerOptions o = options_for(filter_of(r), wrap, Reconstruction::bilinear, taps);
                const std::vector<glm::dvec4> got = d.gpu.sample(d.chain, lookups, o);
                double worst = 0, worst_bound = 0, ratio = 0;
                for (size_t k = 0; k < lookups.size(); ++k) {
                    const Lookup& l = lookups[k];
                    const double bound = cubic_bound(d, l, wrap, r, taps, 32);
                    const double error = max_abs(got[k] - reference_sample(d.chain, o, l));
                    const double r_k = std::isnan(error) ? INFINITY : error / bound;
                    if (r_k > ratio) ratio = r_k, worst = error, worst_bound = bound;
                }
                CHECK_LE(to_string(r) + " " + to_string(wrap) + " " + to_string(taps) +
                             ": worst |GPU - reference| / its bound (error " + test::show(worst) + ", bound " +
                             test::show(worst_bound) + ")",
                         ratio, 1.0);
            }
}

TEST_CASE("gpu-magnify") {
    // --magnify on the device: trilinear (manual: aniso's manual probes run the same level code) and aniso's
    // hardware probes (isotropic footprints: one probe) over LODs -4..3 on a 64² noise texture, and ewa (manual
    // taps for one kernel, hardware for the other) where it reads the cubic alone (LOD <= 0),
    // against the reference. Bounds: the cubic's (bicubic.gpu-vs-reference) for level 0, plus, where levels
    // blend, float rounding of the LOD (2^-20 of a level's share: log2 of a float gradient) times the two
    // levels' difference (< 2 for texels in [0, 1)); hardware probes add the sub-texel term of their taps.
    DeviceCase d;
    test::FootprintRanges ranges;
    ranges.texture_size = d.size;
    ranges.octave_min = -4.0;
    ranges.octave_max = 3.0;
    const std::vector<Lookup> lookups = test::as_float(test::random_footprint_lookups(256, 11, ranges));
    struct Form {
        Filter filter;
        Taps taps;
    };
    for (Reconstruction r : kCubics)
        for (Form form : {Form{Filter::trilinear, Taps::manual}, Form{Filter::aniso, Taps::hardware},
                          Form{Filter::ewa, r == Reconstruction::bspline ? Taps::manual : Taps::hardware}}) {
            const SamplerOptions o = options_for(form.filter, Wrap::repeat, r, form.taps);
            const std::vector<glm::dvec4> got = d.gpu.sample(d.chain, lookups, o);
            double ratio = 0;
            int compared = 0;
            for (size_t k = 0; k < lookups.size(); ++k) {
                const Lookup& l = lookups[k];
                const double share = magnified_share(d.chain, o, l);
                if (form.filter == Filter::ewa && share < 1.0) continue; // the blend with ewa: the goldens
                // Hardware probes at lod >= 1 are the device's trilinear (its mipmap rounding: hw_vs_manual).
                if (form.taps == Taps::hardware && share == 0.0) continue;
                double bound = cubic_bound(d, l, Wrap::repeat, r, form.taps, 64) + 2 * std::ldexp(1.0, -20);
                if (form.taps == Taps::hardware) bound += 2 * d.step; // the level-1 tap's (texels in [0, 1))
                const double error = max_abs(got[k] - reference_sample(d.chain, o, l));
                ratio = std::max(ratio, std::isnan(error) ? INFINITY : error / bound);
                ++compared;
            }
            CHECK(compared > 16, std::to_string(compared) + " lookups compared");
            CHECK_LE(to_string(form.filter) + " --taps " + to_string(form.taps) + " --magnify " + to_string(r) +
                         ": worst |GPU - reference| / its bound over " + std::to_string(compared) + " lookups",
                     ratio, 1.0);
        }
}
