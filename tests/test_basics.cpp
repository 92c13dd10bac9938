// Start here: one fact a case, each a few lines, about the CPU reference and the host's texture builders.
// The expected values are worked out by hand in the comments, never by calling the code under test. The
// rest of the suite (tests/README.md) checks the same code, and the device, in depth.
#include "core/filter.h"
#include "core/lookup.h"
#include "reference/reference.h"
#include "texture/image.h"
#include "texture/mip.h"
#include "texture/sat.h"
#include "support.h"

#include <cmath>
#include <cstdint>

using glm::dvec4;
using tf::Filter;
using tf::Wrap;

namespace {

// Every value here is a sum of a few dozen terms in double: rounding moves it by far less than this.
constexpr double kRounding = 1e-12;

constexpr Wrap kWraps[] = {Wrap::repeat, Wrap::clamp, Wrap::mirror};

// A texture of width x height texels, texel (x, y) = value(x, y) in every colour channel, alpha 1.
template <typename Value>
tf::Image image_of(int width, int height, Value value)
{
    tf::Image image = tf::make_image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.at(x, y) = glm::vec4(glm::vec3(float(value(x, y))), 1.0f);
    return image;
}

tf::SamplerOptions options_for(Filter filter, Wrap wrap = Wrap::repeat)
{
    tf::SamplerOptions options;
    options.filter = filter;
    options.wrap = wrap;
    return options;
}

} // namespace

TEST_SUITE_BEGIN("reference");

// A filter is a weighted mean of texels: on a texture where every texel is c, every filter gives c,
// at any uv (inside, outside, across the wrap) and any footprint (magnified, minified, anisotropic).
TEST_CASE("constant-texture-gives-the-constant")
{
    const glm::vec4 c(0.25f, 0.5f, 0.75f, 1.0f);
    const tf::MipChain chain = tf::build_mip_chain(tf::make_image(16, 16, c));
    const tf::Lookup lookups[] = {
        {0.5, 0.5, 0.01, 0, 0, 0.01},     // magnified
        {-0.3, 1.7, 0.2, 0.05, 0, 0.03},  // minified, anisotropic, outside [0, 1]
        {0.99, 0.01, 0.5, 0.5, -0.5, 0.5} // the whole texture
    };
    for (Filter filter : {Filter::nearest, Filter::bilinear, Filter::trilinear, Filter::nearest_mip,
                          Filter::bilinear_mip, Filter::brilinear, Filter::aniso, Filter::ewa, Filter::ewa_fast,
                          Filter::bspline, Filter::catmull_rom, Filter::sat, Filter::sat_assembly})
        for (Wrap wrap : kWraps)
            for (const tf::Lookup& lookup : lookups) {
                INFO(tf::to_string(filter), " ", tf::to_string(wrap));
                CHECK_NEAR(tf::reference_sample(chain, options_for(filter, wrap), lookup), dvec4(c), kRounding);
            }
}

// The cubic kernels are partitions of unity: the four weights at any offset t in [0, 1) sum to one
// (else a constant texture would not stay constant), and so do the tent's two.
TEST_CASE("filter-weights-sum-to-one")
{
    for (tf::Reconstruction kernel :
         {tf::Reconstruction::bilinear, tf::Reconstruction::bspline, tf::Reconstruction::catmull_rom})
        for (double t = 0.0; t < 1.0; t += 0.125) {
            const double sum = tf::cubic_kernel(t + 1, kernel) + tf::cubic_kernel(t, kernel) +
                               tf::cubic_kernel(t - 1, kernel) + tf::cubic_kernel(t - 2, kernel);
            INFO(tf::to_string(kernel), " t = ", t);
            CHECK_NEAR(sum, 1.0, kRounding);
        }
}

