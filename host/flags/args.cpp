#include "flags/args.h"
#include "core/numbers.h"
#include "texture/error.h"
#include <cstdio>
#include <optional>

namespace tf {

std::string Args::get(const std::string& flag, const std::string& fallback) const
{
    auto it = values.find(flag);
    return it == values.end() ? fallback : it->second;
}

std::string Args::require(const std::string& flag) const
{
    auto it = values.find(flag);
    if (it == values.end())
        throw Error(command + ": missing required flag " + flag + " (see --help)");
    return it->second;
}

int Args::get_int(const std::string& flag, int fallback, int min, int max) const
{
    if (!has(flag))
        return fallback;
    const std::string& text = values.at(flag);
    const std::optional<long long> value = parse_whole_number(text);
    if (!value || *value < min || *value > max)
        throw Error("bad value for " + flag + ": '" + text + "' (expected an integer in [" + std::to_string(min) +
                    ", " + std::to_string(max) + "])");
    return int(*value);
}

namespace {
std::string format_number(double value)
{
    char text[32];
    std::snprintf(text, sizeof(text), "%g", value);
    return text;
}
} // namespace

double Args::get_double(const std::string& flag, double fallback, double min, double max) const
{
    if (!has(flag))
        return fallback;
    const std::string& text = values.at(flag);
    const std::optional<double> value = parse_real_number(text);
    if (!value || *value < min || *value > max)
        throw Error("bad value for " + flag + ": '" + text + "' (expected a number in [" + format_number(min) +
                    ", " + format_number(max) + "])");
    return *value;
}

Args parse_args(const std::string& command, const std::vector<std::string>& argv, const std::vector<FlagSpec>& specs,
                size_t max_positional)
{
    Args args;
    args.command = command;
    for (size_t i = 0; i < argv.size(); ++i) {
        std::string token = argv[i];
        if (token.size() < 2 || token[0] != '-') {
            if (args.positional.size() >= max_positional)
                throw Error(command + ": unexpected argument '" + token + "' (see --help)");
            args.positional.push_back(token);
            continue;
        }
        std::string inline_value;
        bool has_inline = false;
        if (size_t eq = token.find('='); eq != std::string::npos && token.rfind("--", 0) == 0) {
            inline_value = token.substr(eq + 1);
            token = token.substr(0, eq);
            has_inline = true;
        }
        const FlagSpec* spec = nullptr;
        for (const FlagSpec& s : specs)
            if (s.name == token)
                spec = &s;
        if (!spec)
            throw Error(command + ": unknown flag " + token + " (see --help)");
        if (args.has(token))
            throw Error(command + ": flag " + token + " given twice");
        if (spec->value.empty()) {
            if (has_inline)
                throw Error(command + ": flag " + token + " takes no value");
            args.values[token] = "";
        } else if (has_inline) {
            args.values[token] = inline_value;
        } else {
            if (i + 1 >= argv.size())
                throw Error(command + ": flag " + token + " needs a value (" + spec->value + ")");
            // `-o --lod-bias 1` forgot -o's value: say so, not "unexpected argument '1'". Only the command's own
            // flag names count, so that a negative number (--lod-bias -1) stays a value.
            const std::string& next = argv[i + 1];
            const std::string next_name = next.rfind("--", 0) == 0 ? next.substr(0, next.find('=')) : next;
            for (const FlagSpec& s : specs)
                if (s.name == next_name)
                    throw Error(command + ": flag " + token + " needs a value (" + spec->value + "), but the next "
                                "argument is the flag " + next_name);
            args.values[token] = argv[++i];
        }
    }
    return args;
}

std::string format_help(const std::string& usage, const std::vector<FlagSpec>& specs)
{
    std::string out = "usage: " + usage + "\n\noptions:\n";
    for (const FlagSpec& s : specs) {
        std::string left = "  " + s.name + (s.value.empty() ? "" : " " + s.value);
        if (left.size() < 28)
            left.resize(28, ' ');
        else
            left += "\n" + std::string(28, ' ');
        out += left + s.help + "\n";
    }
    return out;
}

std::pair<int, int> parse_size(const std::string& flag, const std::string& text, int min, int max)
{
    size_t x = text.find('x');
    auto bad = [&] {
        return Error("bad value for " + flag + ": '" + text + "' (expected WxH with sides in [" + std::to_string(min) +
                     ", " + std::to_string(max) + "], e.g. 256x256)");
    };
    if (x == std::string::npos)
        throw bad();
    const std::optional<long long> width = parse_whole_number(text.substr(0, x));
    const std::optional<long long> height = parse_whole_number(text.substr(x + 1));
    if (!width || !height || *width < min || *width > max || *height < min || *height > max)
        throw bad();
    return {int(*width), int(*height)};
}

} // namespace tf
