// The HARNESS_RESOURCE_UINT build of the harness shaders (generated/harness_uint/, on this object
// library's include path only).
#include "vulkan/pipelines.h"
#include "texture/error.h"

#include "mesh_frag.h"
#include "render_comp.h"
#include "render_frag.h"
#include "sample_comp.h"

namespace tf {

ShaderCode harness_shader_uint(HarnessShader shader)
{
    switch (shader) {
    case HarnessShader::render_frag: return {render_frag, sizeof(render_frag)};
    case HarnessShader::render_comp: return {render_comp, sizeof(render_comp)};
    case HarnessShader::mesh_frag: return {mesh_frag, sizeof(mesh_frag)};
    case HarnessShader::sample_comp: return {sample_comp, sizeof(sample_comp)};
    case HarnessShader::render_vert: // the vertex stages read no texture: one build serves every binding
    case HarnessShader::mesh_vert:
    case HarnessShader::minimal_comp:
        break;
    case HarnessShader::minimal_trilinear_comp: // reads a float sampler2D: the bench runs it on float formats only
        throw Error("the minimal trilinear pass reads a float texture, not an integer one");
        break;
    }
    return harness_shader(shader, TextureFormat::rgba32f);
}

} // namespace tf
