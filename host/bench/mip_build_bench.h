#pragma once
// The MIP build's speed beside memcpy's on the same machine, in one run (texfilter bench --mip-build):
// the build is bound by memory bandwidth, so memcpy moving the same bytes is the yardstick.
#include <cstdint>
#include <string>

namespace tf {

struct MipBuildBench {
    int side = 0, levels = 0, threads = 0, repeats = 0;
    double bytes_moved = 0;       // bytes read + written by one chain build (every level read once, written once)
    double chain_seconds = 0;     // median build_mip_chain (fresh levels, as users call it)
    double in_place_seconds = 0;  // median chain of downsample_into in place over a touched buffer (the upload's path)
    double memcpy_fresh_seconds = 0; // median memcpy of bytes_moved / 2 into a fresh buffer
    double memcpy_seconds = 0;       // the same into a touched buffer
};

// Refuses a side whose run would hold more than `budget` bytes at once (level 0, the chain built from it, the
// in-place buffer, memcpy's source and destination), before anything is allocated.
void check_mip_build_bench(int side, uint64_t budget);

// side x side random RGBA32F level 0; each measure the median of `repeats` runs.
MipBuildBench run_mip_build_bench(int side, int repeats);

// The lines bench --mip-build prints: GB/s of each, and the build's fraction of memcpy's.
std::string format_mip_build_bench(const MipBuildBench& result);

} // namespace tf
