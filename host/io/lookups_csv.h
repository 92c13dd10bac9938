#pragma once
// The `sample` command's files: lookups in (u,v,dudx,dvdx,dudy,dvdy), colours out (r,g,b,a).
#include "core/lookup_stats.h"
#include "core/lookup.h"
#include <glm/vec4.hpp>
#include <istream>
#include <string>
#include <vector>

namespace tf {

// Throws tf::Error naming the file and line for a missing/empty file, a wrong header, a row without
// six numbers, or more than max_lookups rows. "nan" and "inf" are accepted: filters must cope. A UTF-8
// byte order mark before the header is skipped. Messages quote at most a few dozen characters of the
// offending text (non-printable bytes escaped), however long the line.
std::vector<Lookup> read_lookups_csv(const std::string& path);
// The same from a stream; `name` stands for the file in messages (the fuzz target reads from memory).
std::vector<Lookup> parse_lookups_csv(std::istream& in, const std::string& name);
constexpr size_t max_lookups = 16u << 20;

// Writes "r,g,b,a" rows (9 significant digits) atomically: temp file, then rename. With stats, two
// more columns: fetches,hw_lookups.
void write_colors_csv(const std::string& path, const std::vector<glm::dvec4>& colors,
                      const std::vector<LookupStats>* stats = nullptr);

} // namespace tf
