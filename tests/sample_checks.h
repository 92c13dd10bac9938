#pragma once
// `texfilter sample` on the device against the CPU reference, lookup by lookup within a bound derived from
// the math (sample_checks.cpp says how): the checks tests/test_resource_kinds.cpp runs on every resource kind
// and tests/test_slang.cpp on the harness shader compiled by slangc (sample --spirv).
//
// Use: Case c = make_case(Resource::combined, Filter::trilinear); c.flags += " --spirv X"; check_case(c);
#include "core/filter.h"
#include "core/resource.h"
#include "core/lookup.h"
#include "reference/reference.h"
#include "support.h"

#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tf::test::sample {

constexpr int kSize = 64; // texture side: small, so every run is cheap

// 256 lookups: footprints from 1/4 texel to 64 texels of the 64^2 texture, up to 4:1, uv in [-1, 2].
const std::vector<Lookup>& lookups();
// Them as a CSV in the work directory, for `texfilter sample --lookups`.
const std::string& lookups_path();

// The test device's sampler precision as steps: 2^-subTexelPrecisionBits, 2^-mipmapPrecisionBits.
double sub_texel_step();
double mipmap_step();

struct Case {
    std::string texture = "noise";
    std::string flags;            // the filter's flags (and any more: --spirv FILE)
    SamplerOptions options;       // the same, for the reference
    ResourceOptions resource;
};
Case make_case(Resource resource, Filter filter, Taps taps = Taps::manual, int layers = 4, int layer = 2,
               Wrap wrap = Wrap::repeat);
std::string resource_flags(const ResourceOptions& r);

// `texfilter sample` of the case's lookups with --stats.
SampleResult gpu_run(const Case& c);
// The textures the case's resource holds (one for combined).
std::vector<MipChain> chains_of(const Case& c);

// GPU vs reference within the bound on every lookup; `wrongs` (when given): what a wrong layer / index / an
// unfiltered comparison would give, which must be further than the bound on at least `min_caught` of them.
void check_case(const Case& c, const std::vector<std::vector<glm::dvec4>>& wrongs = {}, double min_caught = 0.9);

// The case's stochastic form (--stochastic white --accumulate 8) on the device vs the reference's
// (sample_checks.cpp says what is asserted); the case's filter must have one.
void check_stochastic(Case c);

} // namespace tf::test::sample
