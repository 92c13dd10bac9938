#include "support.h"
#include "cli/commands.h"
#include "io/lookups_csv.h"
#include "vulkan/device.h"

#include <algorithm>
#include <climits>
#include <cerrno> // program_invocation_short_name
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <system_error>
#include <utility>

#include <glm/common.hpp>
#include <sys/wait.h>
#include <unistd.h>

namespace tf::test {

namespace fs = std::filesystem;

namespace {

// The check reporter's own state, as doctest keeps its own: the running test case's failed checks and how
// many more it may report (limit_failure_lines), set back by the listener as each case starts; the case's
// name; and whether main was asked to list the named checks. No test reads or writes these but through
// the functions declared in support.h.
int g_failures = 0;
int g_lines_left = INT_MAX;
std::string g_case;         // the running test case's name
bool g_listing_checks = false;

// A hung shader fails its test instead of blocking it.
constexpr int kSampleSeconds = 120;

// Every test case starts with a clean count and no limit, and ends saying what it did not show.
struct FailureLimitListener : tf::test::QuietReporter {
    explicit FailureLimitListener(const doctest::ContextOptions&) {}
    void test_case_start(const doctest::TestCaseData& data) override
    {
        g_case = data.m_name;
        g_failures = 0;
        g_lines_left = INT_MAX;
    }
    void test_case_end(const doctest::CurrentTestCaseStats&) override
    {
        if (g_lines_left < 0)
            std::fprintf(stderr, "... and %d more failed checks not shown\n", -g_lines_left);
    }
};
DOCTEST_REGISTER_LISTENER("failure_limit", 1, FailureLimitListener);

} // namespace

// ---------------------------------------------------------------------------------------------------
// Checks.

bool check(bool ok, const char* file, int line, const std::string& what, const std::string& values)
{
    if (!ok) {
        ++g_failures;
        if (g_lines_left-- <= 0)
            return false; // counted (the case has already failed on the ones shown), not reported
    }
    // One doctest assertion at the caller's place: what was checked and, failed, the values compared.
    doctest::detail::ResultBuilder result(doctest::assertType::DT_CHECK, file, line, what.c_str());
    result.m_failed = !ok;
    if (!ok)
        result.m_decomp = values.c_str();
    if (result.log())
        DOCTEST_BREAK_INTO_DEBUGGER();
    result.react();
    return ok;
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

bool check_bound(const std::string& what, double measured, double bound, bool upper, const char* file, int line)
{
    const bool ok = upper ? measured <= bound : measured >= bound; // NaN fails
    std::printf("%-4s %-72s %.4g (%s %.4g)\n", ok ? "ok" : "FAIL", what.c_str(), measured, upper ? "bound" : "at least",
                bound);
    return check(ok, file, line, what,
                 "measured " + show(measured) + (upper ? ", bound " : ", at least ") + show(bound));
}

bool check_true(const std::string& what, bool ok, const std::string& detail, const char* file, int line)
{
    std::printf("%-4s %-72s %s\n", ok ? "ok" : "FAIL", what.c_str(), detail.c_str());
    return check(ok, file, line, what, detail);
}

bool check_contains(const std::string& text, std::initializer_list<std::string> parts, const char* file, int line,
                    const char* text_expr)
{
    std::string missing;
    for (const std::string& part : parts)
        if (text.find(part) == std::string::npos)
            missing += (missing.empty() ? "\"" : ", \"") + part + "\"";
    return check(missing.empty(), file, line, std::string(text_expr) + " contains every part",
                 "\"" + text + "\" lacks " + missing);
}

bool check_eq_text(const std::string& a, const std::string& b, const char* file, int line, const char* a_text,
                   const char* b_text)
{
    const bool ok = a == b;
    return check(ok, file, line, std::string(a_text) + " == " + b_text, ok ? "" : "\"" + a + "\" vs \"" + b + "\"");
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

void limit_failure_lines(int limit) { g_lines_left = limit; }

std::string check_id(const std::string& name)
{
    std::string id;
    for (char c : name) {
        const bool keep = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
        if (c >= 'A' && c <= 'Z')
            id += char(c - 'A' + 'a');
        else if (keep)
            id += c;
        else if (!id.empty() && id.back() != '-')
            id += '-';
    }
    while (!id.empty() && id.back() == '-')
        id.pop_back();
    return id;
}

void set_listing_checks() { g_listing_checks = true; }

void named_check(const std::string& name, const std::function<std::string()>& body)
{
    const std::string id = check_id(name);
    if (listing_checks()) {
        list_check(id);
        return;
    }
    DOCTEST_SUBCASE(id.c_str())
    {
        const int failures_before = failures();
        limit_failure_lines(8); // the first few of a check are enough to see what went wrong
        std::string detail;
        try {
            detail = body();
        } catch (const std::exception& e) {
            detail = std::string("exception: ") + e.what();
            CHECK(!"the check threw", name + ": " + detail);
        }
        const bool failed = failures() > failures_before;
        std::printf("%-58s %s%s%s\n", name.c_str(), failed ? "FAIL" : "PASS", detail.empty() ? "" : "  ",
                    detail.c_str());
        std::fflush(stdout);
    }
}

bool listing_checks() { return g_listing_checks; }

void list_check(const std::string& id) { std::printf("tf-check\t%s\t%s\n", g_case.c_str(), id.c_str()); }

int failures() { return g_failures; }

// ---------------------------------------------------------------------------------------------------
// The device and the `texfilter` command.

std::string texfilter_path()
{
    const char* env = std::getenv("TEXFILTER_EXE");
    return env && *env ? env : TF_TEXFILTER_EXE;
}

std::string test_device()
{
    const char* env = std::getenv("TEXFILTER_TEST_DEVICE");
    return env ? env : "";
}

ContextOptions test_context_options()
{
    ContextOptions options;
    options.device = test_device();
    options.validate = true;
    return options;
}

const DeviceInfo& test_device_info()
{
    static const DeviceInfo info = [] {
        // destroy_instance gives volk's entry points back to a context the test made before this one (they
        // would otherwise be this instance's, destroyed: a crash at that context's end).
        VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
        VkInstance instance = create_instance(false, &messenger);
        const std::vector<DeviceInfo> devices = list_devices(instance);
        const DeviceInfo chosen = devices[size_t(select_device(devices, test_device()))];
        destroy_instance(instance);
        return chosen;
    }();
    return info;
}

namespace {
std::vector<std::function<void()>>& end_of_run_tasks()
{
    static std::vector<std::function<void()>> tasks;
    return tasks;
}
} // namespace

void at_end_of_run(std::function<void()> task) { end_of_run_tasks().push_back(std::move(task)); }

void run_end_of_run()
{
    std::vector<std::function<void()>>& tasks = end_of_run_tasks();
    while (!tasks.empty()) {
        std::function<void()> task = std::move(tasks.back());
        tasks.pop_back();
        task();
    }
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

const fs::path& work_dir()
{
    static const fs::path dir = make_work_dir(program_invocation_short_name);
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

std::vector<Lookup> random_footprint_lookups(int count, unsigned seed, const FootprintRanges& r)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uv(r.uv_min, r.uv_max), angle(0.0, 6.283185307179586),
        octaves(r.octave_min, r.octave_max), stretch(0.0, r.max_stretch), shear(-r.max_shear, r.max_shear);
    std::vector<Lookup> lookups;
    for (int i = 0; i < count; ++i) {
        const double size = std::exp2(octaves(rng)) / r.texture_size;
        const double a = angle(rng);
        const double ratio = r.max_stretch > 0 ? std::exp2(stretch(rng)) : 1.0;
        const double minor = size / ratio;
        double minor_u = -minor * std::sin(a), minor_v = minor * std::cos(a); // a right angle from the major
        if (r.max_shear > 0) {
            const double b = a + 1.5707963267948966 + shear(rng);
            minor_u = minor * std::cos(b);
            minor_v = minor * std::sin(b);
        }
        const double u = uv(rng), v = uv(rng);
        lookups.push_back({u, v, size * std::cos(a), size * std::sin(a), minor_u, minor_v});
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

void write_lookups_csv(const fs::path& path, const std::vector<Lookup>& lookups, bool float_values, int digits)
{
    std::ofstream out(path);
    out << "u,v,dudx,dvdx,dudy,dvdy\n";
    out.precision(digits);
    for (const Lookup& row : lookups) {
        const Lookup l = float_values ? as_float(row) : row;
        out << l.u << "," << l.v << "," << l.dudx << "," << l.dvdx << "," << l.dudy << "," << l.dvdy << "\n";
    }
    if (!out.flush())
        throw Error("cannot write " + path.string());
}

fs::path new_file_in(const fs::path& dir, const std::string& prefix, const std::string& suffix)
{
    std::string name = (dir / (prefix + "XXXXXX" + suffix)).string();
    const int fd = ::mkstemps(name.data(), int(suffix.size()));
    if (fd < 0)
        throw Error("cannot make a file " + name);
    ::close(fd);
    return name;
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

std::vector<std::string> shell_words(const std::string& line)
{
    std::vector<std::string> words;
    std::string word;
    bool in_word = false, quoted = false;
    for (size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '\'')
                quoted = false;
            else
                word += c;
        } else if (c == '\'') {
            quoted = in_word = true;
        } else if (c == '\\' && i + 1 < line.size()) {
            word += line[++i];
            in_word = true;
        } else if (c == ' ') {
            if (in_word)
                words.push_back(word);
            word.clear();
            in_word = false;
        } else {
            word += c;
            in_word = true;
        }
    }
    if (in_word)
        words.push_back(word);
    return words;
}

SampleResult run_sample(const std::string& flags, const std::string& lookups_csv, bool stats)
{
    std::vector<std::string> argv = shell_words(flags);
    argv.push_back("--validate");
    if (!test_device().empty())
        argv.insert(argv.end(), {"--device", test_device()});
    if (stats)
        argv.push_back("--stats");
    const std::vector<Lookup> lookups = read_lookups_csv(lookups_csv);
    SampleOutput output;
    try {
        output = sample_lookups(argv, lookups);
    } catch (const std::exception& e) {
        throw Error("sample " + flags + " (in process): " + e.what());
    }
    if (output.colors.size() != lookups.size() || (stats && output.stats.size() != lookups.size()))
        throw Error(std::to_string(output.colors.size()) + " colours for " + std::to_string(lookups.size()) +
                    " lookups from sample " + flags);
    return {std::move(output.colors), std::move(output.stats)};
}

SampleResult run_sample_command(const std::string& flags, const std::string& lookups_csv, bool stats)
{
    const std::string out = new_file_in(work_dir(), "sample-", ".csv").string();
    const std::string device = test_device().empty() ? "" : "--device '" + test_device() + "' ";
    const std::string command = "timeout " + std::to_string(kSampleSeconds) + " '" + texfilter_path() +
                                "' sample --validate " + device + (stats ? "--stats " : "") + flags + " --lookups '" +
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
