// Texel sources (`sample --resource atlas`, `--resource virtual`; core/texel_sources.h, docs/API.md "Texel
// sources"): the texture as one tile of an atlas, or as shuffled pages of a physical texture found through a
// page table, read by the includes' TF_SOURCE overloads.
//
// The layouts (CPU): the atlas holds the tile's own levels at origin >> l and other content around it; the
// page table maps every page of every level to a distinct place, and the pages really are shuffled; both
// read back (source_fetch, the shader's addressing) as the texture itself, bit for bit.
//
// Every manual family and wrap mode, on a non-power-of-two, non-square texture (45 x 29: levels 45x29,
// 22x14, 11x7, 5x3, 2x1, 1x1, so partial pages and odd halvings), with lookups whose footprints reach the
// tile's edges and wrap (centres near u or v = 0 and 1, footprints up to 64 texels):
// - GPU: atlas and virtual equal combined EXACTLY, colour and fetch count. The bound is zero because the
//   three variants compile the same GLSL filter code (texfilter's sampler2D forms and its TF_SOURCE forms are
//   one template instantiated per kind), run the same float operations in the same order on the same
//   inputs, and texelFetch returns a stored RGBA32F texel unchanged whichever image and coordinate it reads:
//   level sizes and counts are integers (textureSize / textureQueryLevels there, the words here), equal.
//   Any difference is a wrong texel (a bleed, a wrong page, an off-by-one level origin), never rounding.
// - Reference (`--backend reference`): atlas and virtual equal combined exactly (the texture read back
//   through the same addressing, then the ordinary reference).
// It can fail: the hardware sampler on the atlas at the tile's uv (hw-trilinear, what an engine does
// without TF_SOURCE) differs from the tile alone on most lookups near the edges, on both backends.
#include "core/texel_sources.h"
#include "io/pfm.h"
#include "reference/render.h"
#include "reference/resources.h"
#include "support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>

using namespace tf;
using tf::test::max_channel_diff;

