// The harness's own sample shader (shaders/harness/sample.comp.glsl: filter_select.glsl over the texfilter
// includes) compiled by Slang's slangc instead of glslang, run through `texfilter sample [--resource K]
// --spirv`, against the CPU reference: one case a family and kind, with the checks and bounds
// tests/test_resource_kinds.cpp applies to every resource kind (tests/sample_checks.cpp derives them), on the
// same lookups; each case runs the built-in (glslang) module of the kind through the same checks first, so
// both compilers are held to one standard.
//   sample.FAMILY                  the combined kind (sampler2D: Slang's Sampler2D)
//   sample_separate.FAMILY         texture2D + sampler (Slang's Texture2D + SamplerState: the includes read it
//                                  through common.glsl's tfi_slang_* wrappers of Load, GetDimensions and
//                                  SampleLevel), every manual family (the SAT's utexture2D tables too) and
//                                  the hardware-tap forms
//   sample_separate_array.FAMILY   texture2DArray + sampler, layer 2 of 4 (and 9: clamped to 3); a wrong
//                                  layer's reference must be caught on most lookups
//   *.hw-FILTER                    the hardware sampler through SampleGrad (textureGrad): no reference bound
//                                  (the sampler's own LOD and filtering); both modules issue the same image
//                                  instruction on the same uv and gradients from the same quad lanes, so the
//                                  device's answers must be equal bit for bit. lavapipe takes the footprint
//                                  from the quad (sample.comp.glsl), not from the gradient operands (a module
//                                  passing dUVdx twice gave the same bits): there this holds the uv, the
//                                  sampler and the image, and a device that honours the gradients holds them too.
//   spirv_check.built-in-kinds     `sample --spirv`'s interface check (host/vulkan/spirv_module.h) against the
//                                  built-in modules: each kind's own passes, and a module of a kind whose
//                                  texture binding differs (combined vs sampled, 2D vs 2D array) is refused.
//
// The modules come from the ctest fixtures slang.sample_spirv* (tests/slang_check.py: slangc -allow-glsl
// -target spirv -O0, spirv-val) in TF_SLANG_DIR; where those skipped (no slangc to be had here) each case
// says SKIP.
#include "sample_checks.h"
#include "reference/resources.h"
#include "support.h"
#include "texture/error.h"
#include "vulkan/pipelines.h"

#include <cstdio>
#include <filesystem>
#include <string>

using namespace tf;
using namespace tf::test::sample;

