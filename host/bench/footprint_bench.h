#pragma once
// texfilter bench --footprints: every filter's error against footprint size and anisotropy, lookup by lookup.
// Random lookups (an integer hash: the same on every machine) with uv uniform and a footprint J = [dUVdx dUVdy]
// whose major axis is log-uniform over 0.25..256 level-0 texels, anisotropy log-uniform over 1..64, both axes at
// uniform angles. Each lookup's truths are computed on the host, in double, in the sense of the scene truths
// (reference/ground_truth.h): level 0 reconstructed bilinearly, integrated over the pixel mapped into the
// texture by J (uv + J·(s,t)) under a box or a Gaussian (sigma ½ px) pixel filter, by stratified supersampling
// with a grid that resolves the footprint's major axis (four strata a texel along it, capped). A second truth,
// jittered independently, gives each bucket's noise floor: the PSNR of one truth against the other, above which a
// filter's PSNR means nothing. Errors are PSNRs over RGB after the sRGB encode, as the scene bench's.
#include "core/filter.h"
#include "core/lookup.h"
#include "core/lookup_stats.h"
#include "io/texture_source.h"
#include "texture/image.h"
#include "texture/mip.h"
#include "vulkan/device.h"
#include "vulkan/textures.h"
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace tf {

// One texture as the filters see it: on the host (the chain as loaded, rounded to its format) and, when a
// filter needs the device, uploaded there (with the summed-area table when a filter reads it).
struct FootprintTexture {
    std::string name; // as given: a procedural name or an image path
    const MipChain* chain = nullptr;
    const VulkanContext* context = nullptr; // null when no filter of the run needs the device
    const GpuTexture* gpu = nullptr;
};

// A filter's answers to a batch of lookups: one colour each (linear RGBA), and the work each took where the
// evaluator counts it (the device's shaders do; empty otherwise).
struct FootprintAnswers {
    std::vector<glm::dvec4> colors;
    std::vector<LookupStats> stats;
};

using EvaluateLookups = std::function<FootprintAnswers(const FootprintTexture&, const std::vector<Lookup>&)>;

// One row of the filter table (footprint_filters.cpp): a label ([a-z0-9-]) and how to evaluate a batch.
struct FootprintFilter {
    std::string label;
    bool device = false; // runs on the Vulkan device (the texture is uploaded for it)
    bool sat = false;    // reads the summed-area table (the upload builds it)
    EvaluateLookups evaluate;
    SamplerOptions options; // device filters: what the sample pass runs (checked against the texture's format)
};

// Every filter bench --footprints knows: the scene bench's labels on the device (bench_filters()), and host
// evaluators (the CPU reference's EWA, peers).
std::vector<FootprintFilter> footprint_filters();
// The filters --filters names, in its order; tf::Error naming an unknown label and listing the known ones.
std::vector<FootprintFilter> select_footprint_filters(const std::vector<std::string>& labels);
// The default set: ewa, ewa-hw, hw-aniso16, hw-trilinear, trilinear, aniso16, aniso16-hw, sat-assembly.
std::vector<std::string> default_footprint_labels();

// A random footprint in level-0 texels, and its lookup.
struct FootprintLookup {
    Lookup lookup;           // uv units, as the filters take it
    double major = 0;        // the footprint's major axis (J's larger singular value), level-0 texels
    double anisotropy = 1;   // major / minor
    int truth_side = 1;      // the truths' strata: truth_side² samples
};

struct FootprintSampling {
    int lookups = 9000;
    int min_side = 32, max_side = 128; // the truths' strata a side: 4 a texel of the major axis, in these bounds
};

// `count` lookups for a width x height texture, the same for the same arguments on every machine.
std::vector<FootprintLookup> footprint_lookups(int width, int height, const FootprintSampling& sampling);

// A lookup's truth: the mean of level0's bilinear reconstruction over side² stratified samples of the pixel
// filter (reference/ground_truth.h's pattern, for pixel (index, stream): streams 0 and 1 are independent), the
// pixel mapped to uv + dUVdx·s + dUVdy·t, (s, t) the sample's offset from the pixel's centre.
glm::dvec4 footprint_truth(const Image& level0, const Lookup& lookup, PixelFilter filter, int side, uint32_t index,
                           uint32_t stream, Wrap wrap);

// Every filter on one texture (uploaded to the device first, with its summed-area table where a filter reads it,
// when a filter runs there, as `format`: the chain as load_texture rounded it): one answer a filter, each checked to answer every lookup. context: null when none
// of the filters runs on the device.
std::vector<FootprintAnswers> run_footprint_filters(const VulkanContext* context, const std::string& name,
                                                    const MipChain& chain, const std::vector<FootprintFilter>& filters,
                                                    const std::vector<Lookup>& lookups,
                                                    TextureFormat format = TextureFormat::rgba32f);

// Buckets: by major axis (<1, 1-2, ..., 128-256 texels), by anisotropy (1-2, ..., 8-16, >16), and by major axis
// among the near-isotropic footprints alone (anisotropy below 2: "major-isotropic").
struct FootprintBucket {
    std::string axis; // "major", "anisotropy" or "major-isotropic"
    std::string name; // "<1", "1-2", ..., ">16"
    double low = 0, high = 0; // low <= value < high (the major axis, or the anisotropy for axis "anisotropy")
    double below_anisotropy = INFINITY; // and anisotropy < this
};
std::vector<FootprintBucket> footprint_buckets();

struct FootprintConfig {
    bool quick = false;
    std::vector<std::string> textures; // procedural names or image paths
    int texture_size = 512;            // procedural textures' side
    TextureFormat format = TextureFormat::rgba32f; // what the textures are uploaded as (and rounded to, for the truths)
    FootprintSampling sampling;
    std::vector<FootprintFilter> filters;
};

// One (texture, truth, filter, bucket): PSNR over RGB (sRGB-encoded, as the scene bench's) and the bucket's
// noise floor (truth against its second, independent estimate), with the mean work a lookup.
struct FootprintRow {
    std::string texture, truth, label; // truth: box or gaussian
    FootprintBucket bucket;
    int lookups = 0;
    double rmse = 0, psnr = 0, floor_psnr = 0;
    double fetches = NAN, hw_lookups = NAN; // a lookup's mean; NaN where the evaluator does not count
};

struct FootprintTextureInfo {
    std::string name;
    int width = 0, height = 0;
};

struct FootprintRun {
    DeviceInfo device; // empty name when no device was opened (host filters alone)
    std::string date;
    std::string command;
    FootprintConfig config;
    std::vector<FootprintTextureInfo> textures;
    double truth_seconds = 0, filter_seconds = 0;
    std::vector<FootprintRow> rows;
};

// How the run loads a texture: the procedural side, the SAT where a filter reads one, the device's limits (null:
// none). The command checks each texture's size with them (check_texture) before any work.
TextureSource footprint_source(const FootprintConfig& config, const std::string& name);
TextureUse footprint_use(const FootprintConfig& config, const DeviceLimits* device);

// Loads each texture, computes its lookups' truths on every core and runs every filter, one progress line a
// texture on stdout. context: null when no filter needs the device.
FootprintRun run_footprint_bench(const VulkanContext* context, const FootprintConfig& config);

std::string footprint_json(const FootprintRun& run);
std::string footprint_csv(const FootprintRun& run);
// The tables docs/BENCHMARKS.md shows: PSNR per filter (rows) and bucket (columns), one per texture and truth.
std::string footprint_tables(const FootprintRun& run);

} // namespace tf
