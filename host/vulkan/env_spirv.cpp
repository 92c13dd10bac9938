// One environment variant's embedded SPIR-V (see harness_spirv.h): compiled once a map kind with its own
// generated folder first on the include path and TF_SPIRV_FUNCTION naming its function.
#include "vulkan/harness_spirv.h"
#include <cstdint>

#include "render_env_frag.h"

namespace tf {

SpirvWords TF_SPIRV_FUNCTION() { return {render_env_frag, sizeof(render_env_frag)}; }

} // namespace tf
