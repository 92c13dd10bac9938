// STUB (being written).
#include "error.h"
#include "reference.h"
namespace tf {
glm::dvec4 reference_brilinear(const MipChain&, const SamplerOptions&, const Lookup&) { throw Error("brilinear: not yet"); }
glm::dvec4 reference_aniso(const MipChain&, const SamplerOptions&, const Lookup&) { throw Error("aniso: not yet"); }
} // namespace tf
