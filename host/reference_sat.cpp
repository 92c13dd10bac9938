// STUB (being written).
#include "error.h"
#include "reference.h"
namespace tf {
glm::dvec4 reference_sat(const MipChain&, const SamplerOptions&, const Lookup&) { throw Error("sat: not yet"); }
} // namespace tf
