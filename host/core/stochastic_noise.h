#pragma once
// The random numbers of --stochastic (the harness's, not texfilter's API: its stochastic forms take xi from the
// caller). shaders/harness/stochastic_noise.glsl is the GPU twin, bit for bit: integer arithmetic only, each
// number 24 bits in [0, 1), exact in float, so the CPU reference draws the GPU's very numbers.
//
// white: three integer hashes (mix32) of (pixel, frame, lookup): independent across pixels and frames.
// blue:  a low-discrepancy sequence per pixel instead of a blue-noise texture (nothing to generate, store or
//        bind, and no period): frame n takes the R3 point n·(1/φ, 1/φ², 1/φ³) mod 1 (φ the plastic-like root of
//        x⁴ = x + 1, Roberts' "unreasonable effectiveness" sequence), Cranley-Patterson rotated per pixel by the
//        R2 dither lattice (x·(1/ψ) + y·(1/ψ²) mod 1, ψ³ = ψ + 1), which spreads neighbouring pixels' offsets
//        evenly (blue-ish: low spatial discrepancy, not a void-and-cluster texture). Per pixel the N frames
//        then stratify xi in all three dimensions, so the mean of N frames converges faster than white's
//        1/sqrt(N) where the choice is smooth in xi; each frame alone is as noisy as white.
#include "core/hash.h"
#include "harness/config.h"
#include <cstdint>

namespace tf {

enum class Noise { white = HARNESS_NOISE_WHITE, blue = HARNESS_NOISE_BLUE };

struct Xi {
    float x = 0, y = 0, z = 0;
};

// The top 24 bits of h in [0, 1).
constexpr float noise_unit(uint32_t h) { return float(h >> 8) * (1.0f / 16777216.0f); }

constexpr Xi stochastic_xi(Noise noise, int px, int py, uint32_t frame, uint32_t lookup)
{
    const uint32_t x = uint32_t(px), y = uint32_t(py);
    if (noise == Noise::white) {
        const uint32_t h = mix32(lookup + mix32(frame + mix32(y + mix32(x))));
        return {noise_unit(h), noise_unit(mix32(h ^ 0x9e3779b9u)), noise_unit(mix32(h ^ 0x7f4a7c15u))};
    }
    // R2 dither offsets (the three dimensions from three pixel-lattice directions), then R3 steps in time.
    const uint32_t lk = lookup * 0x9e3779b9u;
    const uint32_t ox = x * 0xc13fa9a9u + y * 0x91e10da6u + lk;
    const uint32_t oy = y * 0xc13fa9a9u + x * 0x91e10da6u + lk;
    const uint32_t oz = (x + y) * 0xc13fa9a9u + x * 0x91e10da6u + lk;
    return {noise_unit(ox + frame * 0xd1b54a33u), noise_unit(oy + frame * 0xabc98389u),
            noise_unit(oz + frame * 0x8cb92ba7u)};
}

} // namespace tf
