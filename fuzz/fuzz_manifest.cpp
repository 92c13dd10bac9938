// libFuzzer target: the golden manifest parser (host/cli/golden.cpp), from memory. Asserts: only tf::Error
// escapes, and every message starts with the file's name and a line number; accepted cases have unique
// names, a size in [2, 4096]², thresholds in their ranges and sampler options in theirs.
#include "texture/error.h"
#include "fuzz_common.h"
#include "cli/golden.h"

#include <cctype>
#include <cstdint>
#include <set>
#include <sstream>

namespace {
const std::string name = "fuzz-manifest.txt";
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    std::vector<tf::GoldenCase> cases;
    try {
        cases = tf::parse_manifest(in, name);
    } catch (const tf::Error& e) {
        const std::string message = e.what();
        FUZZ_CHECK(message.rfind(name + ":", 0) == 0 && message.size() > name.size() + 1 &&
                       std::isdigit(static_cast<unsigned char>(message[name.size() + 1])),
                   message);
        return 0;
    }
    std::set<std::string> names;
    for (const tf::GoldenCase& c : cases) {
        FUZZ_CHECK(!c.name.empty() && names.insert(c.name).second, c.name);
        FUZZ_CHECK(c.width >= 2 && c.width <= 4096 && c.height >= 2 && c.height <= 4096);
        FUZZ_CHECK(c.thresholds.fail >= 0.0 && c.thresholds.fail <= 1.0);
        FUZZ_CHECK(c.thresholds.fail_percent >= 0.0 && c.thresholds.fail_percent <= 100.0);
        FUZZ_CHECK(c.thresholds.hard_fail >= 0.0 && c.thresholds.hard_fail <= 1.0);
        FUZZ_CHECK(!c.texture.name_or_path.empty());
        FUZZ_CHECK(c.texture.procedural_size >= 1 && c.texture.procedural_size <= tf::max_texture_dimension);
        tf::fuzz::check_sampler_options(c.sampler);
    }
    return 0;
}
