#pragma once
// build_sat.comp.glsl compiled with -DTF_SAT_NO_FP64 (devices without shaderFloat64), embedded by its own
// object library (its generated header shares the exact build's name): gpu_build_spirv.cpp; and the
// pack_level.comp.glsl variants.
#include "vulkan/harness_spirv.h"

namespace tf {

SpirvWords build_sat_spirv_fp32();
// pack_level.comp.glsl with each integer view format (pack_spirv.cpp, one object library a format).
SpirvWords pack_spirv_rgba8ui();
SpirvWords pack_spirv_rgba16ui();
SpirvWords pack_spirv_r8ui();
SpirvWords pack_spirv_r16ui();
SpirvWords pack_spirv_r32ui();

} // namespace tf
