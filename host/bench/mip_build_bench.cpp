#include "bench/mip_build_bench.h"
#include "core/memory_budget.h"
#include "texture/mip.h"
#include "texture/threads.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <memory>
#include <random>
#include <vector>

namespace tf {

namespace {

// The median time of work(), each run after an untimed prepare().
template <typename Prepare, typename Work>
double median_seconds(int repeats, Prepare prepare, Work work)
{
    std::vector<double> seconds;
    for (int r = 0; r < repeats; ++r) {
        prepare();
        const auto start = std::chrono::steady_clock::now();
        work();
        seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(seconds.begin(), seconds.end());
    return seconds[seconds.size() / 2];
}

double gb_per_second(double bytes, double seconds) { return bytes / seconds / 1e9; }

} // namespace

void check_mip_build_bench(int side, uint64_t budget)
{
    TextureMemory need = estimate_texture_memory(side, side, false, TextureLoad::host);
    // run_mip_build_bench: level 0 beside a chain built from it, then beside the in-place buffer (a level 0) and
    // memcpy's source and destination (half the build's traffic each; the fresh one is freed before the next).
    double traffic = 0;
    for (int w = side, h = side; w > 1 || h > 1; w = std::max(1, w >> 1), h = std::max(1, h >> 1))
        traffic += (double(w) * h + double(std::max(1, w >> 1)) * std::max(1, h >> 1)) * sizeof(glm::vec4);
    need.host_peak = need.decode + std::max(need.chain, need.decode + uint64_t(traffic));
    check_memory_budget("bench --mip-build --texture-size " + std::to_string(side), side, side, need, budget);
}

MipBuildBench run_mip_build_bench(int side, int repeats)
{
    MipBuildBench b;
    b.side = side;
    b.repeats = repeats;
    b.levels = mip_level_count(side, side);
    b.threads = int(hardware_threads());
    Image level0 = make_image(side, side);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> value(0.0f, 1.0f);
    for (glm::vec4& t : level0.texels) t = glm::vec4(value(rng), value(rng), value(rng), 1.0f);
    for (int w = side, h = side; w > 1 || h > 1; w = std::max(1, w >> 1), h = std::max(1, h >> 1)) {
        const double source = double(w) * h * sizeof(glm::vec4);
        const double level = double(std::max(1, w >> 1)) * std::max(1, h >> 1) * sizeof(glm::vec4);
        b.bytes_moved += source + level;
    }

    volatile float sink = 0; // keeps the results alive
    auto nothing = [] {};
    b.chain_seconds = median_seconds(repeats, nothing, [&] { sink = sink + build_mip_chain(level0).levels.back().texels[0].r; });

    std::vector<glm::vec4> buffer = level0.texels;
    auto refill = [&] { std::memcpy(buffer.data(), level0.texels.data(), buffer.size() * sizeof(glm::vec4)); };
    b.in_place_seconds = median_seconds(repeats, refill, [&] {
        for (int w = side, h = side; w > 1 || h > 1; w = std::max(1, w >> 1), h = std::max(1, h >> 1))
            downsample_into(buffer.data(), w, h, buffer.data());
        sink = sink + buffer[0].r;
    });

    // memcpy moving the same bytes: it reads n and writes n, so n = half the build's traffic.
    const size_t n = size_t(b.bytes_moved / 2);
    std::vector<char> source(n, 1);
    b.memcpy_fresh_seconds = median_seconds(repeats, nothing, [&] {
        std::unique_ptr<char[]> fresh(new char[n]);
        std::memcpy(fresh.get(), source.data(), n);
        sink = sink + float(fresh[n / 2]);
    });
    std::vector<char> touched(n, 0);
    b.memcpy_seconds = median_seconds(repeats, nothing, [&] {
        std::memcpy(touched.data(), source.data(), n);
        sink = sink + float(touched[n / 3]);
    });
    return b;
}

std::string format_mip_build_bench(const MipBuildBench& b)
{
    const double chain = gb_per_second(b.bytes_moved, b.chain_seconds);
    const double in_place = gb_per_second(b.bytes_moved, b.in_place_seconds);
    const double fresh = gb_per_second(b.bytes_moved, b.memcpy_fresh_seconds);
    const double touched = gb_per_second(b.bytes_moved, b.memcpy_seconds);
    char text[1024];
    std::snprintf(text, sizeof text,
                  "mip-build %dx%d RGBA32F, %d levels, %d threads, %.2f GB read+written a chain, median of %d\n"
                  "  build_mip_chain (fresh levels)  %7.3f s  %6.2f GB/s  %5.1f %% of memcpy into fresh memory\n"
                  "  memcpy into fresh memory        %7.3f s  %6.2f GB/s\n"
                  "  downsample_into in place        %7.3f s  %6.2f GB/s  %5.1f %% of memcpy into touched memory\n"
                  "  memcpy into touched memory      %7.3f s  %6.2f GB/s\n",
                  b.side, b.side, b.levels, b.threads, b.bytes_moved / 1e9, b.repeats, b.chain_seconds, chain,
                  100.0 * chain / fresh, b.memcpy_fresh_seconds, fresh, b.in_place_seconds, in_place,
                  100.0 * in_place / touched, b.memcpy_seconds, touched);
    return text;
}

} // namespace tf
