// texfilter/debug.glsl — debug views for your own renderer: the LOD a filter samples at as colour, the
// footprint's anisotropy, a heat map (e.g. texel fetches per pixel), and the footprint ellipse and aniso
// probe positions of a lookup, for drawing over the image.
//
// Use:     vec3  tf_debug_lod_color(float lod);          // the mipcolors palette, blended by fract(lod)
//          float tf_debug_anisotropy(vec2 dUVdx, vec2 dUVdy, vec2 textureSize); // major/minor axis ratio
//          vec3  tf_debug_anisotropy_color(float ratio);  // 1: neutral grey .. 16 and more: saturated red
//          vec3  tf_debug_heat(float value, float maxValue); // 0 black, blue, red, yellow, max white
//          tf_Footprint tf_debug_footprint(vec2 uv, vec2 dUVdx, vec2 dUVdy, vec2 textureSize, int levels,
//                                          tf_Sampler s, int family, int maxProbes, int shape, float maxAniso);
//          int   tf_debug_aniso_probe_count(vec2 dUVdx, vec2 dUVdy, vec2 textureSize, int maxProbes, int shape);
//          vec2  tf_debug_aniso_probe(vec2 uv, vec2 dUVdx, vec2 dUVdy, vec2 textureSize, int maxProbes,
//                                     int shape, int k); // uv of tf_aniso's probe k, k in [0, count)
//          They take sizes, not textures: one form serves every resource kind and texel source.
// Math:    tf_Footprint, in level-0 texels: `center` = uv·textureSize; `major`, `minor` the half-axes of the
//          ellipse the family integrates (after its clamps); `lod` the LOD it samples at (biased, clamped);
//          `ratio` the pixel's own anisotropy (before any clamp). Palettes: all linear RGB, piecewise linear
//          between the stops (details below).
// Options: family TF_DEBUG_ISOTROPIC (trilinear, brilinear, the *_mip filters, sat, hardware sampling: the
//          Vulkan LOD, clamped as tf_lod), TF_DEBUG_ANISO (tf_aniso's LOD, with maxProbes and shape),
//          TF_DEBUG_EWA (tf_ewa's LOD, with maxAniso). s: lodBias, lodMin, lodMax as every filter; levels: the
//          texture's level count (textureQueryLevels). No defines.
// Needs:   nothing bound (no texture is read; nothing is declared).
// Cost:    a few dozen ALU operations each, no texel fetch.
// Degenerate input: tf_debug_anisotropy gives 1 for zero gradients and for NaN or ±Inf in them (or a footprint
//          past float range) and +Inf for a footprint of zero area with a non-zero axis. The colour functions
//          map NaN to their first stop (level 0's colour, grey, black), lod below 0 to level 0, +Inf to their
//          last stop (lod: modulo 12 up to level 4096). tf_debug_footprint follows the family's LOD rules: zero
//          gradients the finest level allowed, non-finite ones the coarsest, with a circle of the level's texel.
// Example: float ratio = tf_debug_anisotropy(dFdxFine(uv), dFdyFine(uv), vec2(textureSize(tex, 0)));
//          outColor = vec4(tf_debug_anisotropy_color(ratio), 1.0);
#ifndef TF_DEBUG_GLSL
#define TF_DEBUG_GLSL

// Palettes (docs/API.md): LOD: level l is the colour of the procedural `mipcolors` texture's level l (twelve
// hues 30 degrees apart, red, orange, yellow, ... repeating every 12 levels), mixed linearly with level l+1's by
// fract(lod), as trilinear over mipcolors would show it. Anisotropy: t = log2(ratio)/4 (equal steps for each
// doubling, as the eye judges ratios: 1, 2, 4, 8, 16) through grey (0.2), blue, green, yellow, red. Heat:
// t = value/maxValue through black, blue, red, yellow, white at t = 0, ¼, ½, ¾, 1.
// Footprint: `major` and `minor` are vectors: for EWA the pixel's pre-image J·(disk of radius ½) (minor axis
// grown to major/maxAniso); for aniso the probes' line (½ of the major axis the probes span) by ½·2^lod across
// it; for the isotropic family a circle of radius ½·2^lod (the level's texel), so LOD clamps show; `lod`
// clamped to [lodMin, lodMax] and [0, levels−1]; `ratio` is tf_debug_anisotropy (|major|/|minor| is the
// filter's own).

#include "aniso.glsl"
#include "ewa.glsl"

