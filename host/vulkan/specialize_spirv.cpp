#include "vulkan/specialize_spirv.h"
#include <spirv-tools/optimizer.hpp>
#include <unordered_map>

namespace tf {

std::vector<uint32_t> specialize_spirv(ShaderCode code, FilterVariant variant)
{
    // The variant's spec_constants (pipeline.h); a module without one of the ids keeps it absent.
    std::unordered_map<uint32_t, std::vector<uint32_t>> values;
    for (const SpecConstant& c : spec_constants(variant))
        values[c.id] = {uint32_t(c.value)};
    spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_2); // the harness targets Vulkan 1.2's SPIR-V 1.5
    optimizer.SetMessageConsumer([](spv_message_level_t, const char*, const spv_position_t&, const char*) {});
    optimizer.RegisterPass(spvtools::CreateSetSpecConstantDefaultValuePass(values))
        .RegisterPass(spvtools::CreateFreezeSpecConstantValuePass())
        .RegisterPass(spvtools::CreateFoldSpecConstantOpAndCompositePass())
        .RegisterPass(spvtools::CreateDeadBranchElimPass())
        .RegisterPass(spvtools::CreateEliminateDeadFunctionsPass());
    spvtools::OptimizerOptions options;
    options.set_run_validator(false);
    std::vector<uint32_t> out;
    if (!optimizer.Run(code.words, code.bytes / sizeof(uint32_t), &out, options))
        out.clear();
    return out;
}

} // namespace tf