namespace {

constexpr int kWidth = 45, kHeight = 29;

// Distinct texels (a hash of x and y per channel), alpha 1 (what a PFM holds).
Image texture_level0()
{
    Image image = make_image(kWidth, kHeight);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            image.at(x, y) = glm::vec4(float((x * 7 + y * 3) % 17) / 16.0f, float((x * 5 + y * 11) % 13) / 12.0f,
                                       float((x + 2 * y) % 5) / 4.0f, 1.0f);
    return image;
}

const MipChain& texture()
{
    static const MipChain chain = build_mip_chain(texture_level0());
    return chain;
}

struct Work {
    std::filesystem::path dir;
    std::string texture_path, lookups_path;
};

// 480 lookups: a third of the centres within 0.15 of u = 0 or 1 (v in [0, 1)), a third the same in v, a
// third anywhere in [-1, 2]; footprints 1/4 to 64 level-0 texels, up to 4:1, sheared, at any angle.
const std::vector<Lookup>& lookups()
{
    static const std::vector<Lookup> all = [] {
        std::vector<Lookup> ls = test::random_footprint_lookups(
            480, 2029,
            {.octave_min = -2.0, .octave_max = 6.0, .max_stretch = 2.0, .max_shear = 0.3, .texture_size = double(kWidth)});
        for (size_t i = 0; i < ls.size(); ++i) {
            const double edge = (i % 2 ? 1.0 : 0.0) + (double((i * 37) % 100) / 100.0 - 0.5) * 0.3;
            if (i % 3 == 0)
                ls[i].u = edge, ls[i].v -= std::floor(ls[i].v);
            else if (i % 3 == 1)
                ls[i].v = edge, ls[i].u -= std::floor(ls[i].u);
        }
        return test::as_float(ls);
    }();
    return all;
}

const Work& work()
{
    static const Work w = [] {
        Work w;
        w.dir = test::make_work_dir("texel-sources");
        w.texture_path = (w.dir / "tile.pfm").string();
        write_pfm(w.texture_path, texture_level0());
        w.lookups_path = (w.dir / "lookups.csv").string();
        test::write_lookups_csv(w.lookups_path, lookups());
        return w;
    }();
    return w;
}

// A family as the CLI names it and as the reference takes it.
struct Family {
    std::string flags;
    SamplerOptions options;
};

Family family(const std::string& name, Wrap wrap)
{
    Family f;
    f.options.wrap = wrap;
    std::string filter = name;
    if (name == "aniso-feline") {
        filter = "aniso";
        f.options.aniso_shape = AnisoShape::feline;
        f.flags = " --aniso-shape feline";
    }
    if (name.rfind("stochastic-", 0) == 0) {
        filter = name.substr(11);
        f.options.stochastic = true;
        f.options.noise = Noise::white;
        f.options.accumulate = 4;
        f.flags = " --stochastic white --accumulate 4";
    }
    f.options.filter = parse_filter(filter);
    f.flags = "--filter " + filter + " --wrap " + to_string(wrap) + f.flags;
    return f;
}

const char* kWraps[] = {"repeat", "clamp", "mirror"};

test::SampleResult gpu_run(const Family& f, Resource r)
{
    const Work& w = work();
    return test::run_sample("--texture '" + w.texture_path + "' " + f.flags + " --resource " + to_string(r),
                            w.lookups_path, true);
}

// Bit-for-bit equal colours (and, with stats, fetch counts) on every lookup.
void check_equal(const std::string& what, const std::vector<glm::dvec4>& got, const std::vector<glm::dvec4>& want,
                 const std::vector<LookupStats>* got_stats = nullptr,
                 const std::vector<LookupStats>* want_stats = nullptr)
{
    CHECK(got.size() == want.size(), what + ": " + std::to_string(got.size()) + " rows for " +
                                         std::to_string(want.size()));
    if (got.size() != want.size())
        return;
    test::limit_failure_lines(6);
    double worst = 0;
    size_t differ = 0;
    for (size_t i = 0; i < got.size(); ++i) {
        const double d = max_channel_diff(got[i], want[i]);
        worst = std::max(worst, d);
        differ += d > 0 ? 1 : 0;
        CHECK(d == 0, what + ": lookup " + std::to_string(i) + " " + test::show(got[i]) + " combined " +
                          test::show(want[i]));
        if (got_stats && want_stats)
            CHECK((*got_stats)[i].texel_fetches == (*want_stats)[i].texel_fetches,
                  what + ": lookup " + std::to_string(i) + " fetches " +
                      std::to_string((*got_stats)[i].texel_fetches) + ", combined " +
                      std::to_string((*want_stats)[i].texel_fetches));
    }
    std::printf("%-60s %zu of %zu lookups differ from combined, largest %.3g\n", what.c_str(), differ, got.size(),
                worst);
}

// GPU: atlas and virtual against combined, one family and wrap mode.
void check_gpu(const std::string& name, Wrap wrap)
{
    const Family f = family(name, wrap);
    const test::SampleResult combined = gpu_run(f, Resource::combined);
    for (Resource r : {Resource::atlas, Resource::virtual_texture}) {
        const test::SampleResult got = gpu_run(f, r);
        check_equal(f.flags + " --resource " + to_string(r), got.colors, combined.colors, &got.stats, &combined.stats);
    }
}

// Reference: the same, in process (sample_resource with no device: the reference backend's path).
void check_reference(const std::string& name, Wrap wrap)
{
    const Family f = family(name, wrap);
    const std::vector<glm::dvec4> combined = reference_sample_all(texture(), lookups(), f.options);
    for (Resource r : {Resource::atlas, Resource::virtual_texture})
        check_equal("reference " + f.flags + " --resource " + to_string(r),
                    reference_sample_source(make_source_binding(texture(), r), lookups(), f.options), combined);
}

// The share of lookups near an edge where `a` and `b` differ by more than 0.01.
double differing_share(const std::vector<glm::dvec4>& a, const std::vector<glm::dvec4>& b)
{
    size_t near_edge = 0, differ = 0;
    for (size_t i = 0; i < lookups().size(); ++i) {
        if (i % 3 == 2)
            continue; // the lookups anywhere
        ++near_edge;
        differ += max_channel_diff(a[i], b[i]) > 0.01 ? 1 : 0;
    }
    return double(differ) / double(near_edge);
}

} // namespace

TEST_SUITE_BEGIN("reference");

