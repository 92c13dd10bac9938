#pragma once
// Per-lookup cost, counted by the shader through the includes' TF_COUNT_* hooks (`sample --stats`).
#include <cstdint>

namespace tf {

struct LookupStats {
    uint32_t texel_fetches = 0;    // texelFetch calls
    uint32_t hardware_lookups = 0; // filtered sampler lookups (hw-* filters, hardware taps)
};

} // namespace tf