namespace {

const std::filesystem::path kDir = TF_SLANG_DIR;

// The slangc module of the kind (slang_check.py's VARIANTS), or "" after printing SKIP where the fixture
// could not have slangc.
std::string slang_module(Resource resource)
{
    if (std::filesystem::exists(kDir / "sample.skipped")) {
        std::printf("SKIP: this machine lacks slangc (tools/.venv cannot be made here; slang.sample_spirv says why)\n");
        return "";
    }
    const std::filesystem::path spv = kDir / (resource == Resource::separate         ? "sample_separate.spv"
                                              : resource == Resource::separate_array ? "sample_separate_array.spv"
                                                                                     : "sample.spv");
    CHECK(std::filesystem::exists(spv), spv.string() + " missing: its fixture slang.sample_spirv* failed (see its output)");
    return std::filesystem::exists(spv) ? spv.string() : "";
}

// The reference as if every lookup read layer `layer` of the case's chains (a wrong layer, for the array kind).
std::vector<glm::dvec4> reference_on_layer(const Case& c, int layer)
{
    ResourceOptions one = c.resource;
    one.layer = layer;
    return reference_sample_resource(chains_of(c), lookups(), c.options, one);
}

// The case with the built-in module, then with slangc's.
void check_both(Case c, bool stochastic = false)
{
    const std::string spv = slang_module(c.resource.resource);
    if (spv.empty())
        return;
    std::vector<std::vector<glm::dvec4>> wrongs;
    if (c.resource.resource == Resource::separate_array && !stochastic) { // check_stochastic has its own
        const int read = std::clamp(c.resource.layer, 0, c.resource.layers - 1);
        wrongs = {reference_on_layer(c, read == 0 ? 1 : 0), reference_on_layer(c, read == 3 ? 2 : read + 1)};
    }
    for (const std::string& extra : {std::string(), " --spirv " + spv}) {
        Case run = c;
        run.flags += extra;
        std::printf("%s:\n", extra.empty() ? "glslang (built in)" : "slangc");
        if (stochastic)
            tf::test::sample::check_stochastic(run);
        else
            check_case(run, wrongs);
    }
}

void check_family(Filter filter, Taps taps = Taps::manual) { check_both(make_case(Resource::combined, filter, taps)); }
void check_separate(Filter filter, Taps taps = Taps::manual) { check_both(make_case(Resource::separate, filter, taps)); }
void check_separate_array(Filter filter, Taps taps = Taps::manual, int layer = 2)
{
    check_both(make_case(Resource::separate_array, filter, taps, 4, layer));
}

// A hw-* filter: slangc's module answers as the built-in one, bit for bit (see the top), with the same counts.
void check_hardware(Resource resource, Filter filter)
{
    const std::string spv = slang_module(resource);
    if (spv.empty())
        return;
    const Case c = make_case(resource, filter);
    Case slang = c;
    slang.flags += " --spirv " + spv;
    const test::SampleResult built_in = gpu_run(c), slangc = gpu_run(slang);
    const std::string name = c.flags + resource_flags(c.resource);
    CHECK(built_in.colors.size() == lookups().size() && slangc.colors.size() == lookups().size(), name + ": row counts");
    if (built_in.colors.size() != lookups().size() || slangc.colors.size() != lookups().size())
        return;
    test::limit_failure_lines(8);
    size_t differ = 0, distinct = 0;
    for (size_t i = 0; i < lookups().size(); ++i) {
        const double error = test::max_channel_diff(slangc.colors[i], built_in.colors[i]);
        differ += error != 0.0;
        distinct += test::max_channel_diff(built_in.colors[i], built_in.colors[0]) > 1e-3;
        CHECK(error == 0.0, name + ": lookup " + std::to_string(i) + " slangc " + test::show(slangc.colors[i]) +
                                " glslang " + test::show(built_in.colors[i]));
        CHECK(slangc.stats[i].hardware_lookups == built_in.stats[i].hardware_lookups, name + ": lookup " +
                                                                                          std::to_string(i) + " counts");
    }
    // The lookups see the texture (not one constant answer the two modules could share by accident).
    CHECK(distinct >= lookups().size() / 2, name + ": only " + std::to_string(distinct) + " lookups differ from the first");
    std::printf("%-90s slangc vs glslang: %zu of %zu lookups differ; %zu differ from lookup 0\n", name.c_str(), differ,
                lookups().size(), distinct);
}

} // namespace

// The check's table (harness_variant.h's sample_pass_bindings) agrees with what each built-in variant
// declares (those run with the validation layers on), and tells the kinds apart. CPU only.
TEST_CASE("spirv_check.built-in-kinds")
{
    const Resource kinds[] = {Resource::combined, Resource::separate,       Resource::array, Resource::separate_array,
                              Resource::bindless, Resource::shadow,         Resource::atlas, Resource::virtual_texture};
    for (Resource module_kind : kinds) {
        const ShaderCode code = harness_variant(module_kind, bindless_texture_count).sample;
        const std::string bytes(reinterpret_cast<const char*>(code.words), code.bytes);
        for (Resource pass_kind : kinds) {
            const PassBinding a = sample_pass_bindings(module_kind).at(HARNESS_BINDING_TEXTURE);
            const PassBinding b = sample_pass_bindings(pass_kind).at(HARNESS_BINDING_TEXTURE);
            const bool same_texture = a.type == b.type && a.layered == b.layered;
            std::string refused;
            try {
                check_sample_spirv(bytes, to_string(module_kind) + ".spv", pass_kind);
            } catch (const Error& e) {
                refused = e.what();
            }
            const std::string what = "the built-in " + to_string(module_kind) + " module for --resource " +
                                     to_string(pass_kind) + ": " + (refused.empty() ? "accepted" : refused);
            if (module_kind == pass_kind)
                CHECK(refused.empty(), what);
            else if (!same_texture)
                CHECK(!refused.empty(), what);
            if (module_kind == Resource::combined && pass_kind == Resource::separate)
                std::printf("%s\n", what.c_str());
        }
    }
}

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

