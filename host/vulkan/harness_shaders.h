#pragma once
// The harness shaders' SPIR-V for the way a texture is bound: the combined sampler2D build (every float
// format) or the HARNESS_RESOURCE_UINT build (usampler2D u_texture: r16ui, r32ui), the same sources
// compiled with -DHARNESS_RESOURCE=HARNESS_RESOURCE_UINT (host/vulkan/CMakeLists.txt).
#include "core/texture_format.h"
#include "vulkan/pipeline.h"

namespace tf {

enum class HarnessShader { render_vert, render_frag, render_comp, mesh_vert, mesh_frag, sample_comp,
                           minimal_comp, minimal_trilinear_comp }; // the last two: the bench's minimal pass

ShaderCode harness_shader(HarnessShader shader, TextureFormat format);

// The HARNESS_RESOURCE_UINT build (harness_shaders_uint.cpp, its own object library: the generated
// headers have the same names as the combined build's).
ShaderCode harness_shader_uint(HarnessShader shader);

} // namespace tf