TEST_CASE("atlas-layout")
{
    const MipChain& t = texture();
    const SourceBinding atlas = make_atlas(t);
    const int cell = 64, side = HARNESS_ATLAS_GRID * cell; // next power of two >= 45
    CHECK(atlas.image.levels.size() == size_t(mip_level_count(side, side)),
          std::to_string(atlas.image.levels.size()) + " atlas levels");
    CHECK(source_levels(atlas) == int(t.levels.size()), std::to_string(source_levels(atlas)) + " tile levels");
    const glm::ivec2 origin(HARNESS_ATLAS_CELL_X * cell, HARNESS_ATLAS_CELL_Y * cell);
    for (int l = 0; l < int(t.levels.size()); ++l) {
        const Image& tile = t.levels[size_t(l)];
        const Image& level = atlas.image.levels[size_t(l)];
        CHECK(source_size(atlas, l) == glm::ivec2(tile.width, tile.height),
              "level " + std::to_string(l) + " size " + std::to_string(source_size(atlas, l).x));
        size_t wrong = 0;
        for (int y = 0; y < tile.height; ++y)
            for (int x = 0; x < tile.width; ++x)
                wrong += level.at((origin.x >> l) + x, (origin.y >> l) + y) != tile.at(x, y);
        CHECK(wrong == 0, "level " + std::to_string(l) + ": " + std::to_string(wrong) + " tile texels not at origin >> l");
        // Around the tile: the other cells' colours and the padding, so a read off the tile shows.
        const int c = cell >> l;
        CHECK(level.at(0, 0) == atlas_cell_colour(0), "level " + std::to_string(l) + ": cell 0's colour");
        if (tile.width < c)
            CHECK(level.at((origin.x >> l) + tile.width, origin.y >> l) == atlas_padding_colour(),
                  "level " + std::to_string(l) + ": padding right of the tile");
    }
    const MipChain back = read_source(atlas);
    for (size_t l = 0; l < t.levels.size(); ++l)
        CHECK(back.levels[l].texels == t.levels[l].texels, "read_source level " + std::to_string(l));
}

TEST_CASE("virtual-layout")
{
    const MipChain& t = texture();
    const SourceBinding v = make_virtual_texture(t);
    CHECK(v.image.levels.size() == 1, "one physical level");
    CHECK(source_levels(v) == int(t.levels.size()), std::to_string(source_levels(v)) + " levels");
    // Every page of every level has its own place in the physical texture, and most are not where an
    // unshuffled layout (pages in order, row by row) would put them.
    const int page = HARNESS_VIRTUAL_PAGE, row = v.image.levels[0].width / page;
    std::set<int32_t> places;
    int pages = 0, in_order = 0;
    for (int l = 0; l < source_levels(v); ++l) {
        const glm::ivec2 size = source_size(v, l);
        CHECK(size == glm::ivec2(t.levels[size_t(l)].width, t.levels[size_t(l)].height),
              "level " + std::to_string(l) + " size");
        const int32_t* header = &v.words[size_t(1 + HARNESS_VIRTUAL_LEVEL_WORDS * l)];
        const int px = (size.x + page - 1) / page, py = (size.y + page - 1) / page;
        CHECK(header[HARNESS_VIRTUAL_PAGES_X] == px, "level " + std::to_string(l) + " pages a row");
        for (int k = 0; k < px * py; ++k, ++pages) {
            const int32_t entry = v.words.at(size_t(header[HARNESS_VIRTUAL_FIRST_PAGE] + k));
            places.insert(entry);
            in_order += (entry & 0xffff) + (entry >> 16) * row == pages ? 1 : 0;
        }
    }
    CHECK(int(places.size()) == pages, std::to_string(places.size()) + " places for " + std::to_string(pages) + " pages");
    CHECK(in_order * 4 < pages, std::to_string(in_order) + " of " + std::to_string(pages) + " pages unshuffled");
    // The physical texture's texels outside every page's level content are the padding colour.
    size_t padding = 0;
    for (const glm::vec4& texel : v.image.levels[0].texels)
        padding += texel == virtual_padding_colour();
    CHECK(padding > 0, "padding texels in the physical texture (partial pages, unused places)");
    const MipChain back = read_source(v);
    for (size_t l = 0; l < t.levels.size(); ++l)
        CHECK(back.levels[l].texels == t.levels[l].texels, "read_source level " + std::to_string(l));
}

