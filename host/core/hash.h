#pragma once
// The project's one integer hash: deterministic on every platform (unlike std::rand), cheap, and
// written the same way in GLSL where the GPU must reproduce it (shaders/harness/ground_truth.glsl).
#include <cstdint>

namespace tf {

// "lowbias32": xor-shift / multiply rounds with good avalanche.
constexpr uint32_t mix32(uint32_t x)
{
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

} // namespace tf
