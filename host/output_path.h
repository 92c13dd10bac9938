#pragma once
// Checks an output path before any work is done, so a bad -o fails fast and names the path.
#include <string>
#include <vector>

namespace tf {

// Throws tf::Error unless path ends in one of `extensions` (case-insensitive, e.g. ".png"), is not a
// directory, and its parent directory exists.
void check_output_path(const std::string& path, const std::vector<std::string>& extensions);

} // namespace tf
