#pragma once
// The CLI's commands; each returns the process exit code (0 ok, 1 comparison failed, 2 error).
#include <string>
#include <vector>

namespace tf {

int run_info(const std::vector<std::string>& argv);
int run_render(const std::vector<std::string>& argv);
int run_sample(const std::vector<std::string>& argv);
int run_diff(const std::vector<std::string>& argv);
int run_golden(const std::vector<std::string>& argv);
int run_bench(const std::vector<std::string>& argv);
int run_build(const std::vector<std::string>& argv);
int run_view(const std::vector<std::string>& argv);

} // namespace tf
