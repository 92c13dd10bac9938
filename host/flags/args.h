#pragma once
// Command-line flags: each command declares its flags; anything else is an error naming the flag.
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace tf {

struct FlagSpec {
    std::string name;      // "--scene", or "-o"
    std::string value;     // placeholder for help ("S"); empty for a switch
    std::string help;
};

struct Args {
    std::string command;
    std::map<std::string, std::string> values; // flag -> value ("" for switches)
    std::vector<std::string> positional;

    bool has(const std::string& flag) const { return values.count(flag) != 0; }
    std::string get(const std::string& flag, const std::string& fallback) const;
    std::string require(const std::string& flag) const;
    // The flag's value in core/numbers.h's grammar (decimal only, no spaces, no inf or nan) and in [min, max],
    // or `fallback` where the flag is absent; throws naming the flag, the text and the range.
    int get_int(const std::string& flag, int fallback, int min, int max) const;
    double get_double(const std::string& flag, double fallback, double min, double max) const;
};

// Parses argv after the command name. Throws tf::Error for an unknown flag or a missing value.
Args parse_args(const std::string& command, const std::vector<std::string>& argv, const std::vector<FlagSpec>& specs,
                size_t max_positional);

std::string format_help(const std::string& usage, const std::vector<FlagSpec>& specs);

// "256x128" -> {256, 128}; throws naming the flag for anything else or sides outside [min, max].
std::pair<int, int> parse_size(const std::string& flag, const std::string& text, int min, int max);

} // namespace tf
