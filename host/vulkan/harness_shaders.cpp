#include "vulkan/harness_shaders.h"

#include "mesh_frag.h"
#include "mesh_vert.h"
#include "minimal_comp.h"
#include "minimal_trilinear_comp.h"
#include "render_comp.h"
#include "render_frag.h"
#include "render_vert.h"
#include "sample_comp.h"

namespace tf {

ShaderCode harness_shader(HarnessShader shader, TextureFormat format)
{
    if (format_info(format).integer)
        return harness_shader_uint(shader);
    switch (shader) {
    case HarnessShader::render_vert: return {render_vert, sizeof(render_vert)};
    case HarnessShader::render_frag: return {render_frag, sizeof(render_frag)};
    case HarnessShader::render_comp: return {render_comp, sizeof(render_comp)};
    case HarnessShader::mesh_vert: return {mesh_vert, sizeof(mesh_vert)};
    case HarnessShader::mesh_frag: return {mesh_frag, sizeof(mesh_frag)};
    case HarnessShader::sample_comp: return {sample_comp, sizeof(sample_comp)};
    case HarnessShader::minimal_comp: return {minimal_comp, sizeof(minimal_comp)};
    case HarnessShader::minimal_trilinear_comp: return {minimal_trilinear_comp, sizeof(minimal_trilinear_comp)};
    }
    return {sample_comp, sizeof(sample_comp)};
}

} // namespace tf
