// One pack_level.comp.glsl variant's embedded SPIR-V (gpu_build_spirv.h): compiled once a variant with its
// generated folder first on the include path and TF_SPIRV_FUNCTION naming its function.
#include "vulkan/gpu_build_spirv.h"
#include <cstdint>

#include "pack_level_comp.h"

namespace tf {

SpirvWords TF_SPIRV_FUNCTION() { return {pack_level_comp, sizeof(pack_level_comp)}; }

} // namespace tf
