#pragma once
// The CLI's commands; each returns the process exit code (0 ok, 1 comparison failed, 2 error).
#include "core/lookup.h"
#include "core/lookup_stats.h"
#include <glm/vec4.hpp>
#include <string>
#include <vector>

namespace tf {

int run_info(const std::vector<std::string>& argv);
int run_render(const std::vector<std::string>& argv);
int run_sample(const std::vector<std::string>& argv);
// `texfilter sample FLAGS` without its files: the same flags, checks and work, less --lookups and -o, on
// `lookups` given here; the colours and, with --stats, each lookup's counts. Throws tf::Error where the
// command exits 2 (--backend oiio is the command's alone). The tests' in-process route to the device.
struct SampleOutput {
    std::vector<glm::dvec4> colors;
    std::vector<LookupStats> stats; // with --stats only
};
SampleOutput sample_lookups(const std::vector<std::string>& flags, const std::vector<Lookup>& lookups);
int run_diff(const std::vector<std::string>& argv);
int run_golden(const std::vector<std::string>& argv);
int run_bench(const std::vector<std::string>& argv);
int run_build(const std::vector<std::string>& argv);
int run_view(const std::vector<std::string>& argv);

} // namespace tf
