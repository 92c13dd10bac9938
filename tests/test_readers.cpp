// Tests of the input readers the fuzz targets drive (docs/FUZZING.md): the lookups CSV, the golden
// manifest, the PFM reader and the flag parser, through their file and stream entry points. Each test of
// a fixed bug says which input showed it; all run on the CPU, in milliseconds.
#include "flags/args.h"
#include "core/escape.h"
#include "core/memory_budget.h"
#include "core/numbers.h"
#include "texture/error.h"
#include "cli/golden.h"
#include "io/lookups_csv.h"
#include "io/pfm.h"
#include "support.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

const std::string header = "u,v,dudx,dvdx,dudy,dvdy\n";

void write_bytes(const fs::path& path, const std::string& bytes)
{
    std::ofstream out(path, std::ios::binary);
    out << bytes;
}

// What the reader throws for a file, or "" if it accepts it.
std::string csv_error(const fs::path& path)
{
    try {
        (void)tf::read_lookups_csv(path.string());
    } catch (const tf::Error& e) {
        return e.what();
    }
    return "";
}

bool printable(const std::string& s)
{
    for (unsigned char c : s)
        if (c < 0x20 || c >= 0x7f)
            return false;
    return true;
}

// ---------------------------------------------------------------------------------------------------
// Lookups CSV.

TEST_CASE("csv-bom")
{
    // A UTF-8 byte order mark (what Windows editors write) before the header was rejected with a message
    // whose quoted header looked exactly like the expected one.
    const fs::path work = tf::test::make_work_dir("readers-bom");
    const fs::path path = work / "bom.csv";
    write_bytes(path, "\xEF\xBB\xBF" + header + "0.25,0.75,0.5,0,0,0.125\r\n");
    std::vector<tf::Lookup> lookups;
    try {
        lookups = tf::read_lookups_csv(path.string());
    } catch (const tf::Error& e) {
        CHECK(!"a BOM before the header is refused", e.what());
    }
    CHECK_EQ(lookups.size(), 1);
    if (lookups.size() == 1) {
        CHECK_EQ(lookups[0].u, 0.25);
        CHECK_EQ(lookups[0].v, 0.75);
        CHECK_EQ(lookups[0].dudx, 0.5);
        CHECK_EQ(lookups[0].dvdy, 0.125);
    }
    // Only before the header: one in a row is garbage like any other.
    write_bytes(path, header + "\xEF\xBB\xBF" "0.25,0.75,0.5,0,0,0.125\n");
    CHECK_THROWS_WITH(tf::read_lookups_csv(path.string()), path.string() + ":2: '\\xef\\xbb\\xbf0.25' is not a number");
}

TEST_CASE("csv-long-lines")
{
    // An 8 MB garbage line (the was 50 MB) was echoed whole into the message, so to stderr.
    const fs::path work = tf::test::make_work_dir("readers-long");
    const fs::path path = work / "long.csv";
    const size_t length = size_t(8) << 20;
    write_bytes(path, header + "0.5,0.5,0,0,0,0\n" + std::string(length, 'x') + "\n");
    std::string message = csv_error(path);
    CHECK(message.find(path.string() + ":3: 'xxxxxxxx") == 0, message.substr(0, 200));
    CHECK(message.find("(8388608 characters)") != std::string::npos, message.substr(0, 200));
    CHECK(message.size() < path.string().size() + 120, std::to_string(message.size()) + " characters");

    // The same for a header line of garbage, and bytes that are not text are shown as \xNN.
    write_bytes(path, std::string(1 << 20, '\x01') + "\n" + "0,0,0,0,0,0\n");
    message = csv_error(path);
    CHECK(message.find(path.string() + ":1: expected the header") == 0, message.substr(0, 200));
    CHECK(message.find("'\\x01\\x01") != std::string::npos, message.substr(0, 200));
    CHECK(message.size() < path.string().size() + 300, std::to_string(message.size()) + " characters");
    CHECK(printable(message), message.substr(0, 200));

    // Short text is quoted whole, as before.
    write_bytes(path, header + "0.5,0.5,abc,0,0,0\n");
    CHECK_EQ(csv_error(path) == path.string() + ":2: 'abc' is not a number", 1);
}

