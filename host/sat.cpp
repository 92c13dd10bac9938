// STUB (being written).
#include "sat.h"
namespace tf {
SatTable build_sat(const Image& level0)
{
    SatTable t;
    t.width = level0.width;
    t.height = level0.height;
    t.low.assign(size_t(t.width + 1) * size_t(t.height + 1) * 4, 0u);
    t.high.assign(size_t(t.width + 1) * size_t(t.height + 1), 0u);
    return t;
}
std::array<uint64_t, 4> sat_box_sum(const SatTable&, int, int, int, int) { return {}; }
} // namespace tf
