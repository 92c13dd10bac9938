// xwd_compare DUMP.xwd SHOT.png [--at X,Y] [--tolerance N]
//
// The viewer's "the frame really reached the window" check: the region at X,Y (default 0,0) of an X-side
// capture (`xwd -root` of Xvfb, read by tools/xwd.h), of SHOT.png's size, against SHOT.png's RGB (8-bit, as
// stored; alpha ignored). Prints the largest channel difference (0..255) and how many pixels differ.
// Exit 0: max difference <= N (default 0); 1: more; 2: bad input (a message naming it on stderr).
#include "io/image_io.h"
#include "texture/error.h"
#include "xwd.h"
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

namespace {

int parse_int(const std::string& text, const std::string& what, int min, int max)
{
    int value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || value < min || value > max)
        throw tf::Error("bad " + what + " '" + text + "' (expected an integer in [" + std::to_string(min) + ", " +
                        std::to_string(max) + "])");
    return value;
}

int run(int argc, char** argv)
{
    std::string usage = "usage: xwd_compare DUMP.xwd SHOT.png [--at X,Y] [--tolerance N]";
    std::vector<std::string> files;
    int at_x = 0, at_y = 0, tolerance = 0;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg == "--at" || arg == "--tolerance") {
            if (i + 1 >= argc)
                throw tf::Error(arg + " needs a value (" + usage + ")");
            std::string value = argv[++i];
            if (arg == "--tolerance") {
                tolerance = parse_int(value, "--tolerance", 0, 255);
            } else {
                size_t comma = value.find(',');
                if (comma == std::string::npos)
                    throw tf::Error("bad --at '" + value + "' (expected X,Y)");
                at_x = parse_int(value.substr(0, comma), "--at X", 0, tf::xwd_max_side);
                at_y = parse_int(value.substr(comma + 1), "--at Y", 0, tf::xwd_max_side);
            }
        } else if (arg.starts_with("-")) {
            throw tf::Error("unknown flag " + arg + " (" + usage + ")");
        } else {
            files.push_back(arg);
        }
    }
    if (files.size() != 2)
        throw tf::Error(usage);
    tf::XwdImage dump = tf::read_xwd(files[0]);
    tf::Image shot = tf::read_image_raw(files[1]);
    if (at_x + shot.width > dump.width || at_y + shot.height > dump.height)
        throw tf::Error(files[1] + " (" + std::to_string(shot.width) + "x" + std::to_string(shot.height) + ") at " +
                        std::to_string(at_x) + "," + std::to_string(at_y) + " does not fit in " + files[0] + " (" +
                        std::to_string(dump.width) + "x" + std::to_string(dump.height) + ")");
    int max_difference = 0, first_x = -1, first_y = -1;
    long long differing = 0;
    for (int y = 0; y < shot.height; ++y)
        for (int x = 0; x < shot.width; ++x) {
            glm::vec4 expected = shot.at(x, y);
            glm::u8vec3 got = dump.at(at_x + x, at_y + y);
            int difference = 0;
            for (int c = 0; c < 3; ++c)
                difference = std::max(difference, std::abs(int(got[c]) - int(std::lround(expected[c] * 255.0f))));
            if (difference > 0 && differing++ == 0) {
                first_x = x;
                first_y = y;
            }
            max_difference = std::max(max_difference, difference);
        }
    std::printf("max channel difference %d, %lld of %d pixels differ", max_difference, differing,
                shot.width * shot.height);
    if (differing > 0)
        std::printf(" (first at %d,%d of %s)", first_x, first_y, files[1].c_str());
    std::printf("; tolerance %d: %s\n", tolerance, max_difference <= tolerance ? "PASS" : "FAIL");
    return max_difference <= tolerance ? 0 : 1;
}

} // namespace

int main(int argc, char** argv)
{
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "xwd_compare: %s\n", e.what());
        return 2;
    }
}
