#pragma once
// Filter and wrap-mode names: one enum each, with parse and to-string (the CLI's vocabulary). The values
// are the ids the harness shaders compare with (shaders/harness/config.h; checked in
// scene/shader_interface.h), so the order here is free.
#include "harness/config.h"
#include "core/stochastic_noise.h"
#include <string>
#include <vector>

namespace tf {

enum class Filter {
    nearest = HARNESS_FILTER_NEAREST,         // level 0 only
    bilinear = HARNESS_FILTER_BILINEAR,       // level 0 only
    trilinear = HARNESS_FILTER_TRILINEAR,     // two levels blended by frac(lambda)
    nearest_mip = HARNESS_FILTER_NEAREST_MIP, // one level chosen by LOD (Vulkan mipmapMode NEAREST), nearest texel
    bilinear_mip = HARNESS_FILTER_BILINEAR_MIP, // one level chosen by LOD, bilinear
    hw_nearest = HARNESS_FILTER_HW_NEAREST,     // hardware sampler via textureGrad, level 0 only
    hw_bilinear = HARNESS_FILTER_HW_BILINEAR,
    hw_trilinear = HARNESS_FILTER_HW_TRILINEAR,
    hw_aniso = HARNESS_FILTER_HW_ANISO,   // hardware anisotropic, maxAnisotropy = --aniso
    brilinear = HARNESS_FILTER_BRILINEAR, // trilinear only in a band around level transitions (--band)
    aniso = HARNESS_FILTER_ANISO,         // N trilinear probes along the major axis (--probes, --aniso-shape, --taps)
    ewa = HARNESS_FILTER_EWA,             // elliptical weighted average, Gaussian (--alpha, --max-aniso, --taps)
    sat = HARNESS_FILTER_SAT,             // summed-area table: box over the footprint's bounding box
    sat_assembly = HARNESS_FILTER_SAT_ASSEMBLY, // summed-area table: K boxes along the major axis (--boxes)
    bspline = HARNESS_FILTER_BSPLINE,         // level 0, cubic B-spline (--taps: 16 fetches or 4 bilinear taps)
    catmull_rom = HARNESS_FILTER_CATMULL_ROM, // level 0, Catmull-Rom (--taps: 16 fetches or 9 bilinear taps)
    ewa_fast = HARNESS_FILTER_EWA_FAST,       // the pixel's Gaussian from at most 9 hardware trilinear lookups
    // Scene-level, not lookup filters (render only):
    ground_truth = HARNESS_FILTER_GROUND_TRUTH, // the pixel's integral of the level-0 bilinear texture (--spp)
    none = HARNESS_FILTER_NONE, // no texture at all: fract(uv) as colour, the benchmark's baseline cost
};

enum class Wrap { repeat = HARNESS_WRAP_REPEAT, clamp = HARNESS_WRAP_CLAMP, mirror = HARNESS_WRAP_MIRROR };

// ground-truth: the pixel filter it integrates under, a box over the pixel or a Gaussian (sigma 0.5 px).
enum class PixelFilter { box = HARNESS_PIXEL_FILTER_BOX, gaussian = HARNESS_PIXEL_FILTER_GAUSSIAN };
// ground-truth --truth: integrate level 0's texels reconstructed bilinearly (texels, the default) or the
// procedural texture's analytic definition (analytic; core/analytic_texture.h, which parses the names).
enum class Truth { texels, analytic };
// The procedural textures with an analytic definition (core/analytic_texture.h); none: integrate the texels.
enum class AnalyticKind {
    none = HARNESS_ANALYTIC_NONE,
    checker = HARNESS_ANALYTIC_CHECKER,
    zoneplate = HARNESS_ANALYTIC_ZONEPLATE,
    grid = HARNESS_ANALYTIC_GRID,
};

// aniso: where probes go and how they are weighted (see shaders/texfilter/aniso.glsl).
enum class AnisoShape { gpu = HARNESS_ANISO_GPU, feline = HARNESS_ANISO_FELINE };
// Multi-tap filters: taps from texelFetch (exact everywhere) or hardware bilinear/trilinear lookups.
enum class Taps { manual = HARNESS_TAPS_MANUAL, hardware = HARNESS_TAPS_HARDWARE };
// How one level is reconstructed from its texels (shaders/texfilter/bicubic.glsl): trilinear, aniso and ewa
// use it on level 0 (--magnify), where they magnify; bspline and catmull-rom are the cubics alone.
enum class Reconstruction {
    bilinear = HARNESS_RECONSTRUCT_BILINEAR,
    bspline = HARNESS_RECONSTRUCT_BSPLINE,
    catmull_rom = HARNESS_RECONSTRUCT_CATMULL_ROM
};

Filter parse_filter(const std::string& name); // throws tf::Error listing the valid names
std::string to_string(Filter filter);
const std::vector<Filter>& all_filters(); // the lookup filters: every filter but ground-truth and none
bool is_hardware(Filter filter);
bool is_scene_level(Filter filter); // ground-truth, none: they need a scene, not one uv lookup
bool takes_taps(Filter filter);      // --taps applies: aniso, ewa, bspline, catmull-rom
bool takes_magnify(Filter filter);   // --magnify applies: trilinear, aniso, ewa

// The sampler flags each filter reads: one table (filter.cpp), taken from what the harness
// (shaders/harness/filter_select.glsl, env_select.glsl, the hardware sampler's state) and the CPU reference
// really read, so that every command refuses a flag its filter would ignore (flags/cli_common.h).
// `stochastic`: the one-texel forms (--stochastic), whose bilinear and trilinear read --taps as well.
// Not in it: --filter itself, --backend, and --accumulate (it needs --stochastic: check_stochastic).
const std::vector<std::string>& sampler_flag_names(); // "--wrap", "--aniso", ... in --help's order
bool filter_reads(Filter filter, const std::string& flag, bool stochastic);
// The filters that read `flag`, for messages: "aniso", "trilinear, aniso and ewa".
std::string filters_reading(const std::string& flag);
bool is_lod_flag(const std::string& flag); // --lod-bias, --lod-min, --lod-max

Wrap parse_wrap(const std::string& name);
std::string to_string(Wrap wrap);
AnisoShape parse_aniso_shape(const std::string& name);
std::string to_string(AnisoShape shape);
Taps parse_taps(const std::string& name);
std::string to_string(Taps taps);
Reconstruction parse_reconstruction(const std::string& name);
std::string to_string(Reconstruction reconstruction);
PixelFilter parse_pixel_filter(const std::string& name);
std::string to_string(PixelFilter filter);

// ground-truth: the Gaussian pixel filter's standard deviation in pixels, and the largest sample grid side
// (samples per pixel = side^2, so at most 4096).
constexpr double ground_truth_sigma = HARNESS_GROUND_TRUTH_SIGMA;
constexpr int max_ground_truth_side = HARNESS_MAX_TRUTH_SIDE;

// Everything that selects how one lookup is filtered. Matches the GLSL side (shaders/harness/config.h).
struct SamplerOptions {
    Filter filter = Filter::trilinear;
    Wrap wrap = Wrap::repeat;
    float lod_bias = 0.0f; // added to log2(rho)
    float lod_min = 0.0f;  // clamp of the biased LOD, then clamped to [0, levels-1]
    float lod_max = 1000.0f;
    int aniso = 16;        // hw-aniso only: maxAnisotropy
    float band = 0.25f;    // brilinear: width of the trilinear band around each transition, 0..1
    int probes = 16;       // aniso: maximum number of probes, 1..16
    AnisoShape aniso_shape = AnisoShape::gpu;
    Taps taps = Taps::manual; // aniso, ewa, bspline, catmull-rom
    Reconstruction magnify = Reconstruction::bilinear; // trilinear, aniso, ewa: level 0's reconstruction
    float alpha = 2.0f;    // ewa: Gaussian exp(-alpha r^2)
    float max_aniso = 16.0f; // ewa: eccentricity clamp (minor axis grown to major / max_aniso)
    int boxes = 4;         // sat-assembly: boxes along the major axis, 1..16
    PixelFilter pixel_filter = PixelFilter::box; // ground-truth
    int truth_side = 16;   // ground-truth: a side x side stratified grid of samples a pixel (256 spp)
    // ground-truth: only samples [truth_first, truth_first + truth_count) of the grid, their mean (the
    // viewer accumulates the truth a range a frame); truth_count 0 = every sample from truth_first on.
    int truth_first = 0;
    int truth_count = 0;
    // ground-truth: what it integrates (--truth), and with Truth::analytic the function: set from the
    // texture's name by resolve_analytic_truth (core/analytic_texture.h); the size is level 0's width.
    Truth truth = Truth::texels;
    AnalyticKind analytic = AnalyticKind::none;
    // --stochastic (bilinear, trilinear, aniso, ewa): the one-texel forms of shaders/texfilter/stochastic.glsl
    // with `noise`'s random numbers (core/stochastic_noise.h); a render is the mean of `accumulate` frames,
    // frames stochastic_first .. stochastic_first + accumulate - 1, each with its own numbers.
    bool stochastic = false;
    Noise noise = Noise::white;
    int accumulate = 1; // 1..HARNESS_MAX_ACCUMULATE
    uint32_t stochastic_first = 0;
};

// The ground truth's sample range of `options`, resolved: count 0 becomes the rest of the grid. Throws
// tf::Error naming truth_first/truth_count and the grid when the range is empty or runs past it.
struct TruthRange {
    int first = 0;
    int count = 0;
};
TruthRange truth_range(const SamplerOptions& options);

// The lookup goes through the bound sampler's filtering: the hw-* filters, --taps hardware, and ewa-fast
// (hardware trilinear lookups only).
bool uses_hardware_lookups(const SamplerOptions& options);

// Throws tf::Error naming the filter when options.magnify is not bilinear on a filter that does not take it.
void check_magnify(const SamplerOptions& options);

bool takes_stochastic(Filter filter); // --stochastic applies: bilinear, trilinear, aniso, ewa
Noise parse_noise(const std::string& name); // white | blue
std::string to_string(Noise noise);
// Throws tf::Error naming what is wrong: --stochastic on another filter or with --magnify, accumulate outside
// 1..HARNESS_MAX_ACCUMULATE, accumulate > 1 without --stochastic.
void check_stochastic(const SamplerOptions& options);
// The push constant of frame `frame` (shaders/harness/stochastic_noise.glsl): frame * 4 + the noise id; 0 off.
int32_t stochastic_push(const SamplerOptions& options, uint32_t frame);

} // namespace tf
