// The harness's own sample shader (shaders/harness/sample.comp.glsl: filter_select.glsl over the texfilter
// includes, the combined kind) compiled by Slang's slangc instead of glslang, run through
// `texfilter sample --spirv`, against the CPU reference: one case a family, sample.FAMILY (ctest
// slang.sample.FAMILY), with the checks and bounds tests/test_resource_kinds.cpp applies to every resource
// kind (tests/sample_checks.cpp derives them), on the same lookups; each case runs the built-in (glslang)
// module through the same checks first, so both compilers are held to one standard.
//
// The module comes from the ctest fixture slang.sample_spirv (tests/slang_check.py: slangc -allow-glsl
// -target spirv -O0, spirv-val) in TF_SLANG_DIR; where that fixture skipped (no slangc to be had here) each
// case says SKIP.
#include "sample_checks.h"
#include "support.h"

#include <cstdio>
#include <filesystem>
#include <string>

using namespace tf;
using namespace tf::test::sample;

namespace {

const std::filesystem::path kDir = TF_SLANG_DIR;

// The slangc module's path, or "" after printing SKIP where the fixture could not have slangc.
std::string slang_module()
{
    if (std::filesystem::exists(kDir / "sample.skipped")) {
        std::printf("SKIP: this machine lacks slangc (tools/.venv cannot be made here; slang.sample_spirv says why)\n");
        return "";
    }
    const std::filesystem::path spv = kDir / "sample.spv";
    CHECK(std::filesystem::exists(spv), spv.string() + " missing: the fixture slang.sample_spirv failed (see its output)");
    return std::filesystem::exists(spv) ? spv.string() : "";
}

// The case with the built-in module, then with slangc's.
void check_both(Case c, bool stochastic = false)
{
    const std::string spv = slang_module();
    if (spv.empty())
        return;
    for (const std::string& extra : {std::string(), " --spirv " + spv}) {
        Case run = c;
        run.flags += extra;
        std::printf("%s:\n", extra.empty() ? "glslang (built in)" : "slangc");
        if (stochastic)
            tf::test::sample::check_stochastic(run);
        else
            check_case(run);
    }
}

void check_family(Filter filter, Taps taps = Taps::manual) { check_both(make_case(Resource::combined, filter, taps)); }

} // namespace

TEST_SUITE_BEGIN("gpu");
TEST_CASE("sample.nearest") { check_family(Filter::nearest); }
TEST_CASE("sample.bilinear") { check_family(Filter::bilinear); }
TEST_CASE("sample.trilinear") { check_family(Filter::trilinear); }
TEST_CASE("sample.nearest-mip") { check_family(Filter::nearest_mip); }
TEST_CASE("sample.bilinear-mip") { check_family(Filter::bilinear_mip); }
TEST_CASE("sample.brilinear") { check_family(Filter::brilinear); }
TEST_CASE("sample.aniso") { check_family(Filter::aniso); }
TEST_CASE("sample.aniso-hardware-taps") { check_family(Filter::aniso, Taps::hardware); }
TEST_CASE("sample.ewa") { check_family(Filter::ewa); }
TEST_CASE("sample.ewa-hardware-taps") { check_family(Filter::ewa, Taps::hardware); }
TEST_CASE("sample.bspline") { check_family(Filter::bspline); }
TEST_CASE("sample.catmull-rom") { check_family(Filter::catmull_rom); }
TEST_CASE("sample.stochastic-bilinear") { check_both(make_case(Resource::combined, Filter::bilinear), true); }
TEST_CASE("sample.stochastic-trilinear") { check_both(make_case(Resource::combined, Filter::trilinear), true); }
TEST_CASE("sample.stochastic-aniso") { check_both(make_case(Resource::combined, Filter::aniso), true); }
TEST_CASE("sample.stochastic-ewa") { check_both(make_case(Resource::combined, Filter::ewa), true); }
TEST_SUITE_END();
