#include "vulkan/spirv_module.h"
#include "harness/config.h"
#include "texture/error.h"
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

// What the combined sample pass binds in set 0 (vulkan/pass.cpp, sample.cpp): the texture and the SAT's two
// tables as combined image samplers, the lookups, results and stats as storage buffers.
enum class Descriptor { combined, sampled_image, storage_image, sampler, storage_buffer, uniform_buffer, other };
const std::map<uint32_t, Descriptor>& sample_bindings()
{
    static const std::map<uint32_t, Descriptor> bindings = {
        {HARNESS_BINDING_TEXTURE, Descriptor::combined},       {HARNESS_BINDING_SAT_LOW, Descriptor::combined},
        {HARNESS_BINDING_SAT_HIGH, Descriptor::combined},      {HARNESS_BINDING_LOOKUPS, Descriptor::storage_buffer},
        {HARNESS_BINDING_RESULTS, Descriptor::storage_buffer}, {HARNESS_BINDING_STATS, Descriptor::storage_buffer}};
    return bindings;
}
const char* to_string(Descriptor d)
{
    switch (d) {
    case Descriptor::combined: return "a combined image sampler";
    case Descriptor::sampled_image: return "a sampled image";
    case Descriptor::storage_image: return "a storage image";
    case Descriptor::sampler: return "a sampler";
    case Descriptor::storage_buffer: return "a storage buffer";
    case Descriptor::uniform_buffer: return "a uniform buffer";
    case Descriptor::other: break;
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

// The interface the sample pass gives the shader (see the header); throws naming the first mismatch.
void check_interface(const std::vector<uint32_t>& words, const std::string& name)
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
    auto descriptor = [&](uint32_t storage, uint32_t type) {
        auto t = types.find(type);
        while (t != types.end() && (t->second.opcode == OpTypeArray || t->second.opcode == OpTypeRuntimeArray))
            t = types.find(t->second.operands[1]);
        const uint32_t op = t == types.end() ? 0 : t->second.opcode;
        if (storage == StorageUniformConstant && op == OpTypeSampledImage)
            return Descriptor::combined;
        if (storage == StorageUniformConstant && op == OpTypeImage) // operand 7: Sampled (1 sampled, 2 storage)
            return t->second.count > 6 && t->second.operands[6] == 2 ? Descriptor::storage_image
                                                                     : Descriptor::sampled_image;
        if (storage == StorageUniformConstant && op == OpTypeSampler)
            return Descriptor::sampler;
        if (op == OpTypeStruct && storage == StorageStorageBuffer)
            return Descriptor::storage_buffer;
        if (op == OpTypeStruct && storage == StorageUniform)
            return buffer_block[t->first] ? Descriptor::storage_buffer : Descriptor::uniform_buffer;
        return Descriptor::other;
    };
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
            throw Error(name + ": a resource in descriptor set " + std::to_string(set[id]) +
                        "; the sample pass binds set 0 only");
        const auto expected = sample_bindings().find(binding[id]);
        if (expected == sample_bindings().end())
            throw Error(name + ": a resource at " + where + ", which the sample pass does not bind");
        const Descriptor found = descriptor(storage, pointee);
        if (found != expected->second)
            throw Error(name + ": " + where + " is " + to_string(found) + "; the sample pass binds " +
                        to_string(expected->second) + " there");
    }
}

} // namespace

std::vector<uint32_t> check_sample_spirv(const std::string& bytes, const std::string& name)
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
    check_interface(words, name);
    return words;
}

} // namespace tf
