// Harness only: the random numbers of --stochastic, host/core/stochastic_noise.h's stochastic_xi bit for bit
// (see there for what white and blue are and why). pc.stochastic = frame * 4 + HARNESS_NOISE_*.
#ifndef HARNESS_STOCHASTIC_NOISE_GLSL
#define HARNESS_STOCHASTIC_NOISE_GLSL

#include "config.h"
#include "hash.glsl"

vec3 stochastic_xi(int packed, ivec2 pixel, uint lookup)
{
    uint frame = uint(packed) >> 2, x = uint(pixel.x), y = uint(pixel.y);
    if ((packed & 3) == HARNESS_NOISE_WHITE) {
        uint h = harness_mix32(lookup + harness_mix32(frame + harness_mix32(y + harness_mix32(x))));
        return vec3(harness_unit(h), harness_unit(harness_mix32(h ^ 0x9e3779b9u)), harness_unit(harness_mix32(h ^ 0x7f4a7c15u)));
    }
    uint lk = lookup * 0x9e3779b9u;
    uint ox = x * 0xc13fa9a9u + y * 0x91e10da6u + lk;
    uint oy = y * 0xc13fa9a9u + x * 0x91e10da6u + lk;
    uint oz = (x + y) * 0xc13fa9a9u + x * 0x91e10da6u + lk;
    return vec3(harness_unit(ox + frame * 0xd1b54a33u), harness_unit(oy + frame * 0xabc98389u),
                harness_unit(oz + frame * 0x8cb92ba7u));
}

#endif
