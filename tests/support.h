#pragma once
// What the tests in this folder share: CHECK macros reported through doctest (tests/README.md), a
// scratch directory, the device the suite runs on, and `texfilter sample` runs (a lookups CSV in,
// colours and per-lookup stats out).
//
// doctest's own short macro names are off (DOCTEST_CONFIG_NO_SHORT_MACRO_NAMES, set by CMake): CHECK and
// its family below keep this suite's meaning (a values string, CHECK_NEAR, tf::Error for throws), and
// TEST_CASE / TEST_SUITE_BEGIN / MESSAGE are doctest's.
#include <doctest/doctest.h>

#include "texture/error.h"
#include "core/lookup_stats.h"
#include "reference/reference.h"
#include "vulkan/device.h"

#include <exception>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

namespace tf::test {

// doctest's reporter interface with every event ignored: a reporter or listener overrides only what it uses.
struct QuietReporter : doctest::IReporter {
    void report_query(const doctest::QueryData&) override {}
    void test_run_start() override {}
    void test_run_end(const doctest::TestRunStats&) override {}
    void test_case_start(const doctest::TestCaseData&) override {}
    void test_case_reenter(const doctest::TestCaseData&) override {}
    void test_case_end(const doctest::CurrentTestCaseStats&) override {}
    void test_case_exception(const doctest::TestCaseException&) override {}
    void subcase_start(const doctest::SubcaseSignature&) override {}
    void subcase_end() override {}
    void log_assert(const doctest::AssertData&) override {}
    void log_message(const doctest::MessageData&) override {}
    void test_case_skipped(const doctest::TestCaseData&) override {}
};

// ---------------------------------------------------------------------------------------------------
// Checks. Each CHECK* is one doctest assertion at the caller's file and line: a failed one fails the
// running test case and prints the expression and <values> (what was compared).

bool check(bool ok, const char* file, int line, const std::string& what, const std::string& values = "");
bool check_eq(double a, double b, const char* file, int line, const char* a_text, const char* b_text);
bool check_near(double a, double b, double eps, const char* file, int line, const char* what);
bool check_near(const glm::dvec4& a, const glm::dvec4& b, double eps, const char* file, int line, const char* what);
// threw: the expression threw a tf::Error; message: what it threw (any exception).
bool check_throws(bool threw, const std::string& message, const std::string& part, const char* file, int line,
                  const char* expr);

// Measured against a bound, and named conditions: each prints one line, "ok" or "FAIL", what, the measured
// value and its bound (or the detail), so a run shows its margins and a device's log can be read for them,
// and is one doctest assertion naming what, measured and bound when it fails. NaN fails either bound.
bool check_bound(const std::string& what, double measured, double bound, bool upper, const char* file, int line);
bool check_true(const std::string& what, bool ok, const std::string& detail, const char* file, int line);
// `text` holds every one of `parts`.
bool check_contains(const std::string& text, std::initializer_list<std::string> parts, const char* file, int line,
                    const char* text_expr);
bool check_eq_text(const std::string& a, const std::string& b, const char* file, int line, const char* a_text,
                   const char* b_text);

// Equal, or at most eps apart, in every component (NaN is never near).
bool near(double a, double b, double eps);
bool near(const glm::dvec4& a, const glm::dvec4& b, double eps);
double max_channel_diff(const glm::dvec4& a, const glm::dvec4& b);

// Largest channel difference between the 2x2 texels a bilinear lookup at uv reads on `level`, across (x)
// and down (y): what a rounded weight can move the result by, per unit of weight.
void texel_contrast(const Image& level, double u, double v, Wrap wrap, double& across, double& down);
std::string show(double x); // every digit (%.17g)
std::string show(const glm::dvec4& v);

// For the rest of the running test case report at most `limit` failed checks, counting the rest (the
// case still fails; its end says how many were not shown): one bad GPU run can fail thousands of
// lookups, and the first few say what went wrong. Every test case starts unlimited.
void limit_failure_lines(int limit);
// Failed checks of the running test case (shown or not).
int failures();

// Named checks inside one test case, each its own ctest test: the case runs each as the doctest SUBCASE
// check_id(name) (ctest runs one with --test-case=CASE --subcase=ID). Under --tf-list-checks
// (tests/list_doctest_cases.cmake, at build time) the case calls list_check(ID) instead, which prints
// "tf-check<TAB>CASE<TAB>ID", and runs nothing.
std::string check_id(const std::string& name); // lower case, a-z 0-9 and '-' only
void set_listing_checks();
bool listing_checks();
void list_check(const std::string& id);
// Runs `body` as the named check `name` (its SUBCASE check_id(name), or list_check under --tf-list-checks)
// and prints its line: name, the detail `body` returns, PASS/FAIL. At most 8 failed checks are shown.
void named_check(const std::string& name, const std::function<std::string()>& body);

// ---------------------------------------------------------------------------------------------------
// The device and the `texfilter` command.

// $TEXFILTER_EXE, else the texfilter this build made (tests/CMakeLists.txt compiles its path in).
std::string texfilter_path();

// $TEXFILTER_TEST_DEVICE (an index or part of a name, as `--device`), "" for texfilter's default
// (lavapipe first): the one device every test of the suite runs on, in process and through `sample`.
std::string test_device();
// Context options for that device, with the validation layers on (any message fails the test).
ContextOptions test_context_options();
// The device's properties (tolerances come from its precision bits); read once a process.
const DeviceInfo& test_device_info();

// What must end when the test run ends, before main returns (newest first), not in a static destructor:
// Vulkan objects (by then the loader's and the driver's own exit handlers may have run). main calls
// run_end_of_run.
void at_end_of_run(std::function<void()> task);
void run_end_of_run();

// A fresh directory texfilter-<name>-<pid> in the system's temp dir, removed when the process exits.
std::filesystem::path make_work_dir(const std::string& name);
// This process's scratch directory, texfilter-<executable>-<pid>: made on first use, the same ever after.
const std::filesystem::path& work_dir();
// A new empty file PREFIX<6 characters>SUFFIX in dir, its name unique (mkstemps).
std::filesystem::path new_file_in(const std::filesystem::path& dir, const std::string& prefix,
                                  const std::string& suffix);

// Where random_footprint_lookups draws from. Footprints are 2^o level-0 texels of a texture_size texture,
// o in [octave_min, octave_max], at a random angle; the minor column is shorter by 2^s, s in
// [0, max_stretch], and turned from the major one by a right angle plus a shear in [-max_shear,
// max_shear] radians (columns not orthogonal). A range of zero width draws nothing (so adding one keeps
// the other draws of the same seed).
struct FootprintRanges {
    double uv_min = -1.0, uv_max = 2.0;
    double octave_min = -4.0, octave_max = 9.0;
    double max_stretch = 0.0;
    double max_shear = 0.0;
    double texture_size = 256.0;
};

// Random lookups (as given, in double; as_float gives the GPU's view), the same for the same seed.
std::vector<Lookup> random_footprint_lookups(int count, unsigned seed, const FootprintRanges& ranges);

// The GPU reads lookups as float: the reference must see the same numbers.
Lookup as_float(const Lookup& l);
std::vector<Lookup> as_float(std::vector<Lookup> lookups);

// Header u,v,dudx,dvdx,dudy,dvdy, `digits` significant digits a value (9: every float exactly): by default
// the values as float, the numbers the GPU sees; float_values false writes them as given (`--backend
// reference` reads them as double: 17 digits give it every double exactly).
void write_lookups_csv(const std::filesystem::path& path, const std::vector<Lookup>& lookups,
                       bool float_values = true, int digits = 9);

struct SampleResult {
    std::vector<glm::dvec4> colors;
    std::vector<LookupStats> stats; // with stats only
};

// POSIX shell words of `line`: blanks split, '...' quotes literally, a backslash outside quotes escapes the
// next character (all that tf::shell_quote writes).
std::vector<std::string> shell_words(const std::string& line);

// The lookups of LOOKUPS_CSV filtered as `texfilter sample --validate [--device D] [--stats] FLAGS` filters
// them (D the test device), in process through tf::sample_lookups (cli/commands.h): the same flags, checks
// and device work, no command and no output file. Throws tf::Error naming the flags if it fails (a validation
// message included) or gives other than one row per lookup.
SampleResult run_sample(const std::string& flags, const std::string& lookups_csv, bool stats);
// The command itself, for the tests of the command: `texfilter sample --validate [--device D] [--stats] FLAGS
// --lookups LOOKUPS_CSV -o OUT` (texfilter_path(); OUT a new file in work_dir()) under a time limit (a hung
// shader fails the test instead of blocking it), its CSV read back. Throws tf::Error naming the command line
// if the command fails or its output is not one row per lookup.
SampleResult run_sample_command(const std::string& flags, const std::string& lookups_csv, bool stats);

} // namespace tf::test

