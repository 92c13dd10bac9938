// One embedded SPIR-V module as a function (pipelines.h's SpirvWords): compiled once a variant by its own
// object library (CMakeLists.txt, tf_spirv_variant), with the variant's generated folder first on the
// include path, TF_SPIRV_HEADER naming the generated header, TF_SPIRV_ARRAY its array and
// TF_SPIRV_FUNCTION the function it defines.
#include "vulkan/pipelines.h"

#include TF_SPIRV_HEADER

namespace tf {

SpirvWords TF_SPIRV_FUNCTION() { return {TF_SPIRV_ARRAY, sizeof(TF_SPIRV_ARRAY)}; }

} // namespace tf
