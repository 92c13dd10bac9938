#pragma once
// build_sat.comp.glsl compiled with -DTF_SAT_NO_FP64 (devices without shaderFloat64), embedded by its own
// object library (its generated header shares the exact build's name): gpu_build_spirv.cpp.
#include "vulkan/harness_spirv.h"

namespace tf {

SpirvWords build_sat_spirv_fp32();

} // namespace tf