#define TF_DEBUG_ISOTROPIC 0
#define TF_DEBUG_ANISO 1
#define TF_DEBUG_EWA 2

struct tf_Footprint {
    vec2 center; // uv · textureSize: level-0 texels
    vec2 major;  // half-axes of the ellipse the filter integrates (level-0 texels), |major| >= |minor|
    vec2 minor;
    float lod;   // the LOD the filter samples at
    float ratio; // tf_debug_anisotropy: the pixel's footprint, before the filter's clamps
};

// The mipcolors texture's level colours (host/core/procedural.cpp), linear RGB, level l % 12.
const vec3 TFI_DEBUG_MIP_COLORS[12] = vec3[12](
    vec3(1.0, 0.0, 0.0), vec3(1.0, 0.5, 0.0), vec3(1.0, 1.0, 0.0), vec3(0.5, 1.0, 0.0), vec3(0.0, 1.0, 0.0),
    vec3(0.0, 1.0, 0.5), vec3(0.0, 1.0, 1.0), vec3(0.0, 0.5, 1.0), vec3(0.0, 0.0, 1.0), vec3(0.5, 0.0, 1.0),
    vec3(1.0, 0.0, 1.0), vec3(1.0, 0.0, 0.5));
const vec3 TFI_DEBUG_ANISO_COLORS[5] = vec3[5](vec3(0.2, 0.2, 0.2), vec3(0.05, 0.25, 1.0), vec3(0.05, 0.8, 0.2),
                                               vec3(1.0, 0.85, 0.05), vec3(1.0, 0.05, 0.05));
const vec3 TFI_DEBUG_HEAT_COLORS[5] = vec3[5](vec3(0.0, 0.0, 0.0), vec3(0.1, 0.1, 0.9), vec3(0.9, 0.1, 0.3),
                                              vec3(1.0, 0.8, 0.0), vec3(1.0, 1.0, 1.0));
const float TFI_DEBUG_MAX_LEVEL = 4096.0; // no texture has more levels; keeps int(lod) defined

vec3 tf_debug_lod_color(float lod)
{
    float d = isnan(lod) ? 0.0 : clamp(lod, 0.0, TFI_DEBUG_MAX_LEVEL);
    float lo = floor(d);
    int i = int(lo) % 12;
    return mix(TFI_DEBUG_MIP_COLORS[i], TFI_DEBUG_MIP_COLORS[(i + 1) % 12], d - lo);
}

// Five stops at t = 0, ¼, ½, ¾, 1; t is not NaN.
vec3 tfi_debug_ramp(const vec3 stops[5], float t)
{
    float x = 4.0 * clamp(t, 0.0, 1.0);
    int i = min(int(x), 3);
    return mix(stops[i], stops[i + 1], x - float(i));
}

vec3 tf_debug_anisotropy_color(float ratio)
{
    return tfi_debug_ramp(TFI_DEBUG_ANISO_COLORS, ratio > 1.0 ? 0.25 * log2(ratio) : 0.0); // NaN: grey
}

vec3 tf_debug_heat(float value, float maxValue)
{
    float t = value / maxValue;
    return tfi_debug_ramp(TFI_DEBUG_HEAT_COLORS, isnan(t) ? 0.0 : t);
}

// J = [dUVdx dUVdy]·diag(size) scaled by 2^-e so that its largest entry is in [½, 1) (exact, no overflow
// below); false (e = 0) for zero or non-finite gradients, or entries past float range.
bool tfi_debug_scaled_columns(vec2 dUVdx, vec2 dUVdy, vec2 textureSize, out vec2 cx, out vec2 cy, out int e)
{
    vec2 ax = dUVdx * textureSize, ay = dUVdy * textureSize;
    float m = max(max(abs(ax.x), abs(ax.y)), max(abs(ay.x), abs(ay.y)));
    e = 0;
    cx = vec2(0.0);
    cy = vec2(0.0);
    if (!(m > 0.0) || isinf(m) || !tf_finite(dUVdx) || !tf_finite(dUVdy))
        return false;
    frexp(m, e);
    cx = ldexp(ax, ivec2(-e));
    cy = ldexp(ay, ivec2(-e));
    return true;
}

// The major axis direction of J·Jᵀ = [xx xy; xy yy] (unit vector), from the better-conditioned of its two
// eigenvector formulas; (1, 0) for a circle.
vec2 tfi_debug_major_direction(float xx, float xy, float yy)
{
    float h = 0.5 * (xx - yy), d = length(vec2(h, xy));
    if (!(d > 0.0))
        return vec2(1.0, 0.0);
    return normalize(h >= 0.0 ? vec2(h + d, xy) : vec2(xy, d - h));
}

