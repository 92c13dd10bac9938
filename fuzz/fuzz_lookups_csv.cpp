// libFuzzer target: the `sample` command's lookups CSV reader (host/io/lookups_csv.cpp), from memory.
// Asserts: only tf::Error escapes; a message names the file and is one short printable line (it quotes
// at most a few dozen characters of the input); what it accepts has at most one lookup a line and reads
// back the same when written with every digit.
#include "texture/error.h"
#include "fuzz_common.h"
#include "io/lookups_csv.h"

#include <cstdint>
#include <cstring>
#include <sstream>

namespace {

const char* const name = "fuzz.csv";

bool same(double a, double b) { return (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof a) == 0; }

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::istringstream in(text);
    std::vector<tf::Lookup> lookups;
    try {
        lookups = tf::parse_lookups_csv(in, name);
    } catch (const tf::Error& e) {
        const std::string message = e.what();
        FUZZ_CHECK(message.rfind(name, 0) == 0, message);
        FUZZ_CHECK(message.size() <= 300, std::to_string(message.size()) + " characters");
        FUZZ_CHECK(tf::fuzz::printable(message), message);
        return 0;
    }
    size_t lines = 1;
    for (char c : text)
        lines += c == '\n';
    FUZZ_CHECK(lookups.size() < lines);

    std::string again = "u,v,dudx,dvdx,dudy,dvdy\n";
    char row[200];
    for (const tf::Lookup& l : lookups) {
        std::snprintf(row, sizeof row, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", l.u, l.v, l.dudx, l.dvdx, l.dudy,
                      l.dvdy);
        again += row;
    }
    std::istringstream in2(again);
    const std::vector<tf::Lookup> back = tf::parse_lookups_csv(in2, name);
    FUZZ_CHECK(back.size() == lookups.size());
    for (size_t i = 0; i < back.size(); ++i) {
        const tf::Lookup &a = lookups[i], &b = back[i];
        FUZZ_CHECK(same(a.u, b.u) && same(a.v, b.v) && same(a.dudx, b.dudx) && same(a.dvdx, b.dvdx) &&
                       same(a.dudy, b.dudy) && same(a.dvdy, b.dvdy),
                   "row " + std::to_string(i));
    }
    return 0;
}
