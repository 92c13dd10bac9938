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
// Whichever of the two `env` holds.
GpuEnvironment upload_environment(const VulkanContext& context, const EnvironmentMap& env);
void destroy_environment(const VulkanContext& context, GpuEnvironment& environment);

// Environment pipelines kept for reuse by later renderers of one command or test (lavapipe spends most of a
// small render compiling its pipeline). A pipeline depends only on the key: every renderer of one map kind
// creates an identically defined pipeline layout. Destroy it (its cleanup) before the context, after the last
// frame using its pipelines completed.
struct EnvironmentPipelineCache {
    struct Entry {
        EnvMap map;
        FilterVariant filter; // the filter, --magnify and the gradients
        uint32_t width, height;
        VkPipeline pipeline;
    };
    std::vector<Entry> entries;
    Cleanup cleanup;
};

// One environment scene's renderer (fragment stage; core/environment.h's filters, the color view only): binds the map at HARNESS_BINDING_TEXTURE through a
// LINEAR sampler (hardware taps) or the hw-* state, and a cube again through a NEAREST one at
// HARNESS_BINDING_TEXTURE_NEAREST (the manual filters' texel reads). render_frame draws it.
std::unique_ptr<GpuRenderer> create_environment_renderer(const VulkanContext& context, const GpuEnvironment& environment,
                                                         const SceneParams& scene, const SamplerOptions& options,
                                                         const RenderOptions& render,
                                                         EnvironmentPipelineCache* cache = nullptr);
Image gpu_render_environment(const VulkanContext& context, const GpuEnvironment& environment, const SceneParams& scene,
                             const SamplerOptions& options, const RenderOptions& render,
                             EnvironmentPipelineCache* cache = nullptr);

} // namespace tf