float tf_debug_anisotropy(vec2 dUVdx, vec2 dUVdy, vec2 textureSize)
{
    vec2 cx, cy;
    int e;
    if (!tfi_debug_scaled_columns(dUVdx, dUVdy, textureSize, cx, cy, e))
        return 1.0;
    // σ1/σ2 = σ1²/|det J|: σ1² the largest eigenvalue of J·Jᵀ, no cancellation but det's own.
    float xx = cx.x * cx.x + cy.x * cy.x, xy = cx.x * cx.y + cy.x * cy.y, yy = cx.y * cx.y + cy.y * cy.y;
    float major2 = 0.5 * (xx + yy) + length(vec2(0.5 * (xx - yy), xy));
    return major2 / abs(cx.x * cy.y - cx.y * cy.x); // det 0: +Inf
}

// tf_aniso's probes (aniso.glsl, tfi_aniso_footprint): the same float operations on the same inputs, so
// the same count, axis and LOD; with the level count given instead of the sampler.
struct tfi_DebugProbes {
    vec2 axis;  // the whole major axis in uv (zero for one probe)
    int probes;
    float lod;
};

tfi_DebugProbes tfi_debug_aniso(vec2 dUVdx, vec2 dUVdy, vec2 textureSize, int levels, tf_Sampler s, int maxProbes,
                                int shape)
{
    int maxN = clamp(maxProbes, 1, TF_ANISO_MAX_PROBES);
    tfi_DebugProbes p = tfi_DebugProbes(vec2(0.0), 1, 0.0);
    vec2 ax = dUVdx * textureSize, ay = dUVdy * textureSize;
    vec2 cx, cy;
    int e;
    if (!tfi_debug_scaled_columns(dUVdx, dUVdy, textureSize, cx, cy, e)) {
        bool zero = tf_finite(dUVdx) && tf_finite(dUVdy) && all(equal(ax, vec2(0.0))) && all(equal(ay, vec2(0.0)));
        p.lod = tfi_clamp_lod_levels(zero ? -1.0 / 0.0 : 1.0 / 0.0, s, levels);
        return p;
    }
    if (shape != TF_ANISO_FELINE) {
        float px2 = dot(cx, cx), py2 = dot(cy, cy);
        p.probes = tfi_aniso_count(sqrt(max(px2, py2) / min(px2, py2)), maxN);
        float bias = s.lodBias;
        if (p.probes > 1) {
            bias -= tfi_log2(float(p.probes));
            p.axis = px2 >= py2 ? dUVdx : dUVdy;
        }
        float rho2 = max(dot(ax, ax), dot(ay, ay)); // tf_lod_unclamped's
        p.lod = tfi_clamp_lod_levels(tfi_log2_rho(rho2) + bias, s, levels);
        return p;
    }
    float E = 0.5 * (cx.x + cy.y), F = 0.5 * (cx.x - cy.y);
    float G = 0.5 * (cx.y + cy.x), H = 0.5 * (cx.y - cy.x);
    float Q = length(vec2(E, H)), R = length(vec2(F, G));
    float major = Q + R, minor = abs(Q - R);
    p.probes = tfi_aniso_count(major / minor, maxN);
    p.lod = tfi_clamp_lod_levels(float(e) + tfi_log2(max(minor, major / float(p.probes))) + s.lodBias, s, levels);
    if (p.probes > 1) {
        vec2 z = vec2(F * E - G * H, F * H + G * E);
        float r = length(z);
        vec2 u1 = normalize(z.x >= 0.0 ? vec2(r + z.x, z.y) : vec2(z.y, r - z.x));
        p.axis = ldexp(major * u1 / textureSize, ivec2(e));
    }
    return p;
}

int tf_debug_aniso_probe_count(vec2 dUVdx, vec2 dUVdy, vec2 textureSize, int maxProbes, int shape)
{
    return tfi_debug_aniso(dUVdx, dUVdy, textureSize, 1, tf_sampler(TF_WRAP_REPEAT), maxProbes, shape).probes;
}

