#include "io/lookups_csv.h"
#include "core/escape.h"
#include "texture/error.h"
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include "io/output_path.h"
#include "io/text_file.h"
#include <sstream>

namespace tf {

namespace {

std::string trim(const std::string& s)
{
    size_t b = s.find_first_not_of(" \t\r\n"), e = s.find_last_not_of(" \t\r\n");
    return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

// Text from the file as a message quotes it: at most quote_limit characters, non-printable bytes as
// \xNN, and the full length when cut, so that a 50 MB line of garbage costs one short line on stderr.
constexpr size_t quote_limit = 40;
std::string quote(const std::string& s)
{
    std::string out = "'" + escape_bytes(std::string_view(s).substr(0, quote_limit), Escape::all_but_ascii) + "'";
    if (s.size() > quote_limit)
        out += "... (" + std::to_string(s.size()) + " characters)";
    return out;
}

const std::string utf8_bom = "\xEF\xBB\xBF";

// %.9g (every float comes back the same from strtod), NaN as "nan" whatever its sign bit: printf writes a
// negative NaN "-nan", which is no number in most CSV readers. Infinities are "inf" and "-inf".
int format_value(char* out, size_t size, double value)
{
    return std::isnan(value) ? std::snprintf(out, size, "nan") : std::snprintf(out, size, "%.9g", value);
}

} // namespace

std::vector<Lookup> read_lookups_csv(const std::string& path)
{
    // Held whole while it is parsed: capped at 128 bytes a row for max_lookups rows (a row of six numbers at
    // 9 significant digits is under 100), refused from its size past that.
    constexpr uint64_t max_lookups_file_bytes = uint64_t(max_lookups) * 128;
    std::istringstream in(read_text_file(path, max_lookups_file_bytes, "the lookups file"));
    return parse_lookups_csv(in, path);
}

std::vector<Lookup> parse_lookups_csv(std::istream& in, const std::string& path)
{
    std::string line;
    if (!std::getline(in, line))
        throw Error(path + ": the lookups file is empty (expected a header u,v,dudx,dvdx,dudy,dvdy)");
    // Editors on Windows save "UTF-8" with a byte order mark: invisible, so accept it.
    if (line.compare(0, utf8_bom.size(), utf8_bom) == 0)
        line.erase(0, utf8_bom.size());
    std::string header;
    for (char c : line)
        if (c != ' ' && c != '\t' && c != '\r')
            header += c;
    if (header != "u,v,dudx,dvdx,dudy,dvdy")
        throw Error(path + ":1: expected the header 'u,v,dudx,dvdx,dudy,dvdy', got " + quote(trim(line)));
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
            if (t.empty() || end != t.c_str() + t.size()) // all of it: "1\0junk" is not 1
                throw Error(path + ":" + std::to_string(number) + ": " + quote(t) + " is not a number");
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
        int n = 0;
        for (int k = 0; k < 4; ++k) {
            n += k ? std::snprintf(row + n, sizeof(row) - size_t(n), ",") : 0;
            n += format_value(row + n, sizeof(row) - size_t(n), c[k]);
        }
        if (stats)
            std::snprintf(row + n, sizeof(row) - size_t(n), ",%u,%u", (*stats)[i].texel_fetches,
                          (*stats)[i].hardware_lookups);
        text += row;
        text += '\n';
    }
    write_file_atomic(path, text);
}

} // namespace tf
