#pragma once
// What the tests in this folder share: CHECK macros with one failure count, a scratch directory, and
// `texfilter sample` runs (a lookups CSV in, colours and per-lookup stats out).
#include "texture/error.h"
#include "core/lookup_stats.h"
#include "reference/reference.h"

#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

namespace tf::test {

// ---------------------------------------------------------------------------------------------------
// Checks. Each CHECK* counts one check; a failed one counts a failure and prints
// "file:line: CHECK failed: <expression>  (<values>)" on stderr.

bool check(bool ok, const char* file, int line, const std::string& what, const std::string& values = "");
bool check_eq(double a, double b, const char* file, int line, const char* a_text, const char* b_text);
bool check_near(double a, double b, double eps, const char* file, int line, const char* what);
bool check_near(const glm::dvec4& a, const glm::dvec4& b, double eps, const char* file, int line, const char* what);
// threw: the expression threw a tf::Error; message: what it threw (any exception).
bool check_throws(bool threw, const std::string& message, const std::string& part, const char* file, int line,
                  const char* expr);

// Equal, or at most eps apart, in every component (NaN is never near).
bool near(double a, double b, double eps);
bool near(const glm::dvec4& a, const glm::dvec4& b, double eps);
double max_channel_diff(const glm::dvec4& a, const glm::dvec4& b);

// Largest channel difference between the 2x2 texels a bilinear lookup at uv reads on `level`, across (x)
// and down (y): what a rounded weight can move the result by, per unit of weight.
void texel_contrast(const Image& level, double u, double v, Wrap wrap, double& across, double& down);
std::string show(double x); // every digit (%.17g)
std::string show(const glm::dvec4& v);

// Counts a failure that is no CHECK (an exception, say) and prints "FAIL: why" on stderr.
void fail(const std::string& why);
// From here on print at most `limit` failure lines, counting the rest: one bad GPU run can fail
// thousands of lookups, and the first few say what went wrong.
void limit_failure_lines(int limit);
int checks();
int failures();
// Prints "all passed" or "FAILED"; returns the exit status.
int finish();

// ---------------------------------------------------------------------------------------------------
// The `texfilter` command.

// argv[1], the texfilter executable; anything else prints "usage: <usage>" and exits 2.
std::string texfilter_path_from_args(int argc, char** argv, const char* usage);

// A fresh directory texfilter-<name>-<pid> in the system's temp dir, removed when the process exits.
std::filesystem::path make_work_dir(const std::string& name);

// Random lookups: uv in [-1, 2], footprints 2^o / 256 with o in [-4, max_octave] (1/16 texel and up on a
// 256 texture), a random angle, the minor column shorter by 2^s, s in [0, max_stretch].
std::vector<Lookup> random_footprint_lookups(int count, unsigned seed, double max_octave, double max_stretch);

// The GPU reads lookups as float: the reference must see the same numbers.
Lookup as_float(const Lookup& l);
std::vector<Lookup> as_float(std::vector<Lookup> lookups);

// Header u,v,dudx,dvdx,dudy,dvdy, 9 digits a value: by default the values as float, the numbers the GPU
// sees; float_values false writes them as given (`--backend reference` reads them as double).
void write_lookups_csv(const std::filesystem::path& path, const std::vector<Lookup>& lookups,
                       bool float_values = true);

struct SampleResult {
    std::vector<glm::dvec4> colors;
    std::vector<LookupStats> stats; // with stats only
};

// Runs `texfilter sample --validate [--stats] FLAGS --lookups LOOKUPS_CSV -o OUT` (OUT in work) under a
// time limit and reads one row per lookup back. Throws tf::Error naming the command line if the command
// fails or its output is not that.
SampleResult run_sample(const std::string& texfilter, const std::filesystem::path& work, const std::string& flags,
                        const std::string& lookups_csv, bool stats);

} // namespace tf::test

// CHECK(expr) or CHECK(expr, values): values (a string) says what was compared.
#define CHECK(expr, ...) ::tf::test::check(bool(expr), __FILE__, __LINE__, #expr __VA_OPT__(, __VA_ARGS__))
// Compared as double (the values are counts, sizes and exact floats).
#define CHECK_EQ(a, b) ::tf::test::check_eq(double(a), double(b), __FILE__, __LINE__, #a, #b)
// Doubles or glm::dvec4s, every component within eps.
#define CHECK_NEAR(a, b, eps) \
    ::tf::test::check_near((a), (b), (eps), __FILE__, __LINE__, #a " ~= " #b " within " #eps)
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
