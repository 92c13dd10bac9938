// STUB (being written).
#include "error.h"
#include "reference.h"
namespace tf {
glm::dvec4 reference_ewa(const MipChain&, const SamplerOptions&, const Lookup&) { throw Error("ewa: not yet"); }
} // namespace tf
