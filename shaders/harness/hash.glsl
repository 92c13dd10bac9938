// Harness only: host/core/hash.h's mix32 ("lowbias32") bit for bit, and 24 hash bits as a float in [0, 1)
// (exact in float, as on the CPU): the ground truth's jitter and --stochastic's white noise.
#ifndef HARNESS_HASH_GLSL
#define HARNESS_HASH_GLSL

uint harness_mix32(uint x)
{
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

float harness_unit(uint h) { return float(h >> 8) * (1.0 / 16777216.0); }

#endif
