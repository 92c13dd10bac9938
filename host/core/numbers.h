#pragma once
// The one grammar of numbers that a user writes: every numeric flag of every command, the viewer's script,
// --camera, --memory-budget (docs/CLI.md, "Numbers"). Decimal only:
//   whole number  [+-]?[0-9]+
//   real number   [+-]?([0-9]+(\.[0-9]*)?|\.[0-9]+)([eE][+-]?[0-9]+)?   (finite: 1e999 is out of range)
//   byte size     [0-9]+ then K, M, G or T or nothing (either case; binary units, K = 1024): whole bytes,
//                 so 1.5G is refused (write 1536M)
// No hexadecimal (0x10), no inf or nan, no spaces before, after or inside.
#include <cstdint>
#include <optional>
#include <string_view>

namespace tf {

// The value, or nothing when the text is outside the grammar. Whole numbers and byte counts beyond 64 bits
// saturate (to the type's smallest or largest), so that a caller's range check names them as out of range;
// a real number beyond double's range is nothing (one below its smallest is 0). Callers name the flag and
// the range they expect.
std::optional<long long> parse_whole_number(std::string_view text);
std::optional<double> parse_real_number(std::string_view text);
std::optional<uint64_t> parse_byte_count(std::string_view text);

} // namespace tf
