#pragma once
// What the libFuzzer targets share: a check that aborts (libFuzzer then saves the input as a crash),
// and the valid ranges of SamplerOptions that every parser must hand back.
#include "core/filter.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

// FUZZ_CHECK(condition, message): on failure prints "fuzz check failed: ..." and aborts.
#define FUZZ_CHECK(cond, ...)                                                                                 \
    do {                                                                                                    \
        if (!(cond))                                                                                        \
            ::tf::fuzz::fail(__FILE__, __LINE__, #cond, std::string(__VA_ARGS__));                            \
    } while (0)

namespace tf::fuzz {

[[noreturn]] inline void fail(const char* file, int line, const char* what, const std::string& message)
{
    std::fprintf(stderr, "%s:%d: fuzz check failed: %s%s%s\n", file, line, what, message.empty() ? "" : ": ",
                 message.c_str());
    std::abort();
}

// What cli_common.h's sampler_options_from promises (and so golden cases and the CLI).
inline void check_sampler_options(const SamplerOptions& o)
{
    FUZZ_CHECK(o.aniso >= 1 && o.aniso <= 16);
    FUZZ_CHECK(o.band >= 0.0f && o.band <= 1.0f);
    FUZZ_CHECK(o.probes >= 1 && o.probes <= 16);
    FUZZ_CHECK(o.alpha >= 0.05f && o.alpha <= 16.0f);
    FUZZ_CHECK(o.max_aniso >= 1.0f && o.max_aniso <= 64.0f);
    FUZZ_CHECK(o.boxes >= 1 && o.boxes <= 16);
    FUZZ_CHECK(o.truth_side >= 1 && o.truth_side <= max_ground_truth_side);
    FUZZ_CHECK(o.lod_bias >= -16.0f && o.lod_bias <= 16.0f);
    FUZZ_CHECK(o.lod_min >= 0.0f && o.lod_min <= o.lod_max && o.lod_max <= 1000.0f);
}

// Printable ASCII only: messages are one line on a terminal, whatever bytes the input held.
inline bool printable(const std::string& s)
{
    for (unsigned char c : s)
        if (c < 0x20 || c >= 0x7f)
            return false;
    return true;
}

} // namespace tf::fuzz
