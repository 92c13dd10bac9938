// texfilter: render test scenes, run point lookups, compare images, check goldens.
#include "cli/commands.h"
#include "core/escape.h"
#include "flags/cli_common.h"
#include "texture/error.h"
#include "io/temporary_files.h"
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

namespace {

const char* usage = "usage: texfilter COMMAND [options]\n"
                    "\n"
                    "commands:\n"
                    "  info      list Vulkan devices, their filtering limits, and the one texfilter would use\n"
                    "  render    render a test scene with a filter (GPU or CPU reference) to PNG/EXR/PFM\n"
                    "  sample    filter point lookups from a CSV file to a CSV of colours\n"
                    "  diff      compare two images (idiff-style thresholds)\n"
                    "  golden    render every golden case on the GPU and compare; --update re-blesses from the CPU reference\n"
                    "  bench     time, count and score every scene x filter against ground truth (JSON, CSV, images)\n"
                    "  build     a texture's MIP chain and summed-area table, built by the device (or host), to files\n"
                    "  view      a window to fly over the scenes, compare filters side by side, see LOD and anisotropy\n"
                    "\n"
                    "texfilter COMMAND --help shows a command's options.\n";

// Every message leaves through here: a control byte from a flag, a script line or a file name is written as
// \xNN, so that no input can move the cursor or forge a line of its own.
void print_error(const std::string& message)
{
    std::fprintf(stderr, "texfilter: %s\n", tf::escape_bytes(message, tf::Escape::control).c_str());
}

} // namespace

int main(int argc, char** argv)
{
    tf::install_signal_cleanup(); // before any thread: Ctrl-C must not leave temporaries behind
    if (argc < 2) {
        std::fputs(usage, stderr);
        return 2;
    }
    std::string command = argv[1];
    std::vector<std::string> rest(argv + 2, argv + argc);
    try {
        tf::validate_from_environment(); // TEXFILTER_VALIDATE=yes is refused by every command, not ignored
        if (command == "--help" || command == "-h" || command == "help") {
            std::fputs(usage, stdout);
            return 0;
        }
        if (command == "info")
            return tf::run_info(rest);
        if (command == "render")
            return tf::run_render(rest);
        if (command == "sample")
            return tf::run_sample(rest);
        if (command == "diff")
            return tf::run_diff(rest);
        if (command == "golden")
            return tf::run_golden(rest);
        if (command == "bench")
            return tf::run_bench(rest);
        if (command == "build")
            return tf::run_build(rest);
        if (command == "view")
            return tf::run_view(rest);
        print_error("unknown command '" + command + "'");
        std::fprintf(stderr, "\n%s", usage);
        return 2;
    } catch (const tf::Error& e) {
        print_error(e.what());
        return 2;
    } catch (const std::filesystem::filesystem_error& e) {
        // A file system call that a command did not check first: still a message about a path, not a bug report.
        print_error(e.path1().string() + ": " + e.code().message());
        return 2;
    } catch (const std::exception& e) {
        print_error(std::string("internal error: ") + e.what());
        return 2;
    }
}