TEST_CASE("sample_separate.nearest") { check_separate(Filter::nearest); }
TEST_CASE("sample_separate.bilinear") { check_separate(Filter::bilinear); }
TEST_CASE("sample_separate.trilinear") { check_separate(Filter::trilinear); }
TEST_CASE("sample_separate.nearest-mip") { check_separate(Filter::nearest_mip); }
TEST_CASE("sample_separate.bilinear-mip") { check_separate(Filter::bilinear_mip); }
TEST_CASE("sample_separate.brilinear") { check_separate(Filter::brilinear); }
TEST_CASE("sample_separate.aniso") { check_separate(Filter::aniso); }
TEST_CASE("sample_separate.aniso-hardware-taps") { check_separate(Filter::aniso, Taps::hardware); }
TEST_CASE("sample_separate.ewa") { check_separate(Filter::ewa); }
TEST_CASE("sample_separate.ewa-hardware-taps") { check_separate(Filter::ewa, Taps::hardware); }
TEST_CASE("sample_separate.bspline") { check_separate(Filter::bspline); }
TEST_CASE("sample_separate.bspline-hardware-taps") { check_separate(Filter::bspline, Taps::hardware); }
TEST_CASE("sample_separate.catmull-rom") { check_separate(Filter::catmull_rom); }
TEST_CASE("sample_separate.catmull-rom-hardware-taps") { check_separate(Filter::catmull_rom, Taps::hardware); }
TEST_CASE("sample_separate.sat") { check_separate(Filter::sat); }
TEST_CASE("sample_separate.sat-assembly") { check_separate(Filter::sat_assembly); }
TEST_CASE("sample_separate.stochastic-bilinear") { check_both(make_case(Resource::separate, Filter::bilinear), true); }
TEST_CASE("sample_separate.stochastic-trilinear") { check_both(make_case(Resource::separate, Filter::trilinear), true); }
TEST_CASE("sample_separate.stochastic-aniso") { check_both(make_case(Resource::separate, Filter::aniso), true); }
TEST_CASE("sample_separate.stochastic-ewa") { check_both(make_case(Resource::separate, Filter::ewa), true); }
TEST_CASE("sample_separate.hw-nearest") { check_hardware(Resource::separate, Filter::hw_nearest); }
TEST_CASE("sample_separate.hw-bilinear") { check_hardware(Resource::separate, Filter::hw_bilinear); }
TEST_CASE("sample_separate.hw-trilinear") { check_hardware(Resource::separate, Filter::hw_trilinear); }
TEST_CASE("sample_separate.hw-aniso") { check_hardware(Resource::separate, Filter::hw_aniso); }

TEST_CASE("sample_separate_array.trilinear") { check_separate_array(Filter::trilinear); }
TEST_CASE("sample_separate_array.layer-clamped") { check_separate_array(Filter::bilinear, Taps::manual, 9); }
TEST_CASE("sample_separate_array.ewa") { check_separate_array(Filter::ewa); }
TEST_CASE("sample_separate_array.aniso-hardware-taps") { check_separate_array(Filter::aniso, Taps::hardware); }
TEST_CASE("sample_separate_array.catmull-rom-hardware-taps") { check_separate_array(Filter::catmull_rom, Taps::hardware); }
TEST_CASE("sample_separate_array.hw-trilinear") { check_hardware(Resource::separate_array, Filter::hw_trilinear); }
TEST_SUITE_END();