vec2 tf_debug_aniso_probe(vec2 uv, vec2 dUVdx, vec2 dUVdy, vec2 textureSize, int maxProbes, int shape, int k)
{
    tfi_DebugProbes p = tfi_debug_aniso(dUVdx, dUVdy, textureSize, 1, tf_sampler(TF_WRAP_REPEAT), maxProbes, shape);
    return uv + ((float(k) + 0.5) / float(p.probes) - 0.5) * p.axis;
}

// tf_ewa's LOD and clamped ellipse (ewa.glsl, tfi_ewa_shape): its float operations, its rules.
float tfi_debug_ewa(vec2 dUVdx, vec2 dUVdy, vec2 textureSize, int levels, tf_Sampler s, float maxAniso,
                    out vec2 major, out vec2 minor)
{
    major = vec2(0.0);
    minor = vec2(0.0);
    float lambda;
    if (!tf_finite(dUVdx * textureSize) || !tf_finite(dUVdy * textureSize)) {
        lambda = 1e30;
    } else {
        vec2 g = max(abs(dUVdx), abs(dUVdy));
        float m = max(g.x, g.y);
        if (!(m > 1e-30)) {
            lambda = -1e30;
        } else {
            vec2 ax = dUVdx / m * textureSize, ay = dUVdy / m * textureSize;
            float xx = ax.x * ax.x + ay.x * ay.x, xy = ax.x * ax.y + ay.x * ay.y, yy = ax.y * ax.y + ay.y * ay.y;
            float h = 0.5 * (xx - yy);
            float d = sqrt(h * h + xy * xy);
            float major2 = 0.5 * (xx + yy) + d;
            float cross = ax.x * ay.y - ax.y * ay.x;
            float minor2 = cross * cross / major2;
            float e = maxAniso >= 1.0 ? maxAniso : 1.0;
            minor2 = max(minor2, major2 / (e * e));
            const float majorTexels = 0.25 * float(TF_EWA_MAX_TEXELS - 3) / sqrt(TF_EWA_SUPPORT);
            lambda = tfi_log2(m) +
                     max(0.5 * log2(max(minor2, 1e-30)) - 0.5, 0.5 * log2(major2) - log2(majorTexels)) + s.lodBias;
            vec2 u1 = tfi_debug_major_direction(xx, xy, yy);
            major = 0.5 * m * sqrt(major2) * u1; // the pre-image J·(disk of radius ½), in texels
            minor = 0.5 * m * sqrt(minor2) * vec2(-u1.y, u1.x);
        }
    }
    return tfi_clamp_lod_levels(lambda, s, levels);
}

tf_Footprint tf_debug_footprint(vec2 uv, vec2 dUVdx, vec2 dUVdy, vec2 textureSize, int levels, tf_Sampler s,
                                int family, int maxProbes, int shape, float maxAniso)
{
    tf_Footprint f;
    f.center = uv * textureSize;
    f.ratio = tf_debug_anisotropy(dUVdx, dUVdy, textureSize);
    vec2 ax = dUVdx * textureSize, ay = dUVdy * textureSize;
    bool finite = tf_finite(ax) && tf_finite(ay);
    float xx = ax.x * ax.x + ay.x * ay.x, xy = ax.x * ax.y + ay.x * ay.y, yy = ax.y * ax.y + ay.y * ay.y;
    vec2 u1 = finite ? tfi_debug_major_direction(xx, xy, yy) : vec2(1.0, 0.0);
    vec2 line = vec2(0.0); // aniso: the probes' whole axis in texels
    if (family == TF_DEBUG_EWA) {
        f.lod = tfi_debug_ewa(dUVdx, dUVdy, textureSize, levels, s, maxAniso, f.major, f.minor);
        if (f.major != vec2(0.0))
            return f;
    } else if (family == TF_DEBUG_ANISO) {
        tfi_DebugProbes p = tfi_debug_aniso(dUVdx, dUVdy, textureSize, levels, s, maxProbes, shape);
        f.lod = p.lod;
        line = p.axis * textureSize;
    } else {
        // tf_lod's: non-finite gradients +Inf, zero ones -Inf.
        f.lod = tfi_clamp_lod_levels(finite ? tfi_log2_rho(max(dot(ax, ax), dot(ay, ay))) + s.lodBias : 1.0 / 0.0, s,
                                    levels);
    }
    float texel = 0.5 * exp2(f.lod); // half the sampled level's texel, in level-0 texels
    vec2 along = line != vec2(0.0) ? normalize(line) : u1;
    f.major = max(0.5 * length(line), texel) * along;
    f.minor = texel * vec2(-along.y, along.x);
    return f;
}

#endif
