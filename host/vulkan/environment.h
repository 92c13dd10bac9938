#pragma once
// Environment maps on the device (docs/ENVIRONMENT.md): a cube map (one CUBE_COMPATIBLE RGBA32F image, a face
// a layer, a CUBE view) or a lat-long 2D texture, and the environment scenes (skybox, reflect) drawn from
// them by render_env.frag.glsl, compiled once a map kind.
#include "core/environment.h"
#include "vulkan/render.h"
#include <memory>

namespace tf {

struct GpuEnvironment {
    EnvMap map = EnvMap::cube;
    GpuImage image; // every level (of every face), SHADER_READ_ONLY_OPTIMAL
    int width = 0, height = 0, levels = 0;
};

// Throws tf::Error when the device cannot hold the image (its size against maxImageDimensionCube / 2D).
GpuEnvironment upload_cube_environment(const VulkanContext& context, const CubeMap& cube);
GpuEnvironment upload_latlong_environment(const VulkanContext& context, const MipChain& chain);
void destroy_environment(const VulkanContext& context, GpuEnvironment& environment);

// One environment scene's renderer (fragment stage; core/environment.h's filters, the color view only): binds the map at HARNESS_BINDING_TEXTURE through a
// LINEAR sampler (hardware taps) or the hw-* state, and a cube again through a NEAREST one at
// HARNESS_BINDING_TEXTURE_NEAREST (the manual filters' texel reads). render_frame draws it.
std::unique_ptr<GpuRenderer> create_environment_renderer(const VulkanContext& context, const GpuEnvironment& environment,
                                                         const SceneParams& scene, const SamplerOptions& options,
                                                         const RenderOptions& render);
Image gpu_render_environment(const VulkanContext& context, const GpuEnvironment& environment, const SceneParams& scene,
                             const SamplerOptions& options, const RenderOptions& render);

} // namespace tf
