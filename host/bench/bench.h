#pragma once
// texfilter bench: every scene x filter configuration on one device. GPU time per frame (timestamps),
// cost relative to hw-trilinear and to a no-texture baseline, texel fetches per pixel (counted by the
// shader), error against two ground truths (box and Gaussian pixel filters) and, where the texture has an
// analytic definition (checker, zoneplate, grid: core/analytic_texture.h), a third, the box pixel over that
// function (which judges magnification: the other two integrate the bilinear texels), and temporal flicker
// along a camera path. Writes bench.json, bench.csv and frame-0 images (PFM); tools/bench_report.py adds FLIP,
// plots and an HTML page. The goals of docs/BENCHMARKS.md are checked and reported, never asserted.
#include "bench/metrics.h"
#include "core/filter.h"
#include "vulkan/timing.h"
#include "scene/scene.h"
#include "io/texture_source.h"
#include "vulkan/device.h"
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace tf {

// One filter configuration: a label unique in the run ([a-z0-9-], a file name), the options, and the
// render flags that reproduce it.
struct BenchFilter {
    std::string label;
    SamplerOptions options;
    std::string args;
};

// The standard set: every manual filter and its hardware counterpart, aniso and EWA in both tap forms.
std::vector<BenchFilter> bench_filters();

struct BenchConfig {
    bool quick = false;
    int width = 256, height = 256;
    Stage stage = Stage::fragment; // the mesh scene is always rasterized (graphics pipeline)
    TextureSource texture;
    int truth_side = 16; // 256 samples a pixel
    bool truth_on_cpu = false; // the CPU reference's ground truth instead of the device's
    bool stochastic = true; // the stochastic rows (bench/stochastic_bench.h); off in --quick
    int warmup = 5, frames = 20, flicker_frames = 8;
    // Timed frames only: each pixel the mean of this many lookups spread over it (RenderOptions::lookups), so that
    // a GPU's filter time stands above the harness's per-pixel cost; images, errors and fetch counts use 1.
    int lookups_per_pixel = 1;
    FrameTimer timer = FrameTimer::timestamps; // the wall clock on CPU devices (see vulkan/timing.h)
    std::vector<SceneKind> scenes;
    std::vector<BenchFilter> filters;
};

struct BenchResult {
    SceneKind scene = SceneKind::plane;
    BenchFilter filter;
    Stage stage = Stage::fragment;
    TimeSummary time;
    double vs_hw_trilinear = 0, vs_baseline = 0;
    double fetches_per_pixel = 0, hw_lookups_per_pixel = 0;
    double rmse_box = 0, rmse_gaussian = 0;
    double flicker_box = 0, flicker_gaussian = 0;
    // Against the analytic truth (box pixel over the texture's function): NaN (null in bench.json) where
    // there is none (other textures, the environment scenes).
    double rmse_analytic = NAN, flicker_analytic = NAN;
    std::string image; // frame 0, relative to the output directory
};

// sat's footprint-size sweep: the minify scene at 2 and 64 texels a pixel.
struct SatSweep {
    std::string label;
    TimeSummary at_2x, at_64x;
};

// Stochastic filtering (bench/stochastic_bench.h) on one scene: a filter with --stochastic NOISE, the time of
// one frame and the error of the mean of the first 1, 4, 16 and 64 frames against the box and Gaussian truths.
struct StochasticRow {
    SceneKind scene = SceneKind::plane;
    std::string label; // the bench filter's label (bilinear, trilinear, aniso16, ewa)
    Noise noise = Noise::white;
    TimeSummary time;  // one frame
    std::vector<int> frames; // 1, 4, 16, 64
    std::vector<double> rmse_box, rmse_gaussian; // after frames[k] frames
};

// ewa's footprint-size sweep (bench/ewa_sweep.h): PSNR against the Gaussian truth of the minify scene at
// texels_per_pixel, manual and hardware taps.
struct EwaSweepPoint {
    double texels_per_pixel = 0;
    double psnr_manual = 0, psnr_hardware = 0;
};

struct BenchGoal {
    std::string goal, measured, status, note; // status: met, missed, not-applicable
};

struct BenchRun {
    DeviceInfo device;
    std::string date; // YYYY-MM-DD, local
    BenchConfig config;
    int texture_width = 0, texture_height = 0; // level 0 of the texture benchmarked (procedural or file)
    std::map<SceneKind, TimeSummary> baseline;
    // The compute stage's yardsticks, timed in turn with the baseline (shaders/harness/minimal.glsl): the
    // minimal pass, and it with a minimal manual trilinear lookup (float formats, square power-of-two textures).
    std::map<SceneKind, TimeSummary> minimal, minimal_trilinear;
    // Where trilinear ran too: the largest channel difference between its frame and the minimal trilinear
    // pass's (the yardstick reads the same texels with the same weights, so this is float rounding, except at a
    // periodic scene's seam, where the minimal pass's one gradient pass jumps).
    std::map<SceneKind, double> minimal_trilinear_difference;
    std::map<SceneKind, std::string> truth_box, truth_gaussian; // frame-0 images, relative paths
    std::map<SceneKind, std::string> truth_analytic; // the 2D scenes, when the texture has an analytic definition
    std::vector<BenchResult> results;
    std::vector<SatSweep> sat_sweep;
    std::vector<EwaSweepPoint> ewa_sweep; // when both ewa and ewa-hw ran
    std::vector<StochasticRow> stochastic;
    std::vector<BenchGoal> goals;
};

// Runs everything, writing images under `directory` (which exists), one progress line a result on stdout.
BenchRun run_bench(const VulkanContext& context, const BenchConfig& config, const MipChain& chain,
                   const std::string& directory);

// The goals of docs/BENCHMARKS.md judged on a finished run (a real GPU's goals are
// not-applicable on a CPU device, with the measured figure still given).
std::vector<BenchGoal> judge_goals(const BenchRun& run);

// One scene's results (run.results[first..]): each time relative to that scene's hw-trilinear.
void set_vs_hw_trilinear(BenchRun& run, size_t first);

std::string bench_json(const BenchRun& run);
std::string bench_csv(const BenchRun& run);

} // namespace tf
