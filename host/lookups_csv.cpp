#include "lookups_csv.h"
#include "error.h"
#include <cstdio>
#include <cstdlib>
#include "output_path.h"
#include <filesystem>
#include <fstream>
#include <sstream>

namespace tf {

namespace {

std::string trim(const std::string& s)
{
    size_t b = s.find_first_not_of(" \t\r\n"), e = s.find_last_not_of(" \t\r\n");
    return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

} // namespace

std::vector<Lookup> read_lookups_csv(const std::string& path)
{
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw Error(path + ": is a directory, not a lookups file");
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error(path + ": no such lookups file");
    std::ifstream in(path);
    if (!in)
        throw Error(path + ": cannot open the lookups file");
    std::string line;
    if (!std::getline(in, line))
        throw Error(path + ": the lookups file is empty (expected a header u,v,dudx,dvdx,dudy,dvdy)");
    std::string header;
    for (char c : line)
        if (c != ' ' && c != '\t' && c != '\r')
            header += c;
    if (header != "u,v,dudx,dvdx,dudy,dvdy")
        throw Error(path + ":1: expected the header 'u,v,dudx,dvdx,dudy,dvdy', got '" + trim(line) + "'");
    std::vector<Lookup> lookups;
    for (size_t number = 2; std::getline(in, line); ++number) {
        if (trim(line).empty())
            continue;
        if (lookups.size() >= max_lookups)
            throw Error(path + ": more than " + std::to_string(max_lookups) + " lookups");
        double values[6];
        std::stringstream row(line);
        std::string cell;
        int n = 0;
        while (std::getline(row, cell, ',')) {
            std::string t = trim(cell);
            char* end = nullptr;
            double value = std::strtod(t.c_str(), &end);
            if (t.empty() || *end != '\0')
                throw Error(path + ":" + std::to_string(number) + ": '" + t + "' is not a number");
            if (n < 6)
                values[n] = value;
            ++n;
        }
        if (n != 6)
            throw Error(path + ":" + std::to_string(number) + ": expected 6 values, got " + std::to_string(n));
        lookups.push_back({values[0], values[1], values[2], values[3], values[4], values[5]});
    }
    return lookups;
}

void write_colors_csv(const std::string& path, const std::vector<glm::dvec4>& colors,
                      const std::vector<LookupStats>* stats)
{
    std::string text = stats ? "r,g,b,a,fetches,hw_lookups\n" : "r,g,b,a\n";
    char row[200];
    for (size_t i = 0; i < colors.size(); ++i) {
        const glm::dvec4& c = colors[i];
        int n = std::snprintf(row, sizeof(row), "%.9g,%.9g,%.9g,%.9g", c.r, c.g, c.b, c.a);
        if (stats)
            std::snprintf(row + n, sizeof(row) - size_t(n), ",%u,%u", (*stats)[i].texel_fetches,
                          (*stats)[i].hardware_lookups);
        text += row;
        text += '\n';
    }
    write_file_atomic(path, text);
}

} // namespace tf