// Bilinear at a texel's centre is that texel; halfway between two centres it is their mean.
TEST_CASE("bilinear-at-centres-and-midpoints")
{
    const tf::Image row = image_of(4, 1, [](int x, int) { return 1 << x; }); // 1 2 4 8
    CHECK_NEAR(tf::reference_bilinear(row, 0.375, 0.5, Wrap::clamp).r, 2.0, 0.0); // texel 1's centre: (1 + 0.5)/4
    CHECK_NEAR(tf::reference_bilinear(row, 0.5, 0.5, Wrap::clamp).r, 3.0, 0.0);   // between 1 and 2: (2 + 4)/2
}

// λ = log2 of the footprint's longer side in level-0 texels: on a 256² texture a step of 2/256 in u per
// pixel is 2 texels, λ = 1; 4 texels down v is λ = 2; the bias adds to it.
TEST_CASE("lod-of-known-gradients")
{
    const tf::MipChain chain = tf::build_mip_chain(tf::make_image(256, 256));
    const tf::SamplerOptions options = options_for(Filter::trilinear);
    CHECK_NEAR(tf::reference_lod(chain, {0.5, 0.5, 1.0 / 256, 0, 0, 1.0 / 256}, options), 0.0, kRounding);
    CHECK_NEAR(tf::reference_lod(chain, {0.5, 0.5, 2.0 / 256, 0, 0, 0}, options), 1.0, kRounding);
    CHECK_NEAR(tf::reference_lod(chain, {0.5, 0.5, 0, 0, 0, 4.0 / 256}, options), 2.0, kRounding);
    tf::SamplerOptions biased = options;
    biased.lod_bias = 0.5f;
    CHECK_NEAR(tf::reference_lod(chain, {0.5, 0.5, 2.0 / 256, 0, 0, 0}, biased), 1.5, kRounding);
}

// The wrap modes on a row of 4 texels: texel -1 and 4 are one past each edge, 5 two past the right one.
// repeat: 3 0 1 (period 4); clamp: 0 3 3 (the edge); mirror: 0 3 2 (period 8: 0 1 2 3 3 2 1 0).
TEST_CASE("wrap-of-known-coordinates")
{
    CHECK_EQ(tf::wrap_texel(-1, 4, Wrap::repeat), 3);
    CHECK_EQ(tf::wrap_texel(4, 4, Wrap::repeat), 0);
    CHECK_EQ(tf::wrap_texel(5, 4, Wrap::repeat), 1);
    CHECK_EQ(tf::wrap_texel(-1, 4, Wrap::clamp), 0);
    CHECK_EQ(tf::wrap_texel(4, 4, Wrap::clamp), 3);
    CHECK_EQ(tf::wrap_texel(5, 4, Wrap::clamp), 3);
    CHECK_EQ(tf::wrap_texel(-1, 4, Wrap::mirror), 0);
    CHECK_EQ(tf::wrap_texel(4, 4, Wrap::mirror), 3);
    CHECK_EQ(tf::wrap_texel(5, 4, Wrap::mirror), 2);
}

// The same in uv: nearest at u = -0.25 reads texel -1 (x = -1), at u = 1.25 texel 5 (x = 5).
TEST_CASE("wrap-of-known-uv")
{
    const tf::Image row = image_of(4, 1, [](int x, int) { return x; }); // 0 1 2 3: the value is the texel
    CHECK_EQ(tf::reference_nearest(row, -0.25, 0.5, Wrap::repeat).r, 3);
    CHECK_EQ(tf::reference_nearest(row, -0.25, 0.5, Wrap::clamp).r, 0);
    CHECK_EQ(tf::reference_nearest(row, -0.25, 0.5, Wrap::mirror).r, 0);
    CHECK_EQ(tf::reference_nearest(row, 1.25, 0.5, Wrap::repeat).r, 1);
    CHECK_EQ(tf::reference_nearest(row, 1.25, 0.5, Wrap::clamp).r, 3);
    CHECK_EQ(tf::reference_nearest(row, 1.25, 0.5, Wrap::mirror).r, 2);
}