// doctest's test-case macros under their usual names (the short names are off, see the top).
#define TEST_CASE(...) DOCTEST_TEST_CASE(__VA_ARGS__)
#define TEST_SUITE_BEGIN(...) DOCTEST_TEST_SUITE_BEGIN(__VA_ARGS__)
#define TEST_SUITE_END() DOCTEST_TEST_SUITE_END()
#define MESSAGE(...) DOCTEST_MESSAGE(__VA_ARGS__)
#define INFO(...) DOCTEST_INFO(__VA_ARGS__)

// CHECK(expr) or CHECK(expr, values): values (a string) says what was compared.
#define CHECK(expr, ...) ::tf::test::check(bool(expr), __FILE__, __LINE__, #expr __VA_OPT__(, __VA_ARGS__))
// Compared as double (the values are counts, sizes and exact floats).
#define CHECK_EQ(a, b) ::tf::test::check_eq(double(a), double(b), __FILE__, __LINE__, #a, #b)
// Doubles or glm::dvec4s, every component within eps.
#define CHECK_NEAR(a, b, eps) \
    ::tf::test::check_near((a), (b), (eps), __FILE__, __LINE__, #a " ~= " #b " within " #eps)
// measured <= bound (CHECK_LE) or measured >= bound (CHECK_GE), what a string; printed either way.
#define CHECK_LE(what, measured, bound) ::tf::test::check_bound((what), (measured), (bound), true, __FILE__, __LINE__)
#define CHECK_GE(what, measured, bound) ::tf::test::check_bound((what), (measured), (bound), false, __FILE__, __LINE__)
// A named condition and what was seen (strings); printed either way.
#define CHECK_TRUE(what, ok, detail) ::tf::test::check_true((what), bool(ok), (detail), __FILE__, __LINE__)
// The text (a std::string) contains each of the parts that follow it.
#define CHECK_CONTAINS(text, ...) ::tf::test::check_contains((text), {__VA_ARGS__}, __FILE__, __LINE__, #text)
// Two strings equal.
#define CHECK_EQ_TEXT(a, b) ::tf::test::check_eq_text((a), (b), __FILE__, __LINE__, #a, #b)
// The expression throws tf::Error whose message contains `part`.
#define CHECK_THROWS_WITH(expr, part)                                                             \
    do {                                                                                          \
        bool threw_ = false;                                                                      \
        std::string message_ = "nothing";                                                         \
        try {                                                                                     \
            (void)(expr);                                                                         \
        } catch (const ::tf::Error& e_) {                                                         \
            threw_ = true;                                                                        \
            message_ = e_.what();                                                                 \
        } catch (const std::exception& e_) {                                                      \
            message_ = std::string("a non-tf::Error: ") + e_.what();                              \
        }                                                                                         \
        ::tf::test::check_throws(threw_, message_, (part), __FILE__, __LINE__, #expr);            \
    } while (0)
#define CHECK_THROWS(expr) CHECK_THROWS_WITH(expr, "")
