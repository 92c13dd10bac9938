// texfilter::host as a user links it: build a MIP chain and a summed-area table from the installed
// <texfilter/host.h> alone, and check them against what the header's contracts promise, by brute force:
//   - every SAT box sum equals the sum of the quantised texels q = round((v - offset) / scale * 65535),
//   - the MIP chain has the floor-rule sizes down to 1x1 and each level keeps the mean of the one above,
//   - downsample_into in place (how a streaming upload builds levels) gives build_mip_chain's levels bit for bit,
//   - decode_srgb8 gives linear values and bad input throws tf::Error.
// Prints one line and exits 0 when all hold, 1 (with the first failure) when one does not.
#include <texfilter/host.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>

namespace {

int failures = 0;

void check(bool ok, const char* what)
{
    if (!ok && failures++ == 0) std::fprintf(stderr, "host_tables: FAILED: %s\n", what);
}

uint64_t quantised(float v, float offset, float scale)
{
    if (!(scale > 0)) return 0;
    return uint64_t(std::llround(std::fmin(65535.0, std::fmax(0.0, (double(v) - offset) / scale * 65535.0))));
}

} // namespace

int main()
{
    // An odd-sized texture with values of both signs, so the floor rule's 3-tap levels and the offset matter.
    const int w = 67, h = 45;
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> value(-1.5f, 4.0f);
    tf::Image image = tf::make_image(w, h);
    for (glm::vec4& t : image.texels) t = glm::vec4(value(rng), value(rng), value(rng), value(rng));

    const tf::SatTable sat = tf::build_sat(image);
    check(sat.width == w && sat.height == h, "SAT size");
    check(sat.low.size() == size_t(w + 1) * size_t(h + 1) * 4 && sat.high.size() == size_t(w + 1) * size_t(h + 1),
          "SAT image sizes are (w+1) x (h+1)");
    std::uniform_int_distribution<int> xs(0, w), ys(0, h);
    int boxes = 0;
    for (int i = 0; i < 2000; ++i) {
        int x0 = xs(rng), x1 = xs(rng), y0 = ys(rng), y1 = ys(rng);
        if (x1 < x0) std::swap(x0, x1);
        if (y1 < y0) std::swap(y0, y1);
        const std::array<uint64_t, 4> sum = tf::sat_box_sum(sat, x0, y0, x1, y1);
        for (int c = 0; c < 4; ++c) {
            uint64_t brute = 0;
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x) brute += quantised(image.at(x, y)[c], sat.offset[c], sat.scale[c]);
            check(sum[size_t(c)] == brute, "SAT box sum equals the brute-force sum of quantised texels");
        }
        ++boxes;
    }
    const std::array<uint64_t, 4> whole = tf::sat_box_sum(sat, 0, 0, w, h);
    check(whole[0] > 0, "the whole texture's sum is not zero");

    const tf::MipChain chain = tf::build_mip_chain(image);
    check(int(chain.levels.size()) == tf::mip_level_count(w, h) && chain.levels.size() == 7, "7 levels for 67x45");
    for (size_t l = 1; l < chain.levels.size(); ++l) {
        const tf::Image& above = chain.levels[l - 1];
        const tf::Image& level = chain.levels[l];
        check(level.width == std::max(1, above.width >> 1) && level.height == std::max(1, above.height >> 1),
              "floor-rule level sizes");
        double mean_above = 0, mean = 0;
        for (const glm::vec4& t : above.texels) mean_above += t.r;
        for (const glm::vec4& t : level.texels) mean += t.r;
        mean_above /= double(above.texels.size());
        mean /= double(level.texels.size());
        check(std::fabs(mean - mean_above) < 1e-4, "each level keeps the mean of the level above (box weights)");
    }

    // In place over a level big enough to be built in several bands (2050^2 texels, 64 MiB), odd sizes below.
    tf::Image big = tf::make_image(2050, 2050);
    for (glm::vec4& t : big.texels) t = glm::vec4(value(rng), value(rng), value(rng), value(rng));
    const tf::MipChain reference = tf::build_mip_chain(big);
    std::vector<glm::vec4> buffer = big.texels;
    for (size_t l = 1, bw = 2050, bh = 2050; l < reference.levels.size(); ++l) {
        tf::downsample_into(buffer.data(), int(bw), int(bh), buffer.data());
        bw = std::max<size_t>(1, bw >> 1);
        bh = std::max<size_t>(1, bh >> 1);
        check(std::memcmp(buffer.data(), reference.levels[l].texels.data(), bw * bh * sizeof(glm::vec4)) == 0,
              "downsample_into in place equals build_mip_chain bit for bit");
    }

    const uint8_t rgba[8] = {0, 128, 255, 255, 188, 188, 188, 0};
    const tf::Image decoded = tf::decode_srgb8(rgba, 2, 1, 4);
    check(decoded.texels[0].r == 0.0f && decoded.texels[0].b == 1.0f, "sRGB codes 0 and 255 are 0 and 1");
    check(std::fabs(decoded.texels[0].g - 0.2158605f) < 1e-6f, "sRGB code 128 is 0.21586 linear");
    check(std::fabs(decoded.texels[1].r - 0.5028865f) < 1e-6f && decoded.texels[1].a == 0.0f, "sRGB code 188 is 0.50289 linear, alpha 0 stays 0");

    bool threw = false;
    try {
        tf::sat_box_sum(sat, 0, 0, w + 1, h);
    } catch (const tf::Error&) {
        threw = true;
    }
    check(threw, "a box outside the texture throws tf::Error");
    threw = false;
    try {
        tf::build_mip_chain(tf::Image{});
    } catch (const tf::Error&) {
        threw = true;
    }
    check(threw, "an empty image throws tf::Error");

    if (failures) return 1;
    std::printf("host_tables: %d SAT boxes equal brute force; %zu MIP levels; in-place chain bit for bit; "
                "sRGB decode ok\n", boxes, chain.levels.size());
    return 0;
}
