#pragma once
// A SPIR-V module from outside the build (`texfilter sample --spirv FILE`: the harness's sample.comp.glsl
// compiled by another compiler, e.g. Slang's slangc), checked before any work as every input is: SPIR-V at
// all, valid for Vulkan 1.2, and shaped to take the place of the built-in sample shader (its entry point and
// the descriptor bindings and push constants the sample pass of its resource kind provides). What the driver
// would otherwise meet as undefined behaviour is one message naming the file.
//
// Use: std::vector<uint32_t> words = check_sample_spirv(bytes, path, Resource::combined); then
// ShaderCode{words.data(), bytes}.
// Cost: one SPIRV-Tools validation (~10 ms for the harness module).
#include "core/resource.h"
#include <cstdint>
#include <string>
#include <vector>

namespace tf {

// `bytes`: the file's contents; `name`: its path, for the message. Throws tf::Error naming `name` and the
// first thing wrong: empty, not whole 32-bit words, no SPIR-V magic number (or the other byte order), the
// validator's first complaint, no GLCompute entry point "main", a resource outside descriptor set 0 or at a
// binding (or of a descriptor type, or a 2D image where a 2D array is bound or the other way round) that the
// sample pass of `resource` does not bind (harness_variant.h's sample_pass_bindings), a push constant member
// beyond HARNESS_PUSH_SIZE.
std::vector<uint32_t> check_sample_spirv(const std::string& bytes, const std::string& name, Resource resource);

} // namespace tf
