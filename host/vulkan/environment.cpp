#include "vulkan/environment.h"
#include "core/analytic_texture.h"

#include "harness/config.h"
#include "texture/error.h"
#include "vulkan/pipelines.h"
#include "vulkan/render.h"
#include "vulkan/textures.h"
#include <cstring>

namespace tf {

namespace {

constexpr VkImageUsageFlags map_usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;

VkSampler make_sampler(const VulkanContext& context, const VkSamplerCreateInfo& info, Cleanup& cleanup)
{
    VkSampler sampler = VK_NULL_HANDLE;
    TF_VK(vkCreateSampler(context.device, &info, nullptr, &sampler));
    VkDevice device = context.device;
    cleanup.add([=] { vkDestroySampler(device, sampler, nullptr); });
    return sampler;
}

} // namespace

GpuEnvironment upload_cube_environment(const VulkanContext& context, const CubeMap& cube)
{
    const int size = cube.size();
    if (size < 1)
        throw Error("cube map: no faces to upload");
    if (uint32_t(size) > context.info.max_image_dimension_cube)
        throw Error("cube map: faces of " + std::to_string(size) + " texels exceed " + context.info.name +
                    "'s maxImageDimensionCube " + std::to_string(context.info.max_image_dimension_cube));
    GpuEnvironment e;
    e.map = EnvMap::cube;
    e.width = e.height = size;
    e.levels = int(cube.faces[0].levels.size());
    Cleanup on_failure;
    on_failure.add([&] { destroy_environment(context, e); });
    e.image = create_image(context, VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t(size), uint32_t(size), uint32_t(e.levels),
                           map_usage, VK_IMAGE_ASPECT_COLOR_BIT, cube_face_count, VK_IMAGE_VIEW_TYPE_CUBE,
                           VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT);
    upload_layers(context, e.image, std::vector<MipChain>(cube.faces.begin(), cube.faces.end()),
                  VK_IMAGE_ASPECT_COLOR_BIT, false);
    on_failure.dismiss();
    return e;
}

GpuEnvironment upload_latlong_environment(const VulkanContext& context, const MipChain& chain)
{
    const Image& base = chain.levels.at(0);
    const uint32_t max_side = context.info.max_image_dimension_2d;
    if (uint32_t(base.width) > max_side || uint32_t(base.height) > max_side)
        throw Error("lat-long map: " + std::to_string(base.width) + "x" + std::to_string(base.height) + " exceeds " +
                    context.info.name + "'s maxImageDimension2D " + std::to_string(max_side));
    GpuEnvironment e;
    e.map = EnvMap::latlong;
    e.width = base.width;
    e.height = base.height;
    e.levels = int(chain.levels.size());
    Cleanup on_failure;
    on_failure.add([&] { destroy_environment(context, e); });
    e.image = create_image(context, VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t(e.width), uint32_t(e.height),
                           uint32_t(e.levels), map_usage, VK_IMAGE_ASPECT_COLOR_BIT);
    upload_layers(context, e.image, {chain}, VK_IMAGE_ASPECT_COLOR_BIT, false);
    on_failure.dismiss();
    return e;
}

GpuEnvironment upload_environment(const VulkanContext& context, const EnvironmentMap& env)
{
    return env.map == EnvMap::cube ? upload_cube_environment(context, env.cube)
                                   : upload_latlong_environment(context, env.latlong);
}

void destroy_environment(const VulkanContext& context, GpuEnvironment& environment)
{
    destroy_image(context, environment.image);
    environment = GpuEnvironment{};
}

namespace {

// The map with the filter's sampler, and for a cube also with a nearest one.
std::vector<PassImages> environment_images(const VulkanContext& context, const GpuEnvironment& environment,
                                           const SamplerOptions& options, Cleanup& cleanup)
{
    // The filter's sampler (hw-*: its state; manual filters: trilinear for the hardware taps). A cube's
    // address modes are not used (cube sampling clamps and crosses faces itself); a lat-long map repeats in u
    // and clamps in v (the device cannot cross a pole).
    VkSamplerCreateInfo linear = sampler_create_info(context, options, environment.levels);
    linear.addressModeU = environment.map == EnvMap::latlong ? VK_SAMPLER_ADDRESS_MODE_REPEAT
                                                             : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    linear.addressModeV = linear.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    const VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    std::vector<PassImages> images = {{HARNESS_BINDING_TEXTURE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                       {{make_sampler(context, linear, cleanup), environment.image.view, layout}}}};
    if (environment.map == EnvMap::cube) {
        // The manual cube filters read each texel at its centre's direction: NEAREST in and between levels.
        VkSamplerCreateInfo nearest = linear;
        nearest.magFilter = nearest.minFilter = VK_FILTER_NEAREST;
        nearest.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
        nearest.anisotropyEnable = VK_FALSE;
        nearest.mipLodBias = 0.0f;
        nearest.minLod = 0.0f;
        nearest.maxLod = float(environment.levels - 1);
        images.push_back({HARNESS_BINDING_TEXTURE_NEAREST, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                          {{make_sampler(context, nearest, cleanup), environment.image.view, layout}}});
    }
    return images;
}

// The renderer's pipeline: the cache's for the same map kind, filter and size, else a new one (kept by the
// cache, or by the renderer).
VkPipeline environment_pipeline(const VulkanContext& context, const GpuEnvironment& environment, GpuRenderer& r,
                                const FilterVariant& variant, EnvironmentPipelineCache* cache)
{
    if (cache)
        for (const EnvironmentPipelineCache::Entry& e : cache->entries)
            if (e.map == environment.map && e.filter == variant && e.width == r.width && e.height == r.height)
                return e.pipeline;
    GraphicsPipelineDesc desc;
    desc.color_format = render_color_format;
    desc.width = r.width;
    desc.height = r.height;
    desc.vertex = harness_shader(HarnessShader::render_vert, TextureFormat::rgba32f);
    const SpirvWords fragment = environment.map == EnvMap::cube ? env_spirv_cube() : env_spirv_latlong();
    desc.fragment = {fragment.words, fragment.bytes};
    const VkPipeline pipeline = create_graphics_pipeline(context, desc, r.pass.pipeline_layout, variant,
                                                         cache ? cache->cleanup : r.cleanup);
    if (cache)
        cache->entries.push_back({environment.map, variant, r.width, r.height, pipeline});
    return pipeline;
}

} // namespace

std::unique_ptr<GpuRenderer> create_environment_renderer(const VulkanContext& context, const GpuEnvironment& environment,
                                                         const SceneParams& scene, const SamplerOptions& options,
                                                         const RenderOptions& render, EnvironmentPipelineCache* cache)
{
    check_environment_filter(options);
    check_environment_truth(options);
    if (render.view != DebugView::color)
        throw Error("--view " + to_string(render.view) + " is not available on the environment scenes: use --view color");
    if (render.stage != Stage::fragment)
        throw Error("the environment scenes render in the fragment stage only: use --stage fragment");
    auto renderer = std::make_unique<GpuRenderer>();
    GpuRenderer& r = *renderer;
    Cleanup& cleanup = r.cleanup;
    r.context = &context;
    r.kind = RenderKind::fragment;
    r.width = uint32_t(scene.kind_size.y);
    r.height = uint32_t(scene.kind_size.z);
    r.scene_kind = scene.kind_size.x; // render_frame draws this kind only (the shader's own cast: no constant)
    r.push = make_push_constants(options, 0, glm::vec4(0.0f), glm::vec4(0.0f));
    r.uniforms = create_host_buffer(context, sizeof(SceneParams), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    cleanup.add([&context, &r] { destroy_buffer(context, r.uniforms); });
    std::memcpy(r.uniforms.mapped, &scene, sizeof(SceneParams));
    r.targets = create_render_targets(context, r.width, r.height, false, cleanup);

    const std::vector<PassImages> images = environment_images(context, environment, options, cleanup);
    const std::vector<PassBuffer> buffers = {
        {HARNESS_BINDING_SCENE, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, r.uniforms.buffer, sizeof(SceneParams)}};
    r.pass = create_pass_with_images(context, images, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
                                     VK_SHADER_STAGE_FRAGMENT_BIT, buffers, cleanup);
    const FilterVariant variant = render_variant(options, render, -1); // views are refused above; no 2D cast
    r.pipeline = environment_pipeline(context, environment, r, variant, cache);
    return renderer;
}

Image gpu_render_environment(const VulkanContext& context, const GpuEnvironment& environment, const SceneParams& scene,
                             const SamplerOptions& options, const RenderOptions& render, EnvironmentPipelineCache* cache)
{
    return render_accumulated(*create_environment_renderer(context, environment, scene, options, render, cache), scene,
                              options);
}

} // namespace tf
