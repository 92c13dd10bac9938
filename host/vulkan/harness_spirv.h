#pragma once
// The harness's sample.comp.glsl compiled once a resource kind (-DHARNESS_RESOURCE=N): each variant's
// words are embedded by its own object library (host/vulkan/CMakeLists.txt, tf_harness_variant), whose one
// source, harness_spirv.cpp, defines the function below under the variant's name. No Vulkan here: the
// variants' sources see only this header and their embedded words.
#include <cstddef>
#include <cstdint>

namespace tf {

struct SpirvWords {
    const uint32_t* words;
    size_t bytes;
};

SpirvWords sample_spirv_separate();
SpirvWords sample_spirv_array();
SpirvWords sample_spirv_separate_array();
SpirvWords sample_spirv_bindless();
SpirvWords sample_spirv_shadow();
SpirvWords sample_spirv_atlas();
SpirvWords sample_spirv_virtual();
// render_env.frag.glsl once an environment map kind (-DHARNESS_ENV=HARNESS_ENV_CUBE / _LATLONG; env_spirv.cpp).
SpirvWords env_spirv_cube();
SpirvWords env_spirv_latlong();

} // namespace tf
