#pragma once
// The benchmark on the environment scenes (skybox, reflect): the same rows as a 2D scene (time against the
// no-texture baseline, error and flicker against the box and Gaussian truths through the same directions),
// each filter that has an environment form, on the cube or lat-long map --env makes of --texture.
#include "bench/bench.h"

namespace tf {

// Appends one scene's results to `run` (and its baseline and truths), images under `directory`. Texel reads
// are not counted on these scenes (`sample` takes uv lookups): their fetches_per_pixel and
// hw_lookups_per_pixel are 0. Filters without an environment form (brilinear, sat, sat-assembly) are left out.
void bench_environment_scene(const VulkanContext& context, const BenchConfig& config, SceneKind kind,
                             const std::string& directory, BenchRun& run);

} // namespace tf
