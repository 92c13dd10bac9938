#include "support.h"
#include "io/lookups_csv.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <system_error>

#include <glm/common.hpp>
#include <sys/wait.h>
#include <unistd.h>

namespace tf::test {

namespace fs = std::filesystem;

namespace {

int g_checks = 0;
int g_failures = 0;
int g_lines_left = INT_MAX; // failure lines still to print

// A hung shader fails its test instead of blocking it.
constexpr int kSampleSeconds = 120;

void print_failure(const std::string& line)
{
    std::fflush(stdout); // keep the failure next to the result lines around it
    std::fprintf(stderr, "%s\n", line.c_str());
}

} // namespace

// ---------------------------------------------------------------------------------------------------
// Checks.

bool check(bool ok, const char* file, int line, const std::string& what, const std::string& values)
{
    ++g_checks;
    if (ok)
        return true;
    ++g_failures;
    if (g_lines_left > 0) {
        --g_lines_left;
        print_failure(std::string(file) + ":" + std::to_string(line) + ": CHECK failed: " + what +
                      (values.empty() ? "" : "  (" + values + ")"));
    }
    return false;
}

bool check_eq(double a, double b, const char* file, int line, const char* a_text, const char* b_text)
{
    const bool ok = a == b;
    return check(ok, file, line, std::string(a_text) + " == " + b_text, ok ? "" : show(a) + " vs " + show(b));
}

bool check_near(double a, double b, double eps, const char* file, int line, const char* what)
{
    const bool ok = near(a, b, eps);
    return check(ok, file, line, what, ok ? "" : show(a) + " vs " + show(b));
}

bool check_near(const glm::dvec4& a, const glm::dvec4& b, double eps, const char* file, int line, const char* what)
{
    const bool ok = near(a, b, eps);
    return check(ok, file, line, what, ok ? "" : show(a) + " vs " + show(b));
}

bool check_throws(bool threw, const std::string& message, const std::string& part, const char* file, int line,
                  const char* expr)
{
    const bool ok = threw && message.find(part) != std::string::npos;
    return check(ok, file, line, "throws tf::Error containing \"" + part + "\": " + expr,
                 ok ? "" : threw ? "threw \"" + message + "\"" : "threw " + message);
}

bool near(double a, double b, double eps) { return a == b || std::fabs(a - b) <= eps; }

bool near(const glm::dvec4& a, const glm::dvec4& b, double eps)
{
    return near(a.x, b.x, eps) && near(a.y, b.y, eps) && near(a.z, b.z, eps) && near(a.w, b.w, eps);
}

double max_channel_diff(const glm::dvec4& a, const glm::dvec4& b)
{
    const glm::dvec4 d = glm::abs(a - b);
    return std::max(std::max(d.x, d.y), std::max(d.z, d.w));
}

std::string show(double x)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
}

std::string show(const glm::dvec4& v)
{
    return "(" + show(v.x) + ", " + show(v.y) + ", " + show(v.z) + ", " + show(v.w) + ")";
}

void fail(const std::string& why)
{
    ++g_failures;
    print_failure("FAIL: " + why);
}

void limit_failure_lines(int limit) { g_lines_left = limit; }

int checks() { return g_checks; }

int failures() { return g_failures; }

int finish()
{
    std::printf("%s\n", g_failures ? "FAILED" : "all passed");
    return g_failures ? 1 : 0;
}

// ---------------------------------------------------------------------------------------------------
// The `texfilter` command.

std::string texfilter_path_from_args(int argc, char** argv, const char* usage)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s\n", usage);
        std::exit(2);
    }
    return argv[1];
}

fs::path make_work_dir(const std::string& name)
{
    // Destroyed at exit, std::exit included: every directory made goes with it.
    static struct Cleanup {
        std::vector<fs::path> dirs;
        ~Cleanup()
        {
            std::error_code ec;
            for (const fs::path& dir : dirs)
                fs::remove_all(dir, ec);
        }
    } cleanup;
    const fs::path dir = fs::temp_directory_path() / ("texfilter-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir); // left by an earlier process with the same id
    fs::create_directories(dir);
    cleanup.dirs.push_back(dir);
    return dir;
}

namespace {

// Through a volatile: GCC 12.2 at -O2/-O3 vectorises six double -> float -> double conversions in a row
// and leaves the last two (dudy, dvdy) unrounded.
double round_to_float(double x)
{
    volatile float f = float(x);
    return f;
}

} // namespace

std::vector<Lookup> random_footprint_lookups(int count, unsigned seed, double max_octave, double max_stretch)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uv(-1.0, 2.0), angle(0.0, 6.283185307179586), octaves(-4.0, max_octave),
        stretch(0.0, max_stretch);
    std::vector<Lookup> lookups;
    for (int i = 0; i < count; ++i) {
        const double size = std::exp2(octaves(rng)) / 256.0;
        const double a = angle(rng), ratio = std::exp2(stretch(rng));
        lookups.push_back({uv(rng), uv(rng), size * std::cos(a), size * std::sin(a), -size / ratio * std::sin(a),
                           size / ratio * std::cos(a)});
    }
    return lookups;
}

