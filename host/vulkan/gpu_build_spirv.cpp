// The float-quantisation SAT build's embedded SPIR-V (see gpu_build_spirv.h).
#include "vulkan/gpu_build_spirv.h"
#include <cstdint>

#include "build_sat_comp.h"

namespace tf {

SpirvWords build_sat_spirv_fp32() { return {build_sat_comp, sizeof(build_sat_comp)}; }

} // namespace tf
