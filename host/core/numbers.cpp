#include "core/numbers.h"
#include <cctype>
#include <charconv>
#include <limits>
#include <string>
#include <system_error>

namespace tf {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The length of the run of digits at `at`.
size_t digits(std::string_view text, size_t at)
{
    size_t n = 0;
    while (at + n < text.size() && is_digit(text[at + n]))
        ++n;
    return n;
}

} // namespace

std::optional<long long> parse_whole_number(std::string_view text)
{
    size_t at = !text.empty() && (text[0] == '+' || text[0] == '-') ? 1 : 0;
    if (digits(text, at) == 0 || at + digits(text, at) != text.size())
        return std::nullopt;
    const size_t skip = text[0] == '+' ? 1 : 0; // from_chars reads a '-' but not a '+'
    long long value = 0;
    const auto [end, error] = std::from_chars(text.data() + skip, text.data() + text.size(), value);
    if (error == std::errc::result_out_of_range)
        return text[0] == '-' ? std::numeric_limits<long long>::min() : std::numeric_limits<long long>::max();
    if (error != std::errc() || end != text.data() + text.size())
        return std::nullopt;
    return value;
}

std::optional<double> parse_real_number(std::string_view text)
{
    size_t at = !text.empty() && (text[0] == '+' || text[0] == '-') ? 1 : 0;
    const size_t whole = digits(text, at);
    at += whole;
    size_t fraction = 0;
    if (at < text.size() && text[at] == '.') {
        fraction = digits(text, at + 1);
        at += 1 + fraction;
    }
    if (whole == 0 && fraction == 0)
        return std::nullopt;
    if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
        size_t sign = at + 1 < text.size() && (text[at + 1] == '+' || text[at + 1] == '-') ? 1 : 0;
        const size_t exponent = digits(text, at + 1 + sign);
        if (exponent == 0)
            return std::nullopt;
        at += 1 + sign + exponent;
    }
    if (at != text.size())
        return std::nullopt;
    const size_t skip = text[0] == '+' ? 1 : 0;
    double value = 0;
    const auto [end, error] =
        std::from_chars(text.data() + skip, text.data() + text.size(), value, std::chars_format::general);
    if (end != text.data() + text.size() || (error != std::errc() && error != std::errc::result_out_of_range))
        return std::nullopt;
    if (error == std::errc::result_out_of_range) { // past double's range, or below its smallest: 1e-999 is 0
        size_t e = text.find_first_of("eE");
        if (e == std::string_view::npos || text[e + 1] != '-')
            return std::nullopt;
        value = text[0] == '-' ? -0.0 : 0.0;
    }
    return value;
}

std::optional<uint64_t> parse_byte_count(std::string_view text)
{
    const size_t n = digits(text, 0);
    if (n == 0 || n + 1 < text.size())
        return std::nullopt;
    unsigned shift = 0;
    if (n < text.size()) {
        switch (std::toupper(static_cast<unsigned char>(text[n]))) {
        case 'K': shift = 10; break;
        case 'M': shift = 20; break;
        case 'G': shift = 30; break;
        case 'T': shift = 40; break;
        default: return std::nullopt;
        }
    }
    uint64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + n, value);
    if (error == std::errc::result_out_of_range || value > (std::numeric_limits<uint64_t>::max() >> shift))
        return std::numeric_limits<uint64_t>::max();
    if (error != std::errc() || end != text.data() + n)
        return std::nullopt;
    return value << shift;
}

} // namespace tf
