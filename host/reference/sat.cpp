// CPU reference of the sat and sat-assembly filters (shaders/texfilter/sat.glsl), from the definition:
// the mean of the box-reconstructed level-0 texture (texel (i, j) constant on [i, i+1) x [j, j+1)) over
// an axis-aligned box, by brute force over every texel the box touches, each weighted by its exact
// overlap, in double (no summed-area table). Wrap modes through wrap_texel.
//
// The texels are those the filter documents it averages: each channel quantised to 16 bits over its own
// range, v -> lo + round((v - lo) / s * 65535) * s / 65535 with lo the channel's smallest value and s its
// largest minus lo, rounded up to float (a constant channel stays lo). Texels must be finite: NaN or
// ±Inf anywhere in level 0 throws tf::Error, as building the table does.
//
// The box: centre (u·W, v·H), half-extents ½(|J e_x| + |J e_y|) per axis with J in level-0 texels times
// 2^lodBias (components clamped to ±2^24), the extent clamped to W x H texels (hx ≤ W/2, hy ≤ H/2);
// a zero-width axis takes the texel under the centre. Non-finite gradients: the whole texture's mean.
// sat-assembly: the parallelogram uv + J·(a, b), a, b in [−½, ½], cut along its longer column into K
// slices (K = boxes, clamped to 1..16); the mean of the K slices' bounding-box means.
#include "texture/error.h"
#include "reference/reference.h"

#include <glm/common.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace tf {

namespace {

constexpr double kMaxColumn = 16777216.0; // 2^24 texels, as the shader's clamp

// Texels covered by [x0, x1) on one axis: the first index and each texel's overlap / width.
struct Coverage {
    long long first = 0;
    std::vector<double> weights;
};

Coverage coverage(double x0, double x1) {
    Coverage c;
    c.first = (long long)std::floor(x0);
    if (!(x1 > x0)) { // zero width: the limit of the mean is the texel under x0
        c.weights = {1.0};
        return c;
    }
    const long long last = (long long)std::ceil(x1) - 1;
    for (long long t = c.first; t <= last; ++t) {
        const double overlap = std::min(x1, double(t + 1)) - std::max(x0, double(t));
        c.weights.push_back(overlap / (x1 - x0));
    }
    return c;
}

// Moves a centre by whole periods (repeat, mirror), or to where only edge texels are seen (clamp: the
// box is at most the texture's size, so from -n or 2n outward it covers nothing else). The mean is
// unchanged; the loops stay short for any finite uv.
double reduce_centre(double x, int n, Wrap wrap) {
    const double size = n;
    switch (wrap) {
    case Wrap::repeat:
        return x - size * std::floor(x / size);
    case Wrap::mirror:
        return x - 2.0 * size * std::floor(x / (2.0 * size));
    case Wrap::clamp:
        return std::clamp(x, -size, 2.0 * size);
    }
    throw Error("reference_sat: invalid wrap mode");
}

// The documented 16-bit levels of each channel: value = lo + q * step, q = round((v - lo) / span * 65535).
struct Levels {
    glm::dvec4 lo{0.0}, span{0.0};
    glm::dvec4 operator()(const glm::vec4& texel) const {
        glm::dvec4 out;
        for (int c = 0; c < 4; ++c) {
            if (span[c] == 0.0) {
                out[c] = lo[c];
                continue;
            }
            const double q = std::clamp(std::round((double(texel[c]) - lo[c]) / span[c] * 65535.0), 0.0, 65535.0);
            out[c] = lo[c] + q * (span[c] / 65535.0);
        }
        return out;
    }
};

Levels channel_levels(const Image& image) {
    glm::dvec4 lo(INFINITY), hi(-INFINITY);
    for (int j = 0; j < image.height; ++j)
        for (int i = 0; i < image.width; ++i) {
            const glm::vec4& t = image.at(i, j);
            for (int c = 0; c < 4; ++c) {
                const double v = t[c];
                if (!std::isfinite(v))
                    throw Error("reference_sat: texel (" + std::to_string(i) + ", " + std::to_string(j) + ") is " +
                                (std::isnan(v) ? "NaN" : v > 0 ? "+Inf" : "-Inf") + ": sat needs finite texels");
                lo[c] = std::min(lo[c], v);
                hi[c] = std::max(hi[c], v);
            }
        }
    Levels levels;
    levels.lo = lo;
    for (int c = 0; c < 4; ++c) { // the span as the smallest float at least hi - lo
        const double d = hi[c] - lo[c];
        float f = float(d);
        if (double(f) < d)
            f = std::nextafter(f, INFINITY);
        if (std::isinf(f))
            throw Error("reference_sat: channel " + std::to_string(c) + " spans more than a float holds");
        levels.span[c] = f;
    }
    return levels;
}

// Mean of the texture over the box centred at (cx, cy) (texel units) with half-extents (hx, hy).
glm::dvec4 box_mean(const Image& image, const Levels& levels, double cx, double cy, double hx, double hy, Wrap wrap) {
    hx = std::min(hx, 0.5 * image.width);
    hy = std::min(hy, 0.5 * image.height);
    cx = reduce_centre(cx, image.width, wrap);
    cy = reduce_centre(cy, image.height, wrap);
    const Coverage x = coverage(cx - hx, cx + hx), y = coverage(cy - hy, cy + hy);
    std::vector<int> columns(x.weights.size());
    for (size_t a = 0; a < columns.size(); ++a)
        columns[a] = wrap_texel(x.first + (long long)a, image.width, wrap);
    glm::dvec4 sum(0.0);
    for (size_t b = 0; b < y.weights.size(); ++b) {
        const int row = wrap_texel(y.first + (long long)b, image.height, wrap);
        glm::dvec4 line(0.0);
        for (size_t a = 0; a < columns.size(); ++a)
            line += x.weights[a] * levels(image.at(columns[a], row));
        sum += y.weights[b] * line;
    }
    return sum;
}

} // namespace