TEST_CASE("csv-numbers")
{
    const fs::path work = tf::test::make_work_dir("readers-numbers");
    const fs::path path = work / "numbers.csv";
    // A NUL byte ended the number for strtod, so "1<NUL>junk" read as 1.
    write_bytes(path, header + "0.5,0.5,0,0,0,1" + std::string(1, '\0') + "junk\n");
    CHECK_THROWS_WITH(tf::read_lookups_csv(path.string()), "'1\\x00junk' is not a number");
    // nan, inf, hex floats and blank lines are fine; the stream entry point names what it is given.
    std::istringstream in(header + "\nnan,inf,-inf,0x1p-3,1e300,-0\n \t\n");
    const std::vector<tf::Lookup> lookups = tf::parse_lookups_csv(in, "memory");
    CHECK_EQ(lookups.size(), 1);
    if (lookups.size() == 1)
        CHECK(std::isnan(lookups[0].u) && lookups[0].v == INFINITY && lookups[0].dudy == 1e300);
    std::istringstream empty("");
    CHECK_THROWS_WITH(tf::parse_lookups_csv(empty, "memory"), "memory: the lookups file is empty");
}

// ---------------------------------------------------------------------------------------------------
// Manifest, PFM and flags through their stream entry points and the parsing fixes they share.

TEST_CASE("manifest-stream")
{
    std::istringstream in("# comment\nplane-a plane checker trilinear lod-bias=1 size=64x32\n\n"
                          "zoom-b zoom noise bilinear texture-size=16 fail=0.01\n");
    const std::vector<tf::GoldenCase> cases = tf::parse_manifest(in, "m.txt");
    CHECK_EQ(cases.size(), 2);
    if (cases.size() == 2) {
        CHECK(cases[0].name == "plane-a" && cases[0].width == 64 && cases[0].height == 32);
        CHECK_EQ(cases[0].sampler.lod_bias, 1.0);
        CHECK_EQ(cases[1].texture.procedural_size, 16);
        CHECK_EQ(cases[1].thresholds.fail, 0.01);
    }
    std::istringstream twice("x plane checker nearest\nx plane checker nearest\n");
    CHECK_THROWS_WITH(tf::parse_manifest(twice, "m.txt"), "m.txt:2: case name 'x' used twice");
    // A NUL inside a value ended it for strtod/strtol: "fail=0.5<NUL>9" read as 0.5.
    std::istringstream nul("y plane checker nearest fail=0.5" + std::string(1, '\0') + "9\n");
    CHECK_THROWS_WITH(tf::parse_manifest(nul, "m.txt"), "m.txt:1: bad value for --fail");
    std::istringstream size_nul("y plane checker nearest size=64x64" + std::string(1, '\0') + "\n");
    CHECK_THROWS_WITH(tf::parse_manifest(size_nul, "m.txt"), "m.txt:1: bad value for size");
}

TEST_CASE("pfm-stream")
{
    const std::string pixels(12, '\0');
    std::istringstream good("PF\n1 1\n-1.0\n" + pixels, std::ios::binary);
    const tf::Image image = tf::read_pfm(good, "p.pfm");
    CHECK(image.width == 1 && image.height == 1 && image.texels.size() == 1 && image.texels[0].a == 1.0f);
    // The magic is two bytes and a whitespace: "PFX" is no colour PFM, and a big file without any
    // whitespace is refused without reading it into one word.
    std::istringstream pfx("PFX\n1 1\n-1.0\n" + pixels, std::ios::binary);
    CHECK_THROWS_WITH(tf::read_pfm(pfx, "p.pfm"), "p.pfm: not a colour PFM file");
    std::istringstream word(std::string(1 << 20, 'P'), std::ios::binary);
    CHECK_THROWS_WITH(tf::read_pfm(word, "p.pfm"), "p.pfm: not a colour PFM file");
    std::istringstream header_only("PF\n1 1\n-1.0", std::ios::binary);
    CHECK_THROWS_WITH(tf::read_pfm(header_only, "p.pfm"), "p.pfm: ");
}

TEST_CASE("flags")
{
    const std::vector<tf::FlagSpec> specs = {{"--n", "N", ""}, {"--x", "X", ""}, {"--size", "WxH", ""}};
    const tf::Args args =
        tf::parse_args("t", {"--n", "5" + std::string(1, '\0') + "7", "--x=2.5", "--size", "8x8"}, specs, 0);
    CHECK_THROWS_WITH(args.get_int("--n", 0, 0, 100), "bad value for --n");
    CHECK_EQ(args.get_double("--x", 0, 0, 10), 2.5);
    CHECK(tf::parse_size("--size", args.get("--size", ""), 2, 16) == std::make_pair(8, 8));
    CHECK_THROWS_WITH(tf::parse_size("--size", "8" + std::string(1, '\0') + "1x8", 2, 16), "bad value for --size");
}

