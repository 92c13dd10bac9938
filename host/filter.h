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
};

enum class Wrap { repeat, clamp, mirror };

Filter parse_filter(const std::string& name); // throws tf::Error listing the valid names
std::string to_string(Filter filter);
const std::vector<Filter>& all_filters();
bool is_hardware(Filter filter);

Wrap parse_wrap(const std::string& name);
std::string to_string(Wrap wrap);

// Everything that selects how one lookup is filtered. Matches the GLSL side (shaders/harness/config.h).
struct SamplerOptions {
    Filter filter = Filter::trilinear;
    Wrap wrap = Wrap::repeat;
    float lod_bias = 0.0f; // added to log2(rho)
    float lod_min = 0.0f;  // clamp of the biased LOD, then clamped to [0, levels-1]
    float lod_max = 1000.0f;
    int aniso = 16;        // hw-aniso only: maxAnisotropy
};

} // namespace tf