Lookup as_float(const Lookup& l)
{
    return {round_to_float(l.u),    round_to_float(l.v),    round_to_float(l.dudx),
            round_to_float(l.dvdx), round_to_float(l.dudy), round_to_float(l.dvdy)};
}

std::vector<Lookup> as_float(std::vector<Lookup> lookups)
{
    for (Lookup& l : lookups)
        l = as_float(l);
    return lookups;
}

void write_lookups_csv(const fs::path& path, const std::vector<Lookup>& lookups, bool float_values)
{
    std::ofstream out(path);
    out << "u,v,dudx,dvdx,dudy,dvdy\n";
    out.precision(9);
    for (const Lookup& row : lookups) {
        const Lookup l = float_values ? as_float(row) : row;
        out << l.u << "," << l.v << "," << l.dudx << "," << l.dvdx << "," << l.dudy << "," << l.dvdy << "\n";
    }
    if (!out.flush())
        throw Error("cannot write " + path.string());
}

namespace {

// "exit 2", or how std::system's command ended otherwise.
std::string exit_text(int status)
{
    if (status != -1 && WIFEXITED(status))
        return "exit " + std::to_string(WEXITSTATUS(status));
    return "status " + std::to_string(status);
}

// The r,g,b,a[,fetches,hw_lookups] rows `sample -o` wrote; `command` names them in errors.
SampleResult read_colors_csv(const std::string& path, bool stats, const std::string& command)
{
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    if (line != (stats ? "r,g,b,a,fetches,hw_lookups" : "r,g,b,a"))
        throw Error("unexpected header '" + line + "' from " + command);
    SampleResult result;
    while (std::getline(in, line)) {
        glm::dvec4 c;
        LookupStats s;
        const int n = std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%u,%u", &c.r, &c.g, &c.b, &c.a, &s.texel_fetches,
                                  &s.hardware_lookups);
        if (n != (stats ? 6 : 4))
            throw Error("bad row '" + line + "' from " + command);
        result.colors.push_back(c);
        if (stats)
            result.stats.push_back(s);
    }
    return result;
}

} // namespace

SampleResult run_sample(const std::string& texfilter, const fs::path& work, const std::string& flags,
                        const std::string& lookups_csv, bool stats)
{
    static int runs = 0; // one output file a run, kept until the work dir goes
    const std::string out = (work / ("sample-" + std::to_string(runs++) + ".csv")).string();
    const std::string command = "timeout " + std::to_string(kSampleSeconds) + " '" + texfilter +
                                "' sample --validate " + (stats ? "--stats " : "") + flags + " --lookups '" +
                                lookups_csv + "' -o '" + out + "' > /dev/null";
    if (const int status = std::system(command.c_str()); status != 0)
        throw Error("command failed (" + exit_text(status) + "): " + command);
    SampleResult result = read_colors_csv(out, stats, command);
    const size_t lookups = read_lookups_csv(lookups_csv).size();
    if (result.colors.size() != lookups)
        throw Error(std::to_string(result.colors.size()) + " rows for " + std::to_string(lookups) + " lookups from " +
                    command);
    return result;
}

void texel_contrast(const Image& level, double u, double v, Wrap wrap, double& across, double& down)
{
    double x = u * level.width - 0.5, y = v * level.height - 0.5;
    long long i0 = (long long)std::floor(x), j0 = (long long)std::floor(y);
    glm::dvec4 t[2][2];
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i)
            t[j][i] = glm::dvec4(level.at(wrap_texel(i0 + i, level.width, wrap), wrap_texel(j0 + j, level.height, wrap)));
    across = std::max(max_channel_diff(t[0][0], t[0][1]), max_channel_diff(t[1][0], t[1][1]));
    down = std::max(max_channel_diff(t[0][0], t[1][0]), max_channel_diff(t[0][1], t[1][1]));
}

} // namespace tf::test
