#include "vulkan/gpu_build.h"
#include "harness/config.h"
#include "texture/error.h"
#include "vulkan/device.h"
#include "vulkan/memory.h"
#include "vulkan/pipelines.h"
#include <algorithm>
#include <array>
#include <cstring>

#include "build_mip_comp.h"
#include "build_sat_comp.h"
#include "dynamic_texture_comp.h"

namespace tf {

// The GPU MIP and SAT builds: pipelines, per-texture targets, and the commands of each build.
namespace {

// build_mip's and build_sat's push constants (HARNESS_BUILD_PUSH_SIZE bytes).
struct BuildPush {
    int32_t size[2];
    int32_t source_level_or_pass;
    int32_t levels;
    int32_t tail;
    int32_t pad[3];
};
static_assert(sizeof(BuildPush) == HARNESS_BUILD_PUSH_SIZE && sizeof(PackPush) == HARNESS_BUILD_PUSH_SIZE);

void compute_to_compute(VkCommandBuffer cb)
{
    memory_barrier(cb, {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT},
                       {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT});
}

void transfer_to_compute(VkCommandBuffer cb)
{
    memory_barrier(cb, {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT},
                       {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT});
}

} // namespace

GpuBuildKernels create_gpu_build_kernels(const VulkanContext& context, Cleanup& cleanup)
{
    GpuBuildKernels k;
    k.mip_set_layout = create_set_layout(
        context,
        {{HARNESS_BUILD_BINDING_LEVELS, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, HARNESS_MIP_MAX_LEVELS,
          VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
         {HARNESS_BUILD_BINDING_COUNTER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}},
        cleanup);
    k.sat_set_layout = create_set_layout(
        context,
        {{HARNESS_BUILD_BINDING_LEVEL0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
         {HARNESS_BUILD_BINDING_SAT_LOW, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
         {HARNESS_BUILD_BINDING_SAT_HIGH, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
         {HARNESS_BUILD_BINDING_RANGE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}},
        cleanup);
    k.mip_layout = create_push_layout(context, k.mip_set_layout, sizeof(BuildPush), cleanup);
    k.sat_layout = create_push_layout(context, k.sat_set_layout, sizeof(BuildPush), cleanup);
    k.mip = create_compute_pipeline(context, {build_mip_comp, sizeof(build_mip_comp)}, k.mip_layout, Filter::nearest,
                                    cleanup);
    k.exact_sat = context.info.shader_float64;
    const SpirvWords fp32 = build_sat_spirv_fp32();
    const ShaderCode sat = k.exact_sat ? ShaderCode{build_sat_comp, sizeof(build_sat_comp)}
                                       : ShaderCode{fp32.words, fp32.bytes};
    k.sat = create_compute_pipeline(context, sat, k.sat_layout, Filter::nearest, cleanup);
    {
        k.pack_set_layout = create_set_layout(
            context,
            {{HARNESS_BUILD_BINDING_LEVELS, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, HARNESS_MIP_MAX_LEVELS,
              VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
             {HARNESS_BUILD_BINDING_CODES, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, HARNESS_MIP_MAX_LEVELS,
              VK_SHADER_STAGE_COMPUTE_BIT, nullptr}},
            cleanup);
        k.pack_layout = create_push_layout(context, k.pack_set_layout, sizeof(PackPush), cleanup);
    }
    return k;
}

MipBuildTarget create_mip_build_target(const VulkanContext& context, const GpuBuildKernels& kernels, VkImage image,
                                       int width, int height, Cleanup& cleanup)
{
    const int limit = int(std::min<uint32_t>(context.info.max_image_dimension_2d, 1u << (HARNESS_MIP_MAX_LEVELS - 1)));
    if (width < 1 || height < 1 || width > limit || height > limit)
        throw Error("GPU MIP build: texture " + std::to_string(width) + "x" + std::to_string(height) +
                    " is outside 1.." + std::to_string(limit) + " a side (maxImageDimension2D of " + context.info.name +
                    ", at most 16384)");
    MipBuildTarget t;
    t.width = width;
    t.height = height;
    t.levels = mip_level_count(width, height);
    t.plan = plan_mip_build(width, height);
    for (int l = 0; l < t.levels; ++l)
        t.level_views.push_back(create_level_view(context, image, VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t(l), cleanup));
    t.counter = create_device_buffer(context, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    cleanup.add([&context, buffer = t.counter]() mutable { destroy_buffer(context, buffer); });
    t.set = allocate_set(context, kernels.mip_set_layout,
                         {{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, HARNESS_MIP_MAX_LEVELS},
                          {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}},
                         t.pool, cleanup);
    // Every element of the array is written (views past the last level repeat level 0: never stored to).
    std::array<VkDescriptorImageInfo, HARNESS_MIP_MAX_LEVELS> images{};
    for (size_t l = 0; l < images.size(); ++l)
        images[l] = {VK_NULL_HANDLE, t.level_views[l < t.level_views.size() ? l : 0], VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorBufferInfo counter{t.counter.buffer, 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet writes[2]{{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}, {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}};
    writes[0].dstSet = t.set;
    writes[0].dstBinding = HARNESS_BUILD_BINDING_LEVELS;
    writes[0].descriptorCount = HARNESS_MIP_MAX_LEVELS;
    writes[0].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    writes[0].pImageInfo = images.data();
    writes[1].dstSet = t.set;
    writes[1].dstBinding = HARNESS_BUILD_BINDING_COUNTER;
    writes[1].descriptorCount = 1;
    writes[1].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[1].pBufferInfo = &counter;
    vkUpdateDescriptorSets(context.device, 2, writes, 0, nullptr);
    return t;
}

void record_mip_build(VkCommandBuffer cb, const GpuBuildKernels& kernels, const MipBuildTarget& target)
{
    if (target.plan.empty())
        return; // 1x1: level 0 is the chain
    vkCmdFillBuffer(cb, target.counter.buffer, 0, VK_WHOLE_SIZE, 0u);
    transfer_to_compute(cb);
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, kernels.mip);
    vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, kernels.mip_layout, 0, 1, &target.set, 0, nullptr);
    for (size_t i = 0; i < target.plan.size(); ++i) {
        const MipBuildPass& pass = target.plan[i];
        if (i > 0)
            compute_to_compute(cb); // the pass reads the level the last one wrote
        const BuildPush push{{target.width, target.height}, pass.source_level, pass.levels, pass.tail ? 1 : 0, {}};
        vkCmdPushConstants(cb, kernels.mip_layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
        vkCmdDispatch(cb, uint32_t(pass.groups_x), uint32_t(pass.groups_y), 1);
    }
}

SatImages create_sat_images(const VulkanContext& context, int width, int height)
{
    if (width < 1 || height < 1 || width > sat_max_dimension || height > sat_max_dimension)
        throw Error("GPU summed-area table: texture " + std::to_string(width) + "x" + std::to_string(height) +
                    " is outside 1.." + std::to_string(sat_max_dimension) +
                    " a side (40-bit sums are exact only up to 4096x4096 texels of 16 bits)");
    if (uint32_t(width) + 1 > context.info.max_image_dimension_2d || uint32_t(height) + 1 > context.info.max_image_dimension_2d)
        throw Error("the summed-area table of a " + std::to_string(width) + "x" + std::to_string(height) +
                    " texture needs one more texel a side than maxImageDimension2D = " +
                    std::to_string(context.info.max_image_dimension_2d));
    const uint32_t tw = uint32_t(width) + 1, th = uint32_t(height) + 1;
    const VkImageUsageFlags usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    SatImages images;
    Cleanup on_failure;
    on_failure.add([&] { destroy_sat_images(context, images); });
    images.low = create_image(context, VK_FORMAT_R32G32B32A32_UINT, tw, th, 1, usage, VK_IMAGE_ASPECT_COLOR_BIT);
    images.high = create_image(context, VK_FORMAT_R32_UINT, tw, th, 1, usage, VK_IMAGE_ASPECT_COLOR_BIT);
    on_failure.dismiss();
    return images;
}

void destroy_sat_images(const VulkanContext& context, SatImages& images)
{
    destroy_image(context, images.low);
    destroy_image(context, images.high);
}

SatBuildTarget create_sat_build_target(const VulkanContext& context, const GpuBuildKernels& kernels,
                                       VkImageView level0_view, const SatImages& images, int width, int height,
                                       Cleanup& cleanup)
{
    SatBuildTarget t;
    t.width = width;
    t.height = height;
    t.low = images.low;
    t.high = images.high;
    const VkDeviceSize range_bytes = sat_range_words * sizeof(uint32_t);
    t.range = create_device_buffer(context, range_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                                             VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                                             VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    cleanup.add([&context, buffer = t.range]() mutable { destroy_buffer(context, buffer); });
    t.readback = create_host_buffer(context, range_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    cleanup.add([&context, buffer = t.readback]() mutable { destroy_buffer(context, buffer); });
    t.set = allocate_set(context, kernels.sat_set_layout,
                         {{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 3}, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}}, t.pool,
                         cleanup);
    const VkDescriptorImageInfo views[3] = {{VK_NULL_HANDLE, level0_view, VK_IMAGE_LAYOUT_GENERAL},
                                            {VK_NULL_HANDLE, t.low.view, VK_IMAGE_LAYOUT_GENERAL},
                                            {VK_NULL_HANDLE, t.high.view, VK_IMAGE_LAYOUT_GENERAL}};
    const VkDescriptorBufferInfo range{t.range.buffer, 0, range_bytes};
    VkWriteDescriptorSet writes[4];
    const uint32_t bindings[3] = {HARNESS_BUILD_BINDING_LEVEL0, HARNESS_BUILD_BINDING_SAT_LOW,
                                  HARNESS_BUILD_BINDING_SAT_HIGH};
    for (int i = 0; i < 4; ++i) {
        writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[i].dstSet = t.set;
        writes[i].descriptorCount = 1;
        if (i < 3) {
            writes[i].dstBinding = bindings[i];
            writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
            writes[i].pImageInfo = &views[i];
        } else {
            writes[i].dstBinding = HARNESS_BUILD_BINDING_RANGE;
            writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
            writes[i].pBufferInfo = &range;
        }
    }
    vkUpdateDescriptorSets(context.device, 4, writes, 0, nullptr);
    return t;
}

void record_sat_layouts(VkCommandBuffer cb, const SatBuildTarget& target)
{
    for (VkImage image : {target.low.image, target.high.image})
        image_barrier(cb, {.image = image, .from = scope::undefined, .to = scope::compute_read_write});
}

void record_sat_build(VkCommandBuffer cb, const GpuBuildKernels& kernels, const SatBuildTarget& target)
{
    const std::array<uint32_t, sat_range_words> initial = sat_range_initial();
    vkCmdUpdateBuffer(cb, target.range.buffer, 0, sizeof initial, initial.data());
    transfer_to_compute(cb);
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, kernels.sat);
    vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, kernels.sat_layout, 0, 1, &target.set, 0, nullptr);
    const uint32_t texels = uint32_t(target.width) * uint32_t(target.height);
    const uint32_t per_group = 256u * 16u; // TF_SAT_GROUP_SIZE x TF_SAT_RANGE_TEXELS
    const uint32_t groups[3] = {(texels + per_group - 1) / per_group, uint32_t(target.height) + 1,
                                (uint32_t(target.width) + 1 + 15) / 16};
    const int passes[3] = {HARNESS_SAT_PASS_RANGE, HARNESS_SAT_PASS_ROWS, HARNESS_SAT_PASS_COLUMNS};
    for (int i = 0; i < 3; ++i) {
        if (i > 0)
            compute_to_compute(cb);
        const BuildPush push{{target.width, target.height}, passes[i], 0, 0, {}};
        vkCmdPushConstants(cb, kernels.sat_layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
        vkCmdDispatch(cb, groups[i], 1, 1);
    }
    // The range words to the host (the filters' offset and scale).
    memory_barrier(cb, {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT},
                       {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT});
    const VkBufferCopy copy{0, 0, sat_range_words * sizeof(uint32_t)};
    vkCmdCopyBuffer(cb, target.range.buffer, target.readback.buffer, 1, &copy);
    memory_barrier(cb, {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT},
                       {VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT});
}

namespace {

VkFormat code_format(TextureFormat format)
{
    const FormatInfo& info = format_info(format);
    if (info.channels == 4)
        return info.bits == 8 ? VK_FORMAT_R8G8B8A8_UINT : info.bits == 16 ? VK_FORMAT_R16G16B16A16_UINT
                                                                          : VK_FORMAT_R32G32B32A32_UINT;
    return info.bits == 8 ? VK_FORMAT_R8_UINT : info.bits == 16 ? VK_FORMAT_R16_UINT : VK_FORMAT_R32_UINT;
}

int encoding_id(ChannelEncoding encoding)
{
    switch (encoding) {
    case ChannelEncoding::float16: return HARNESS_ENCODING_FLOAT16;
    case ChannelEncoding::unorm8: return HARNESS_ENCODING_UNORM8;
    case ChannelEncoding::srgb8: return HARNESS_ENCODING_SRGB8;
    default: return HARNESS_ENCODING_FLOAT32;
    }
}

} // namespace

// The pack_level variant whose store's format qualifier is the integer view's.
SpirvWords pack_spirv(VkFormat codes)
{
    switch (codes) {
    case VK_FORMAT_R8G8B8A8_UINT: return pack_spirv_rgba8ui();
    case VK_FORMAT_R16G16B16A16_UINT: return pack_spirv_rgba16ui();
    case VK_FORMAT_R8_UINT: return pack_spirv_r8ui();
    case VK_FORMAT_R16_UINT: return pack_spirv_r16ui();
    default: return pack_spirv_r32ui();
    }
}

bool pack_supported(const VulkanContext& context, const GpuBuildKernels&, TextureFormat format)
{
    const FormatInfo& info = format_info(format);
    if (info.integer || (info.channels == 4 && info.bits == 32))
        return false;
    const VkFormat codes = code_format(format);
    // r8ui and r16ui are extended storage formats (a shader capability of their own).
    if ((codes == VK_FORMAT_R8_UINT || codes == VK_FORMAT_R16_UINT) && !context.info.storage_image_extended_formats)
        return false;
    VkFormatProperties properties{};
    vkGetPhysicalDeviceFormatProperties(context.physical, codes, &properties);
    return (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT) != 0;
}

PackTarget create_pack_target(const VulkanContext& context, const GpuBuildKernels& kernels, const MipBuildTarget& mip,
                              VkImage format_image, TextureFormat format, Cleanup& cleanup)
{
    const FormatInfo& info = format_info(format);
    PackTarget p;
    p.code_format = code_format(format);
    const SpirvWords words = pack_spirv(p.code_format);
    p.pipeline = create_compute_pipeline(context, {words.words, words.bytes}, kernels.pack_layout, Filter::nearest, cleanup);
    p.channels = info.channels;
    p.encoding = encoding_id(info.encoding);
    p.alpha_encoding = encoding_id(info.encoding == ChannelEncoding::srgb8 ? ChannelEncoding::unorm8 : info.encoding);
    for (int l = 0; l < mip.levels; ++l)
        p.code_views.push_back(create_level_view(context, format_image, p.code_format, uint32_t(l), cleanup));
    p.set = allocate_set(context, kernels.pack_set_layout, {{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 2 * HARNESS_MIP_MAX_LEVELS}},
                         p.pool, cleanup);
    std::array<VkDescriptorImageInfo, HARNESS_MIP_MAX_LEVELS> levels{}, codes{};
    // Level 0 and the entries past the last level are never stored to: they repeat level 1's views, which
    // are in GENERAL while the pass runs (the layer checks every element's layout).
    for (size_t l = 0; l < levels.size(); ++l) {
        const size_t v = l >= 1 && l < p.code_views.size() ? l : std::min<size_t>(1, p.code_views.size() - 1);
        levels[l] = {VK_NULL_HANDLE, mip.level_views[v], VK_IMAGE_LAYOUT_GENERAL};
        codes[l] = {VK_NULL_HANDLE, p.code_views[v], VK_IMAGE_LAYOUT_GENERAL};
    }
    VkWriteDescriptorSet writes[2]{{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}, {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}};
    for (int i = 0; i < 2; ++i) {
        writes[i].dstSet = p.set;
        writes[i].dstBinding = i == 0 ? HARNESS_BUILD_BINDING_LEVELS : HARNESS_BUILD_BINDING_CODES;
        writes[i].descriptorCount = HARNESS_MIP_MAX_LEVELS;
        writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
        writes[i].pImageInfo = i == 0 ? levels.data() : codes.data();
    }
    vkUpdateDescriptorSets(context.device, 2, writes, 0, nullptr);
    return p;
}

void record_pack_levels(VkCommandBuffer cb, const GpuBuildKernels& kernels, const PackTarget& pack,
                        const MipBuildTarget& mip)
{
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pack.pipeline);
    vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, kernels.pack_layout, 0, 1, &pack.set, 0, nullptr);
    for (int l = 1; l < mip.levels; ++l) {
        const int w = std::max(1, mip.width >> l), h = std::max(1, mip.height >> l);
        const PackPush push{{w, h}, l, pack.encoding, pack.alpha_encoding, pack.channels, {}};
        vkCmdPushConstants(cb, kernels.pack_layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
        vkCmdDispatch(cb, uint32_t(w + 15) / 16, uint32_t(h + 15) / 16, 1);
    }
}

void read_sat_range(const SatBuildTarget& target, const std::string& texture_name, glm::vec4& offset,
                    glm::vec4& scale)
{
    std::array<uint32_t, sat_range_words> words{};
    std::memcpy(words.data(), target.readback.mapped, sizeof words);
    sat_range_offset_scale(words, target.width, texture_name, offset, scale);
}

// A texture whose levels and summed-area table the device builds (--build gpu): level 0 up as RGBA32F,
// then record_mip_build and record_sat_build, and for a format other than RGBA32F a blit a level.
namespace {

void check_features(const VulkanContext& context, VkFormat format, VkFormatFeatureFlags needed, const std::string& what)
{
    VkFormatProperties properties{};
    vkGetPhysicalDeviceFormatProperties(context.physical, format, &properties);
    if ((properties.optimalTilingFeatures & needed) != needed)
        throw Error("--build gpu: " + context.info.name + " cannot " + what);
}

constexpr VkPipelineStageFlags shader_stages = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;

// Staging: level 0 as RGBA32F (what the levels are built from: as given, like build_mip_chain); for another
// format, level 0 as the format stores it, then (with a table) its rounded texels as RGBA32F, which the table
// sums (as load_texture's quantise_chain does before build_sat).
void fill_staging(const VulkanContext& context, GpuBuild& b, const Image& level0, Cleanup& objects)
{
    const TextureFormat format = b.texture.format;
    const size_t texels = level0.texels.size();
    b.float_bytes = texels * sizeof(glm::vec4);
    const size_t packed_bytes = b.in_place ? 0 : texels * texel_bytes(format);
    b.rounded_offset = b.float_bytes + (packed_bytes + 15) / 16 * 16;
    const size_t total = b.in_place ? b.float_bytes : b.rounded_offset + (b.with_sat ? b.float_bytes : 0);
    b.staging = create_host_buffer(context, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    objects.add([&context, buffer = b.staging]() mutable { destroy_buffer(context, buffer); });
    advise_huge_pages(b.staging.mapped, total);
    char* bytes = static_cast<char*>(b.staging.mapped);
    std::memcpy(bytes, level0.texels.data(), b.float_bytes);
    if (!b.in_place)
        pack_texels(level0.texels.data(), texels, format, bytes + b.float_bytes);
    if (!b.in_place && b.with_sat) {
        glm::vec4* rounded = reinterpret_cast<glm::vec4*>(bytes + b.rounded_offset);
        for (size_t i = 0; i < texels; ++i)
            rounded[i] = quantise_texel(level0.texels[i], format);
    }
}

} // namespace

GpuBuild prepare_gpu_build(const VulkanContext& context, const Image* level0, int w, int h, bool with_sat,
                           TextureFormat format)
{
    check_gpu_build(format, "");
    if (w < 1 || h < 1 || (level0 && (level0->width != w || level0->height != h ||
                                      level0->texels.size() != size_t(w) * size_t(h))))
        throw Error("--build gpu: level 0 of " + std::to_string(w) + "x" + std::to_string(h) + " is not whole");
    check_format_support(context, format, SamplerOptions{});
    check_features(context, VK_FORMAT_R32G32B32A32_SFLOAT, VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT | VK_FORMAT_FEATURE_BLIT_SRC_BIT,
                   "store into or blit from R32G32B32A32_SFLOAT images");
    GpuBuild b;
    b.in_place = format == TextureFormat::rgba32f;
    if (!b.in_place && !level0)
        throw Error("--build gpu: a level 0 written on the device is RGBA32F (no format conversion of level 0)");
    b.with_sat = with_sat;
    b.objects = std::make_shared<Cleanup>();
    Cleanup& objects = *b.objects;
    Cleanup on_failure; // a half-made build undone: its texture's images and its objects
    on_failure.add([&] { destroy_gpu_build(context, b); });
    b.kernels = create_gpu_build_kernels(context, objects);
    b.pack = !b.in_place && pack_supported(context, b.kernels, format);
    if (!b.in_place && !b.pack)
        check_features(context, vk_format(format), VK_FORMAT_FEATURE_BLIT_DST_BIT, "blit into " + to_string(format) + " images");
    GpuTexture& t = b.texture;
    t.format = format;
    t.filterable = format_filterable(context, format);
    t.width = w;
    t.height = h;
    t.levels = mip_level_count(w, h);
    const uint32_t levels = uint32_t(t.levels);
    b.built = create_image(context, VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t(w), uint32_t(h), levels,
                           gpu_build_chain_usage, VK_IMAGE_ASPECT_COLOR_BIT);
    if (b.in_place) {
        t.chain = b.built;
    } else {
        objects.add([&context, image = b.built]() mutable { destroy_image(context, image); });
        const VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                        VK_IMAGE_USAGE_TRANSFER_SRC_BIT | (b.pack ? VkImageUsageFlags(VK_IMAGE_USAGE_STORAGE_BIT) : 0u);
        t.chain = create_image(context, vk_format(format), uint32_t(w), uint32_t(h), levels, usage,
                               VK_IMAGE_ASPECT_COLOR_BIT, 1, VK_IMAGE_VIEW_TYPE_2D, b.pack ? gpu_pack_image_flags : 0u);
    }
    b.mip = create_mip_build_target(context, b.kernels, b.built.image, w, h, objects);
    if (b.pack)
        b.pack_target = create_pack_target(context, b.kernels, b.mip, t.chain.image, format, objects);
    if (with_sat) {
        const SatImages images = create_sat_images(context, w, h); // the texture's (destroy_texture)
        t.sat_low = images.low;
        t.sat_high = images.high;
        b.sat = create_sat_build_target(context, b.kernels, b.mip.level_views[0], images, w, h, objects);
    } else {
        upload_empty_sat(context, t);
    }
    if (level0)
        fill_staging(context, b, *level0, objects);
    on_failure.dismiss();
    return b;
}

namespace {

// Level 0 (RGBA32F, or as the format stores it) from the staging buffer at `offset` into `image`, in
// TRANSFER_DST_OPTIMAL.
void copy_level0(VkCommandBuffer cb, const GpuBuild& b, VkDeviceSize offset, VkImage image)
{
    VkBufferImageCopy copy{};
    copy.bufferOffset = offset;
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {uint32_t(b.texture.width), uint32_t(b.texture.height), 1};
    vkCmdCopyBufferToImage(cb, b.staging.buffer, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
}

// `built` in GENERAL with level 0 visible to the build's compute reads: copied from the staging buffer, or
// as the caller's compute shader just wrote it.
void record_level0(VkCommandBuffer cb, const GpuBuild& b, Level0 level0)
{
    const uint32_t levels = uint32_t(b.texture.levels);
    if (level0 != Level0::from_staging) {
        memory_barrier(cb, {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT},
                           {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT});
        return;
    }
    image_barrier(cb, {.image = b.built.image, .from = scope::undefined, .to = scope::transfer_dst, .levels = levels});
    copy_level0(cb, b, 0, b.built.image);
    image_barrier(cb, {.image = b.built.image, .from = scope::transfer_dst, .to = scope::compute_read_write,
                       .levels = levels});
}

// The summed-area table, after the MIP build.
void record_table(VkCommandBuffer cb, const GpuBuild& b, Level0 level0)
{
    if (!b.in_place && level0 == Level0::from_staging) {
        // The table sums the texels the format stores: level 0 rounded, over the unrounded one the levels
        // were built from (the build's reads done first).
        image_barrier(cb, {.image = b.built.image, .from = scope::compute_read_write, .to = scope::transfer_dst});
        copy_level0(cb, b, b.rounded_offset, b.built.image);
        image_barrier(cb, {.image = b.built.image, .from = scope::transfer_dst,
                           .to = {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT, VK_IMAGE_LAYOUT_GENERAL}});
    }
    // The build's dispatches bind every level writable (the validator counts level 0 as written).
    memory_barrier(cb, {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT},
                       {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT});
    record_sat_build(cb, b.kernels, b.sat);
    for (VkImage image : {b.sat.low.image, b.sat.high.image})
        image_barrier(cb, {.image = image, .from = scope::compute_write, .to = scope::shader_read});
}

// The format's image: level 0 as the format stores it (copied), levels 1.. stored by pack_level with the
// host's codes.
void record_packed_levels(VkCommandBuffer cb, const GpuBuild& b, BarrierScope previous)
{
    const GpuTexture& t = b.texture;
    const uint32_t levels = uint32_t(t.levels);
    image_barrier(cb, {.image = t.chain.image, .from = previous, .to = scope::transfer_dst});
    copy_level0(cb, b, b.float_bytes, t.chain.image);
    image_barrier(cb, {.image = t.chain.image, .from = scope::transfer_dst, .to = scope::shader_read});
    if (levels > 1) {
        image_barrier(cb, {.image = t.chain.image, .from = previous, .to = scope::compute_write,
                           .levels = levels - 1, .base_level = 1});
        memory_barrier(cb, {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT},
                           {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT});
        record_pack_levels(cb, b.kernels, b.pack_target, b.mip);
        image_barrier(cb, {.image = t.chain.image, .from = scope::compute_write, .to = scope::shader_read,
                           .levels = levels - 1, .base_level = 1});
    }
    image_barrier(cb, {.image = b.built.image, .from = scope::compute_write, .to = scope::shader_read,
                       .levels = levels});
}

// No integer stores: level 0 as the format stores it; every other level blitted (1:1, nearest: a format
// conversion with the device's rounding).
void record_blitted_levels(VkCommandBuffer cb, const GpuBuild& b, BarrierScope previous)
{
    const GpuTexture& t = b.texture;
    const uint32_t levels = uint32_t(t.levels);
    image_barrier(cb, {.image = b.built.image, .from = scope::compute_write, .to = scope::transfer_src,
                       .levels = levels});
    image_barrier(cb, {.image = t.chain.image, .from = previous, .to = scope::transfer_dst, .levels = levels});
    copy_level0(cb, b, b.float_bytes, t.chain.image);
    for (uint32_t l = 1; l < levels; ++l) {
        const int32_t lw = std::max(1, t.width >> l), lh = std::max(1, t.height >> l);
        VkImageBlit blit{};
        blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l, 0, 1};
        blit.dstSubresource = blit.srcSubresource;
        blit.srcOffsets[1] = blit.dstOffsets[1] = {lw, lh, 1};
        vkCmdBlitImage(cb, b.built.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, t.chain.image,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_NEAREST);
    }
    image_barrier(cb, {.image = t.chain.image, .from = scope::transfer_dst, .to = scope::shader_read, .levels = levels});
    // Leave `built` as an in-place build leaves its image, so a rebuild starts from one layout.
    image_barrier(cb, {.image = b.built.image, .from = scope::transfer_src,
                       .to = {VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
                       .levels = levels});
}

} // namespace

void record_gpu_build(VkCommandBuffer cb, GpuBuild& b, Level0 level0)
{
    // The images' side before this build: nothing (first build), else the last frame's reads.
    const bool first = level0 != Level0::written;
    const BarrierScope previous = first ? scope::undefined : BarrierScope{shader_stages, 0, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    record_level0(cb, b, level0);
    if (b.with_sat)
        for (VkImage image : {b.sat.low.image, b.sat.high.image}) // the last frame's reads before this build's writes
            image_barrier(cb, {.image = image, .from = previous, .to = scope::compute_read_write});
    record_mip_build(cb, b.kernels, b.mip);
    if (b.with_sat)
        record_table(cb, b, level0);
    if (b.in_place)
        image_barrier(cb, {.image = b.built.image, .from = scope::compute_write, .to = scope::shader_read,
                           .levels = uint32_t(b.texture.levels)});
    else if (b.pack)
        record_packed_levels(cb, b, previous);
    else
        record_blitted_levels(cb, b, previous);
}

void finish_gpu_build(GpuBuild& b, const std::string& texture_name)
{
    if (b.with_sat)
        read_sat_range(b.sat, texture_name, b.texture.sat_offset, b.texture.sat_scale);
}

void destroy_gpu_build(const VulkanContext& context, GpuBuild& b)
{
    destroy_texture(context, b.texture);
    b.objects.reset(); // runs the build objects' cleanup
    b = GpuBuild{};
}

GpuTexture upload_texture(const VulkanContext& context, const MipChain& chain, bool with_sat, TextureFormat format,
                          TextureBuild build)
{
    if (build == TextureBuild::gpu)
        return upload_gpu_built_texture(context, chain.levels.at(0), with_sat, format);
    return upload_texture(context, chain, with_sat, format);
}

GpuTexture upload_gpu_built_texture(const VulkanContext& context, const Image& level0, bool with_sat,
                                    TextureFormat format)
{
    GpuBuild b = prepare_gpu_build(context, &level0, level0.width, level0.height, with_sat, format);
    Cleanup cleanup;
    cleanup.add([&] { destroy_gpu_build(context, b); });
    submit_and_wait(context, [&](VkCommandBuffer cb) { record_gpu_build(cb, b, Level0::from_staging); });
    finish_gpu_build(b);
    GpuTexture t = b.texture;
    b.texture = GpuTexture{}; // handed on: the build's objects go, its images stay
    return t;
}

// The dynamic texture: its generator pipeline and each frame's commands.
namespace {

struct GeneratorPush {
    int32_t size, frame;
};

} // namespace

DynamicTexture create_dynamic_texture(const VulkanContext& context, int size)
{
    DynamicTexture d;
    d.size = size;
    d.build = prepare_gpu_build(context, nullptr, size, size, false, TextureFormat::rgba32f);
    Cleanup on_failure;
    on_failure.add([&] { destroy_dynamic_texture(context, d); });
    Cleanup& objects = *d.build.objects; // the generator's objects go with the build's
    d.set_layout = create_set_layout(context, {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}},
                                     objects);
    d.layout = create_push_layout(context, d.set_layout, sizeof(GeneratorPush), objects);
    d.pipeline = create_compute_pipeline(context, {dynamic_texture_comp, sizeof(dynamic_texture_comp)}, d.layout,
                                         Filter::nearest, objects);
    d.set = allocate_set(context, d.set_layout, {{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}}, d.pool, objects);
    const VkDescriptorImageInfo image{VK_NULL_HANDLE, d.build.mip.level_views[0], VK_IMAGE_LAYOUT_GENERAL};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = d.set;
    write.dstBinding = 0;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    write.pImageInfo = &image;
    vkUpdateDescriptorSets(context.device, 1, &write, 0, nullptr);
    on_failure.dismiss();
    return d;
}

void record_dynamic_frame(VkCommandBuffer cb, DynamicTexture& d, int frame)
{
    const uint32_t levels = uint32_t(d.build.texture.levels);
    // The last frame's reads (fragment or compute) before this frame's writes; the first frame discards.
    image_barrier(cb, {.image = d.build.built.image, .from = d.first ? scope::undefined : scope::shader_read,
                       .to = scope::compute_read_write, .levels = levels});
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, d.pipeline);
    vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, d.layout, 0, 1, &d.set, 0, nullptr);
    const GeneratorPush push{d.size, frame};
    vkCmdPushConstants(cb, d.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdDispatch(cb, uint32_t(d.size + 15) / 16, uint32_t(d.size + 15) / 16, 1);
    record_gpu_build(cb, d.build, d.first ? Level0::written_first : Level0::written);
    d.first = false;
}

void destroy_dynamic_texture(const VulkanContext& context, DynamicTexture& d)
{
    destroy_gpu_build(context, d.build);
    d = DynamicTexture{};
}

} // namespace tf