// A texture whose atlas or physical texture would pass the device's largest side is refused before the build.
TEST_CASE("source-size-refused")
{
    CHECK_THROWS_WITH(check_source_size(Resource::atlas, 9000, 100, 16384), "16384");
    CHECK_THROWS_WITH(check_source_size(Resource::virtual_texture, 16384, 16384, 16384), "physical texture");
    check_source_size(Resource::atlas, 8192, 8192, 16384);
    CHECK(source_image_size(Resource::atlas, 45, 29) == glm::ivec2(128), "atlas of 45x29");
}

// The reference's hw-trilinear on the atlas (the atlas at the tile's uv) bleeds; its trilinear does not.
TEST_CASE("reference-atlas-hw-bleeds")
{
    for (const char* wrap : kWraps) {
        Family hw = family("hw-trilinear", parse_wrap(wrap));
        const SourceBinding atlas = make_atlas(texture());
        const double share =
            differing_share(reference_sample_source(atlas, lookups(), hw.options),
                            reference_sample_all(texture(), lookups(), hw.options));
        std::printf("reference hw-trilinear --wrap %s on the atlas: %.0f %% of the edge lookups bleed\n", wrap,
                    100 * share);
        CHECK(share >= 0.5, std::string(wrap) + ": hw-trilinear on the atlas differs on only " + test::show(share));
    }
}

TEST_SUITE_END();

TEST_SUITE_BEGIN("gpu");

// The hardware sampler on the atlas bleeds on the device too (the picture docs/images/api/atlas-bleeding.png).
TEST_CASE("atlas-hw-bleeds")
{
    for (const char* wrap : kWraps) {
        const Family hw = family("hw-trilinear", parse_wrap(wrap));
        const double share = differing_share(gpu_run(hw, Resource::atlas).colors, gpu_run(hw, Resource::combined).colors);
        std::printf("hw-trilinear --wrap %s on the atlas: %.0f %% of the edge lookups bleed\n", wrap, 100 * share);
        CHECK(share >= 0.5, std::string(wrap) + ": hw-trilinear on the atlas differs on only " + test::show(share));
    }
}

TEST_SUITE_END();

// One case a family and wrap mode, on each backend: gpu/FAMILY-WRAP and reference/FAMILY-WRAP.
#define TF_SOURCE_CASES(family_name, id)                                                                               \
    TEST_CASE("gpu-" id "-repeat" * doctest::test_suite("gpu")) { check_gpu(family_name, Wrap::repeat); }             \
    TEST_CASE("gpu-" id "-clamp" * doctest::test_suite("gpu")) { check_gpu(family_name, Wrap::clamp); }               \
    TEST_CASE("gpu-" id "-mirror" * doctest::test_suite("gpu")) { check_gpu(family_name, Wrap::mirror); }             \
    TEST_CASE("reference-" id "-repeat" * doctest::test_suite("reference")) { check_reference(family_name, Wrap::repeat); } \
    TEST_CASE("reference-" id "-clamp" * doctest::test_suite("reference")) { check_reference(family_name, Wrap::clamp); }   \
    TEST_CASE("reference-" id "-mirror" * doctest::test_suite("reference")) { check_reference(family_name, Wrap::mirror); }

TF_SOURCE_CASES("nearest", "nearest")
TF_SOURCE_CASES("bilinear", "bilinear")
TF_SOURCE_CASES("trilinear", "trilinear")
TF_SOURCE_CASES("nearest-mip", "nearest-mip")
TF_SOURCE_CASES("bilinear-mip", "bilinear-mip")
TF_SOURCE_CASES("brilinear", "brilinear")
TF_SOURCE_CASES("aniso", "aniso")
TF_SOURCE_CASES("aniso-feline", "aniso-feline")
TF_SOURCE_CASES("ewa", "ewa")
TF_SOURCE_CASES("bspline", "bspline")
TF_SOURCE_CASES("catmull-rom", "catmull-rom")
TF_SOURCE_CASES("stochastic-bilinear", "stochastic-bilinear")
TF_SOURCE_CASES("stochastic-trilinear", "stochastic-trilinear")
TF_SOURCE_CASES("stochastic-aniso", "stochastic-aniso")
TF_SOURCE_CASES("stochastic-ewa", "stochastic-ewa")