// core/numbers.h: the one grammar of every numeric flag. Decimal only; the forms strtol/strtod also took
// (hexadecimal, inf, nan, spaces) are refused; byte sizes are whole.
TEST_CASE("number-grammar")
{
    using tf::parse_real_number;
    using tf::parse_whole_number;
    CHECK(parse_whole_number("16") == 16);
    CHECK(parse_whole_number("+16") == 16);
    CHECK(parse_whole_number("-0") == 0);
    CHECK(parse_whole_number("0016") == 16);
    for (const char* bad : {"", "+", "-", "0x10", "1e3", "1.0", " 5", "5 ", "5\n", "1_000", "++1", "١"})
        CHECK(!parse_whole_number(bad), bad);
    // Beyond 64 bits: saturated, so that a range check names it out of range.
    CHECK(parse_whole_number("99999999999999999999") == std::numeric_limits<long long>::max());
    CHECK(parse_whole_number("-99999999999999999999") == std::numeric_limits<long long>::min());

    CHECK(parse_real_number("16") == 16.0);
    CHECK(parse_real_number("2.5") == 2.5);
    CHECK(parse_real_number("-.5") == -0.5);
    CHECK(parse_real_number("1.") == 1.0);
    CHECK(parse_real_number("+1e-3") == 0.001);
    CHECK(parse_real_number("2E2") == 200.0);
    CHECK(parse_real_number("1e-999") == 0.0);
    CHECK(parse_real_number("0.1000000000000000055511151231257827") == 0.1);
    for (const char* bad : {"", ".", "-", "e5", "1e", "1e+", "0x10", "0x1p3", "inf", "-inf", "nan", "infinity",
                            " 1", "1 ", "1.5.2", "1,5", "1e999", "-1e999", "1f"})
        CHECK(!parse_real_number(bad), bad);

    CHECK(tf::parse_byte_count("512") == 512u);
    CHECK(tf::parse_byte_count("1k") == 1024u);
    CHECK(tf::parse_byte_count("1536M") == 1536ull << 20);
    CHECK(tf::parse_byte_count("8G") == 8ull << 30);
    CHECK(tf::parse_byte_count("2T") == 2ull << 40);
    for (const char* bad : {"", "G", "1.5", "1.5G", "-1G", "+1G", "8GB", "8GiB", "8 G", " 8G", "0x10", "1e9"})
        CHECK(!tf::parse_byte_count(bad), bad);
    CHECK(tf::parse_byte_count("99999999999999999999") == std::numeric_limits<uint64_t>::max());
    CHECK(tf::parse_byte_count("17179869184G") == std::numeric_limits<uint64_t>::max()); // 2^34 G = 2^64 bytes

    // The flags read through it.
    const std::vector<tf::FlagSpec> specs = {{"--n", "N", ""}, {"--x", "X", ""}};
    CHECK_THROWS_WITH(tf::parse_args("t", {"--x", "0x10"}, specs, 0).get_double("--x", 0, 0, 100),
                      "bad value for --x: '0x10' (expected a number in [0, 100])");
    CHECK_THROWS_WITH(tf::parse_args("t", {"--x", "inf"}, specs, 0).get_double("--x", 0, 0, INFINITY),
                      "bad value for --x: 'inf' (expected a number in [0, inf])");
    CHECK_THROWS_WITH(tf::parse_args("t", {"--n", " 5"}, specs, 0).get_int("--n", 0, 0, 100),
                      "bad value for --n: ' 5' (expected an integer in [0, 100])");
    CHECK_THROWS_WITH(tf::parse_args("t", {"--n", "99999999999999999999"}, specs, 0).get_int("--n", 0, 0, 100),
                      "bad value for --n: '99999999999999999999' (expected an integer in [0, 100])");
    CHECK_THROWS_WITH(tf::parse_byte_size("1.5"), "'1.5' is not a size (a whole number of bytes, or of K, M, G or T: "
                                                  "512M, 8G; 1536M, not 1.5G)");
    CHECK_THROWS_WITH(tf::parse_byte_size("0"), "'0' is out of range (expected 1 byte to 1e18 bytes, e.g. 512M, 8G)");
    CHECK_THROWS_WITH(tf::parse_byte_size("99999999999999999999G"), "'99999999999999999999G' is out of range "
                                                                    "(expected 1 byte to 1e18 bytes, e.g. 512M, 8G)");
}

// core/escape.h: what every message and the lookups CSV's quotes write for bytes a terminal would act on.
TEST_CASE("escape-bytes")
{
    using tf::Escape;
    const std::string text = std::string("a\x1b[2J\n\t\x7f\\b") + std::string(1, '\0') + "\xc3\xa9";
    CHECK(tf::escape_bytes(text, Escape::control) == "a\\x1b[2J\\x0a\\x09\\x7f\\b\\x00\xc3\xa9");
    CHECK(tf::escape_bytes(text, Escape::all_but_ascii) == "a\\x1b[2J\\x0a\\x09\\x7f\\x5cb\\x00\\xc3\\xa9");
}

} // namespace

