#include "vulkan/spirv_module.h"
#include "harness/config.h"
#include "texture/error.h"
#include "vulkan/harness_variant.h"
#include <cstring>
#include <map>
#include <spirv-tools/libspirv.hpp>

namespace tf {

namespace {

constexpr uint32_t kMagic = 0x07230203;

// The few opcodes, decorations and storage classes read here (SPIR-V specification, section 3).
enum : uint32_t {
    OpEntryPoint = 15, OpTypeImage = 25, OpTypeSampler = 26, OpTypeSampledImage = 27, OpTypeArray = 28,
    OpTypeRuntimeArray = 29, OpTypeStruct = 30, OpTypePointer = 32, OpVariable = 59, OpDecorate = 71,
    OpMemberDecorate = 72,
    DecorationBufferBlock = 3, DecorationOffset = 35, DecorationBinding = 33, DecorationDescriptorSet = 34,
    StorageUniformConstant = 0, StorageUniform = 2, StoragePushConstant = 9, StorageStorageBuffer = 12,
    ExecutionModelGLCompute = 5,
};

// A descriptor as the module declares it: its type, and for an image whether it is a 2D array.
struct Declared {
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM; // MAX_ENUM: a resource of no kind the pass binds
    bool layered = false;
};
std::string to_string(VkDescriptorType type, bool layered)
{
    const std::string image = layered ? " (2D array)" : " (2D)";
    switch (type) {
    case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER: return "a combined image sampler" + image;
    case VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE: return "a sampled image" + image;
    case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE: return "a storage image";
    case VK_DESCRIPTOR_TYPE_SAMPLER: return "a sampler";
    case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER: return "a storage buffer";
    case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER: return "a uniform buffer";
    default: break;
    }
    return "a resource of another kind";
}

struct Instruction {
    uint32_t opcode;
    const uint32_t* operands; // after the opcode word
    uint32_t count;           // operands
};

// The module's instructions (the validator has checked their word counts).
std::vector<Instruction> instructions(const std::vector<uint32_t>& words)
{
    std::vector<Instruction> all;
    for (size_t i = 5; i < words.size();) {
        const uint32_t n = words[i] >> 16;
        all.push_back({words[i] & 0xffffu, &words[i + 1], n - 1});
        i += n;
    }
    return all;
}

// The interface the sample pass of `resource` gives the shader (see the header); throws naming the first mismatch.
void check_interface(const std::vector<uint32_t>& words, const std::string& name, Resource resource)
{
    const std::vector<Instruction> module = instructions(words);
    std::map<uint32_t, uint32_t> binding, set, type_of_pointer, storage_of_pointer;
    std::map<uint32_t, Instruction> types;
    std::map<uint32_t, uint32_t> largest_offset; // struct id -> largest member Offset
    std::map<uint32_t, bool> buffer_block;
    bool entry = false;
    for (const Instruction& in : module) {
        if (in.opcode == OpEntryPoint && in.count >= 3 && in.operands[0] == ExecutionModelGLCompute &&
            std::strncmp(reinterpret_cast<const char*>(&in.operands[2]), "main", 5) == 0)
            entry = true;
        if (in.opcode == OpDecorate && in.count >= 3 && in.operands[1] == DecorationBinding)
            binding[in.operands[0]] = in.operands[2];
        if (in.opcode == OpDecorate && in.count >= 3 && in.operands[1] == DecorationDescriptorSet)
            set[in.operands[0]] = in.operands[2];
        if (in.opcode == OpDecorate && in.count >= 2 && in.operands[1] == DecorationBufferBlock)
            buffer_block[in.operands[0]] = true;
        if (in.opcode == OpMemberDecorate && in.count >= 4 && in.operands[2] == DecorationOffset)
            largest_offset[in.operands[0]] = std::max(largest_offset[in.operands[0]], in.operands[3]);
        if (in.opcode == OpTypeImage || in.opcode == OpTypeSampler || in.opcode == OpTypeSampledImage ||
            in.opcode == OpTypeArray || in.opcode == OpTypeRuntimeArray || in.opcode == OpTypeStruct)
            types.insert({in.operands[0], in});
        if (in.opcode == OpTypePointer && in.count >= 3) {
            storage_of_pointer[in.operands[0]] = in.operands[1];
            type_of_pointer[in.operands[0]] = in.operands[2];
        }
    }
    if (!entry)
        throw Error(name + ": has no GLCompute entry point named 'main' (the sample pass's compute shader)");
    auto declared = [&](uint32_t storage, uint32_t type) -> Declared {
        auto t = types.find(type);
        while (t != types.end() && (t->second.opcode == OpTypeArray || t->second.opcode == OpTypeRuntimeArray))
            t = types.find(t->second.operands[1]);
        const uint32_t op = t == types.end() ? 0 : t->second.opcode;
        // OpTypeImage's operands: result, sampled type, Dim, Depth, Arrayed (4), MS, Sampled (6: 1 sampled, 2 storage)
        auto layered = [&](uint32_t image) {
            auto i = types.find(image);
            return i != types.end() && i->second.opcode == OpTypeImage && i->second.count > 4 && i->second.operands[4] == 1;
        };
        if (storage == StorageUniformConstant && op == OpTypeSampledImage)
            return {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, layered(t->second.operands[1])};
        if (storage == StorageUniformConstant && op == OpTypeImage)
            return {t->second.count > 6 && t->second.operands[6] == 2 ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE
                                                                       : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE,
                    layered(t->first)};
        if (storage == StorageUniformConstant && op == OpTypeSampler)
            return {VK_DESCRIPTOR_TYPE_SAMPLER};
        if (op == OpTypeStruct && storage == StorageStorageBuffer)
            return {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER};
        if (op == OpTypeStruct && storage == StorageUniform)
            return {buffer_block[t->first] ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER : VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER};
        return {};
    };
    const std::map<uint32_t, PassBinding> expected_bindings = sample_pass_bindings(resource);
    const std::string pass = "the sample pass of --resource " + to_string(resource);
    const std::string build = " (--resource " + to_string(resource) +
                              " runs shaders/harness/sample.comp.glsl compiled with -DHARNESS_RESOURCE=" +
                              std::to_string(int(resource)) + ")";
    for (const Instruction& in : module) {
        if (in.opcode != OpVariable || in.count < 3)
            continue;
        const uint32_t id = in.operands[1], storage = in.operands[2];
        const uint32_t pointee = type_of_pointer[in.operands[0]];
        if (storage == StoragePushConstant && largest_offset[pointee] >= HARNESS_PUSH_SIZE)
            throw Error(name + ": a push constant at byte " + std::to_string(largest_offset[pointee]) +
                        ", beyond the " + std::to_string(HARNESS_PUSH_SIZE) + " bytes the sample pass pushes");
        if (!binding.count(id))
            continue;
        const std::string where = "binding " + std::to_string(binding[id]);
        if (set[id] != 0)
            throw Error(name + ": a resource in descriptor set " + std::to_string(set[id]) + "; " + pass +
                        " binds set 0 only");
        const auto expected = expected_bindings.find(binding[id]);
        if (expected == expected_bindings.end())
            throw Error(name + ": a resource at " + where + ", which " + pass + " does not bind" + build);
        const Declared found = declared(storage, pointee);
        const PassBinding& want = expected->second;
        if (found.type != want.type || found.layered != want.layered)
            throw Error(name + ": " + where + " is " + to_string(found.type, found.layered) + "; " + pass +
                        " binds " + to_string(want.type, want.layered) + " there" + build);
    }
}

} // namespace

std::vector<uint32_t> check_sample_spirv(const std::string& bytes, const std::string& name, Resource resource)
{
    if (bytes.empty())
        throw Error(name + ": empty (expected a SPIR-V module)");
    if (bytes.size() % 4 != 0)
        throw Error(name + ": " + std::to_string(bytes.size()) +
                    " bytes, not a whole number of 32-bit words: not a SPIR-V module");
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), bytes.size());
    if (words[0] != kMagic)
        throw Error(name + ": not a SPIR-V module (" +
                    std::string(__builtin_bswap32(words[0]) == kMagic ? "the other byte order than this machine's"
                                                                      : "no SPIR-V magic number") + ")");
    spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_2); // the harness's target (texfilter_add_shaders: vulkan1.2)
    std::string first;
    tools.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t&, const char* message) {
        if (first.empty())
            first = message;
    });
    if (!tools.Validate(words))
        throw Error(name + ": not valid SPIR-V for Vulkan 1.2 (" + (first.empty() ? "the validator says no more" : first) +
                    ")");
    check_interface(words, name, resource);
    return words;
}

} // namespace tf
