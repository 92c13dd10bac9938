// One harness variant's embedded SPIR-V (see harness_spirv.h): compiled once a variant with its own
// generated folder first on the include path and TF_SPIRV_FUNCTION naming its function.
#include "vulkan/harness_spirv.h"
#include <cstdint>

#include "sample_comp.h"

namespace tf {

SpirvWords TF_SPIRV_FUNCTION() { return {sample_comp, sizeof(sample_comp)}; }

} // namespace tf
