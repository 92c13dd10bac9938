#pragma once
// The harness's SPIR-V specialised on the host before the driver sees it: its specialization constants
// (spec_constants, vulkan/pipeline.h) frozen to one FilterVariant and the code they rule out removed.
//
// Why: the harness shaders hold every filter behind those constants (240 KB of SPIR-V for render.frag). A
// driver may inline every function before it folds them: lavapipe (Mesa 22.3) spent ~0.9 s of NIR work a
// pipeline on the whole module, against ~0.1 s on the specialised one, on every pipeline even with a warm
// shader cache. The passes (SPIRV-Tools: set and freeze the constants, fold what depends on them, drop dead
// branches and uncalled functions) change no instruction that is kept, so the pipeline computes the same values.
//
// Use: std::vector<uint32_t> words = specialize_spirv(code, variant); an empty result means "not
// specialised" (the optimiser refused the module): use `code` with a VkSpecializationInfo instead.
// Cost: ~0.1 s for the largest harness module, no validation pass (the module came from glslang).
#include "vulkan/pipeline.h"
#include <cstdint>
#include <vector>

namespace tf {

std::vector<uint32_t> specialize_spirv(ShaderCode code, FilterVariant variant);

} // namespace tf
