#pragma once
// Output files: checked before any work is done (a bad -o fails fast and names the path), and
// written atomically so that a failure never leaves a partial file.
#include <string>
#include <vector>

namespace tf {

// Throws tf::Error unless path ends in one of `extensions` (case-insensitive, e.g. ".png"), is not a
// directory, and its parent directory exists.
void check_output_path(const std::string& path, const std::vector<std::string>& extensions);

// Beside the target, unique per process: written first, renamed into place when complete.
std::string temporary_path_for(const std::string& path);

// Writes text to path via a temporary file and a rename, so a failure leaves no partial file.
void write_file_atomic(const std::string& path, const std::string& content);

} // namespace tf
