#pragma once
// Filter and wrap-mode names: one enum each, with parse and to-string (the CLI's vocabulary).
#include <string>
#include <vector>

namespace tf {

enum class Filter {
    nearest,      // level 0 only
    bilinear,     // level 0 only
    trilinear,    // two levels blended by frac(lambda)
    nearest_mip,  // one level chosen by LOD (Vulkan mipmapMode NEAREST), nearest texel
    bilinear_mip, // one level chosen by LOD, bilinear
    hw_nearest,   // hardware sampler via textureGrad, level 0 only
    hw_bilinear,
    hw_trilinear,
    hw_aniso,     // hardware anisotropic, maxAnisotropy = --aniso
    brilinear,    // trilinear only in a band around level transitions (--band)
    aniso,        // N trilinear probes along the major axis (--probes, --aniso-shape, --taps)
    ewa,          // elliptical weighted average, Gaussian (--alpha, --max-aniso, --taps)
    sat,          // summed-area table: box over the footprint's bounding box
    sat_assembly, // summed-area table: K boxes along the major axis (--boxes)
    // Scene-level, not lookup filters (render only):
    ground_truth, // the pixel's integral of the level-0 bilinear texture under a pixel filter (--spp)
    none,         // no texture at all: fract(uv) as colour, the benchmark's baseline cost
};

enum class Wrap { repeat, clamp, mirror };

// ground-truth: the pixel filter it integrates under, a box over the pixel or a Gaussian (sigma 0.5 px).
enum class PixelFilter { box, gaussian };

// aniso: where probes go and how they are weighted (see shaders/texfilter/aniso.glsl).
enum class AnisoShape { gpu, feline };
// Multi-tap filters: taps from texelFetch (exact everywhere) or hardware bilinear/trilinear lookups.
enum class Taps { manual, hardware };

Filter parse_filter(const std::string& name); // throws tf::Error listing the valid names
std::string to_string(Filter filter);
const std::vector<Filter>& all_filters(); // the lookup filters: every filter but ground-truth and none
bool is_hardware(Filter filter);
bool is_scene_level(Filter filter); // ground-truth, none: they need a scene, not one uv lookup

Wrap parse_wrap(const std::string& name);
std::string to_string(Wrap wrap);
AnisoShape parse_aniso_shape(const std::string& name);
std::string to_string(AnisoShape shape);
Taps parse_taps(const std::string& name);
std::string to_string(Taps taps);
PixelFilter parse_pixel_filter(const std::string& name);
std::string to_string(PixelFilter filter);

// ground-truth: the Gaussian pixel filter's standard deviation in pixels, and the largest sample grid side
// (samples per pixel = side^2, so at most 4096).
constexpr double ground_truth_sigma = 0.5;
constexpr int max_ground_truth_side = 64;

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
    Taps taps = Taps::manual; // aniso, ewa
    float alpha = 2.0f;    // ewa: Gaussian exp(-alpha r^2)
    float max_aniso = 16.0f; // ewa: eccentricity clamp (minor axis grown to major / max_aniso)
    int boxes = 4;         // sat-assembly: boxes along the major axis, 1..16
    PixelFilter pixel_filter = PixelFilter::box; // ground-truth
    int truth_side = 16;   // ground-truth: a side x side stratified grid of samples a pixel (256 spp)
};

} // namespace tf
