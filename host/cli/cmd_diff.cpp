#include "flags/cli_common.h"
#include "cli/commands.h"
#include "core/diff.h"
#include "texture/error.h"
#include "io/image_io.h"
#include "core/memory_budget.h"
#include "io/output_path.h"
#include <cstdio>
#include <limits>

namespace tf {

int run_diff(const std::vector<std::string>& argv)
{
    std::vector<FlagSpec> specs = {
        {"--fail", "X", "a pixel fails when a channel differs by more than X (default 1e-6)"},
        {"--failpercent", "P", "pass if at most P percent of pixels fail (default 0)"},
        {"--hardfail", "H", "fail if any channel differs by more than H (default: no limit)"},
        {"-o", "DIFF.png", "write |A-B| amplified 10x"},
        {"--memory-budget", "SIZE", "most host memory the two images may take (512M, 8G; default: half of physical "
                                    "memory); checked from the headers before decoding"},
        {"--help", "", "show this help"}};
    Args args = parse_args("diff", argv, specs, 2);
    if (args.has("--help")) {
        std::fputs(format_help("texfilter diff A B [--fail X] [--failpercent P] [--hardfail H] [-o DIFF.png]\n"
                               "exit status: 0 pass, 1 fail, 2 error",
                               specs)
                       .c_str(),
                   stdout);
        return 0;
    }
    if (args.positional.size() != 2)
        throw Error("diff: needs two images, A and B");
    DiffThresholds thresholds;
    thresholds.fail = args.get_double("--fail", 1e-6, 0.0, 1e30);
    thresholds.fail_percent = args.get_double("--failpercent", 0.0, 0.0, 100.0);
    thresholds.hard_fail = args.get_double("--hardfail", std::numeric_limits<double>::infinity(), 0.0,
                                           std::numeric_limits<double>::infinity());
    std::string out;
    if (args.has("-o"))
        out = checked_output_path(args.get("-o", ""), {".png", ".exr"}, args.positional);
    // Both images are held decoded, and the diff image beside them: check that before decoding either.
    const uint64_t budget = args.has("--memory-budget")
                                ? parse_flag(args, "--memory-budget", "", parse_byte_size)
                                : default_memory_budget();
    uint64_t need = 0;
    for (const std::string& path : args.positional) {
        const ImageHeader h = read_image_header(path, raw_image_max_dimension);
        need += estimate_texture_memory(h.width, h.height, false, TextureLoad::host).decode;
        if (need > budget)
            throw Error(path + ": a " + std::to_string(h.width) + "x" + std::to_string(h.height) +
                        " image; the two decoded images need " + format_bytes(need) + " or more, over the memory "
                        "budget of " + format_bytes(budget) + " (--memory-budget SIZE raises it)");
    }
    Image a = read_image_raw(args.positional[0]);
    Image b = read_image_raw(args.positional[1]);
    if (a.width != b.width || a.height != b.height)
        throw Error("image sizes differ: " + args.positional[0] + " is " + std::to_string(a.width) + "x" +
                    std::to_string(a.height) + ", " + args.positional[1] + " is " + std::to_string(b.width) +
                    "x" + std::to_string(b.height));
    DiffResult result = diff_images(a, b, thresholds);
    if (args.has("-o"))
        write_image(out, diff_image(a, b, 10.0));
    std::printf("%s\n", describe(result, thresholds).c_str());
    return result.pass ? 0 : 1;
}

} // namespace tf