SatLevels reference_sat_levels(const Image& level0) {
    const Levels levels = channel_levels(level0);
    return {levels.lo, levels.span};
}

glm::dvec4 reference_sat(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup,
                         const SatLevels& sat) {
    if (chain.levels.empty()) throw Error("reference_sat: empty MIP chain");
    const Image& image = chain.levels[0];
    const double w = image.width, h = image.height;
    Levels levels;
    levels.lo = sat.lo;
    levels.span = sat.span;
    if (!finite_footprint(chain, lookup)) // NaN, Inf, or past float range as the shader's float input holds it
        return box_mean(image, levels, 0.5 * w, 0.5 * h, 0.5 * w, 0.5 * h, Wrap::repeat); // the whole texture
    const double m = std::exp2(double(options.lod_bias));
    auto column = [&](double du, double dv) {
        return glm::dvec2(std::clamp(du * w * m, -kMaxColumn, kMaxColumn), std::clamp(dv * h * m, -kMaxColumn, kMaxColumn));
    };
    const glm::dvec2 jx = column(lookup.dudx, lookup.dvdx), jy = column(lookup.dudy, lookup.dvdy);
    const glm::dvec2 centre(lookup.u * w, lookup.v * h);

    if (options.filter != Filter::sat_assembly) {
        const glm::dvec2 half = 0.5 * (glm::abs(jx) + glm::abs(jy));
        return box_mean(image, levels, centre.x, centre.y, half.x, half.y, options.wrap);
    }
    const int k = std::clamp(options.boxes, 1, 16);
    const bool x_major = jx.x * jx.x + jx.y * jx.y >= jy.x * jy.x + jy.y * jy.y;
    const glm::dvec2 major = x_major ? jx : jy, minor = x_major ? jy : jx;
    // Slice s covers a in [-1/2 + s/K, -1/2 + (s+1)/K): centre at a_s, its own parallelogram J/K by J.
    const glm::dvec2 half = 0.5 * (glm::abs(major) / double(k) + glm::abs(minor));
    glm::dvec4 sum(0.0);
    for (int s = 0; s < k; ++s) {
        const double a = (s + 0.5) / k - 0.5;
        const glm::dvec2 c = centre + a * major;
        sum += box_mean(image, levels, c.x, c.y, half.x, half.y, options.wrap);
    }
    return sum / double(k);
}

} // namespace tf