// A MIP level halves each side (the floor rule) down to 1x1: 256² has 9 levels, 5x3 has 3 (5x3, 2x1, 1x1).
TEST_CASE("mip-level-count")
{
    CHECK_EQ(tf::mip_level_count(256, 256), 9);
    CHECK_EQ(tf::mip_level_count(5, 3), 3);
    CHECK_EQ(tf::mip_level_count(1, 1), 1);
    CHECK_EQ(tf::build_mip_chain(tf::make_image(5, 3)).levels.size(), 3);
}

// Level 1 of a 2x2 is the mean of its four texels; of a 3x3 (odd: each texel of the smaller level covers
// 1.5 texels a side) the mean of all nine, none dropped.
TEST_CASE("mip-level-1-is-the-mean")
{
    const tf::MipChain two = tf::build_mip_chain(image_of(2, 2, [](int x, int y) { return 1 + x + 2 * y; }));
    CHECK_EQ(two.levels[1].at(0, 0).r, 2.5f); // (1 + 2 + 3 + 4) / 4
    const tf::MipChain three = tf::build_mip_chain(image_of(3, 3, [](int x, int y) { return x + 3 * y; }));
    CHECK_EQ(three.levels[1].at(0, 0).r, 4.0f); // (0 + 1 + ... + 8) / 9
}

// Trilinear halfway between two levels (λ = 0.5) is the mean of the two levels' bilinear values.
TEST_CASE("trilinear-blends-two-levels")
{
    const tf::MipChain chain = tf::build_mip_chain(image_of(2, 2, [](int x, int y) { return 1 + x + 2 * y; }));
    // Level 0 at the centre of texel (0, 0) is 1, level 1 (its one texel) is 2.5: halfway, 1.75.
    CHECK_NEAR(tf::reference_trilinear_at(chain, 0.5, 0.25, 0.25, Wrap::clamp).r, 1.75, kRounding);
}

// A summed-area table answers a box's sum in four reads: every box equals the texels added one by one.
// The texels are k/65535 with 0 and 1 present, so the table's 16-bit codes are the k themselves.
TEST_CASE("sat-box-equals-brute-force-sum")
{
    const auto code = [](int x, int y) { return x == 16 && y == 10 ? 65535 : (x * 7919 + y * 104729) % 65535; };
    const tf::Image image = image_of(17, 11, [&](int x, int y) { return code(x, y) / 65535.0; });
    const tf::SatTable table = tf::build_sat(image);
    const int boxes[][4] = {{0, 0, 17, 11}, {3, 2, 4, 3}, {5, 1, 16, 9}, {0, 10, 17, 11}, {7, 4, 7, 4}};
    for (const auto& b : boxes) {
        uint64_t sum = 0;
        for (int y = b[1]; y < b[3]; ++y)
            for (int x = b[0]; x < b[2]; ++x)
                sum += uint64_t(code(x, y));
        INFO("box [", b[0], ", ", b[2], ") x [", b[1], ", ", b[3], ")");
        CHECK_EQ(tf::sat_box_sum(table, b[0], b[1], b[2], b[3])[0], sum);
    }
}

// sRGB's transfer functions: 0 and 1 are fixed, they invert each other, and mid-grey 0.5 encoded is
// 0.214 linear ((0.5 + 0.055)/1.055)^2.4.
TEST_CASE("srgb-round-trip")
{
    CHECK_EQ(tf::srgb_to_linear(0.0), 0.0);
    CHECK_NEAR(tf::srgb_to_linear(1.0), 1.0, kRounding);
    CHECK_NEAR(tf::srgb_to_linear(0.5), std::pow(0.555 / 1.055, 2.4), kRounding);
    for (double x = 0.0; x <= 1.0; x += 0.0625)
        CHECK_NEAR(tf::srgb_to_linear(tf::linear_to_srgb(x)), x, kRounding);
}

TEST_SUITE_END();
