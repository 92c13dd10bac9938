#pragma once
// MIP chains and summed-area tables built on the device (build_mip.comp.glsl, build_sat.comp.glsl), a
// texture uploaded as level 0 and built there, and the dynamic texture made on the device every frame.
#include "core/texture_build.h"
#include "core/texture_format.h"
#include "texture/mip.h"
#include "texture/sat.h"
#include "vulkan/cleanup.h"
#include "vulkan/memory.h"
#include "vulkan/textures.h"
#include <glm/vec4.hpp>
#include <memory>
#include <string>
#include <vector>

namespace tf {

// What the filters read, built on the device: the MIP chain (build_mip.comp.glsl, the passes of
// tf::plan_mip_build) and the summed-area table (build_sat.comp.glsl), recorded into the caller's command
// buffer, so a texture made on the GPU can be built and filtered in one submission.
// The two build pipelines of one device. exact_sat: the SAT quantises in double (shaderFloat64), so its
// tables equal tf::build_sat's bit for bit; without doubles it quantises in float (within one level).
struct GpuBuildKernels {
    VkDescriptorSetLayout mip_set_layout = VK_NULL_HANDLE, sat_set_layout = VK_NULL_HANDLE;
    VkPipelineLayout mip_layout = VK_NULL_HANDLE, sat_layout = VK_NULL_HANDLE;
    VkPipeline mip = VK_NULL_HANDLE, sat = VK_NULL_HANDLE;
    bool exact_sat = false;
    // pack_level.comp.glsl: a level's codes into an integer view of the format's image, rounded as the host
    // rounds them (its pipeline, one an integer view format, is the PackTarget's).
    VkDescriptorSetLayout pack_set_layout = VK_NULL_HANDLE;
    VkPipelineLayout pack_layout = VK_NULL_HANDLE;
};
GpuBuildKernels create_gpu_build_kernels(const VulkanContext& context, Cleanup& cleanup);

// The push constants of pack_level.comp.glsl.
struct PackPush {
    int32_t size[2];
    int32_t level;
    int32_t encoding, alpha_encoding; // HARNESS_ENCODING_*
    int32_t channels;
    int32_t pad[2];
};

// The usage an RGBA32F chain image needs to be built in place (and copied from, and sampled).
constexpr VkImageUsageFlags gpu_build_chain_usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                                    VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;

// An RGBA32F image of width x height with every level (gpu_build_chain_usage), its per-level storage views
// and the descriptor set the MIP build binds.
struct MipBuildTarget {
    int width = 0, height = 0, levels = 0;
    std::vector<MipBuildPass> plan;
    std::vector<VkImageView> level_views; // one storage view a level; [0] is what the SAT build reads
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;
    Buffer counter; // the tail's group counter (device-local, cleared by each build)
};
// Throws tf::Error for a side outside 1..maxImageDimension2D or above 16384 (the shader's 15 views).
MipBuildTarget create_mip_build_target(const VulkanContext& context, const GpuBuildKernels& kernels, VkImage image,
                                       int width, int height, Cleanup& cleanup);

// Before: level 0 written and made visible to compute-shader reads, every level in GENERAL layout.
// After: levels 1.. written by compute shaders (the caller's barrier makes them visible to its reads).
void record_mip_build(VkCommandBuffer command_buffer, const GpuBuildKernels& kernels, const MipBuildTarget& target);

// The two table images of a width x height texture (RGBA32UI low words, R32UI high bytes, one texel more a
// side; storage + sampled). Throws tf::Error for a side outside 1..sat_max_dimension or beyond the device's
// maxImageDimension2D. The caller's, as create_image's image is (destroy_sat_images, or a GpuTexture's).
struct SatImages {
    GpuImage low, high;
};
SatImages create_sat_images(const VulkanContext& context, int width, int height);
void destroy_sat_images(const VulkanContext& context, SatImages& images);

// The range words and the descriptor set of a SAT build reading `level0_view` (a storage view of an RGBA32F
// level 0, GENERAL) into the images of create_sat_images (low and high: copies, not owned).
struct SatBuildTarget {
    int width = 0, height = 0;
    GpuImage low, high;
    Buffer range;    // device-local, the shader's TF_SAT_RANGE
    Buffer readback; // host-visible copy of it, written by record_sat_build
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;
};
// Everything made is destroyed by `cleanup`.
SatBuildTarget create_sat_build_target(const VulkanContext& context, const GpuBuildKernels& kernels,
                                       VkImageView level0_view, const SatImages& images, int width, int height,
                                       Cleanup& cleanup);

// Before: level 0 written and visible to compute-shader reads, low and high in GENERAL layout (as
// record_sat_layouts leaves them). After: both tables written by compute shaders, and the range words
// copied to target.readback and made visible to the host.
void record_sat_layouts(VkCommandBuffer command_buffer, const SatBuildTarget& target);
void record_sat_build(VkCommandBuffer command_buffer, const GpuBuildKernels& kernels, const SatBuildTarget& target);

// The format's levels 1.. from the RGBA32F chain, each code rounded as tf::pack_texels rounds it
// (pack_level.comp.glsl), through integer views (R8G8B8A8_UINT, ...) of an image created with
// gpu_pack_image_flags and STORAGE usage.
struct PackTarget {
    VkFormat code_format = VK_FORMAT_UNDEFINED;
    VkPipeline pipeline = VK_NULL_HANDLE; // pack_level for code_format
    std::vector<VkImageView> code_views; // one a level
    int encoding = 0, alpha_encoding = 0, channels = 4; // HARNESS_ENCODING_*
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;
};
constexpr VkImageCreateFlags gpu_pack_image_flags = VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT | VK_IMAGE_CREATE_EXTENDED_USAGE_BIT;
// Whether the device can store `format`'s codes (the integer view format supports storage; r8ui and r16ui
// also need shaderStorageImageExtendedFormats); else the levels are blitted (the device's own rounding).
bool pack_supported(const VulkanContext& context, const GpuBuildKernels& kernels, TextureFormat format);
PackTarget create_pack_target(const VulkanContext& context, const GpuBuildKernels& kernels, const MipBuildTarget& mip,
                              VkImage format_image, TextureFormat format, Cleanup& cleanup);
// Before: the chain's levels written and visible to compute reads; the format image's levels 1.. in GENERAL.
// After: levels 1.. of the format image written by compute shaders.
void record_pack_levels(VkCommandBuffer command_buffer, const GpuBuildKernels& kernels, const PackTarget& pack,
                        const MipBuildTarget& mip);

// Once the submission has completed: the table's offset and scale (sat_range_offset_scale: throws naming
// `texture_name` for a non-finite texel).
void read_sat_range(const SatBuildTarget& target, const std::string& texture_name, glm::vec4& offset,
                    glm::vec4& scale);

// A texture whose levels (and summed-area table) the device builds, in three steps so the build can share
// a submission with what fills level 0 and what filters the result: prepare_gpu_build makes the images and
// the build's objects, record_gpu_build records the build (any number of times: a dynamic texture is
// rebuilt every frame), finish_gpu_build reads the table's range once a submission has completed.
// upload_gpu_built_texture (below) is the three in one submission.
struct GpuBuild {
    GpuTexture texture;  // what the filters bind; its chain is `built` itself for RGBA32F
    GpuImage built;      // RGBA32F, every level, storage: where the levels are built
    bool in_place = true; // texture.chain is built (else each level is stored into the format:)
    bool pack = false;    // by pack_level with the host's rounding (else blitted: the device's rounding)
    PackTarget pack_target;
    bool with_sat = false;
    GpuBuildKernels kernels;
    MipBuildTarget mip;
    SatBuildTarget sat;
    Buffer staging;        // level 0 as RGBA32F, then packed in the format (no staging without level 0)
    size_t float_bytes = 0;    // staging: level 0 as given at 0, packed at float_bytes,
    size_t rounded_offset = 0; // and rounded to the format (what the table sums) here
    // The build's own objects (not the texture's images, which destroy_texture destroys), and what a user of
    // the build adds (a dynamic texture's generator): destroyed together by destroy_gpu_build.
    std::shared_ptr<Cleanup> objects;
};

// level0: uploaded by the first record_gpu_build (null: the caller writes level 0 of `built` itself, in
// GENERAL layout, before each record_gpu_build). Throws tf::Error as upload_gpu_built_texture.
GpuBuild prepare_gpu_build(const VulkanContext& context, const Image* level0, int width, int height, bool with_sat,
                           TextureFormat format);

// Where level 0 stands when the build is recorded.
enum class Level0 {
    from_staging,  // first build: every image UNDEFINED; copy level 0 from the staging buffer
    written,       // `built` in GENERAL, level 0 just written by a compute shader; the other images as the
                   // last record_gpu_build left them (SHADER_READ_ONLY), or UNDEFINED the first time
    written_first, // as written, the first time (texture images UNDEFINED)
};
// Leaves texture.chain and the tables in SHADER_READ_ONLY_OPTIMAL, visible to fragment and compute
// shaders. For a rebuild the caller first makes the last frame's reads finish before level 0's writes
// (built: SHADER_READ_ONLY -> GENERAL).
void record_gpu_build(VkCommandBuffer command_buffer, GpuBuild& build, Level0 level0);

// After a submission with record_gpu_build completed: texture.sat_offset and sat_scale (throws naming
// texture_name for a non-finite texel).
void finish_gpu_build(GpuBuild& build, const std::string& texture_name = "");

// Destroys the texture and the build's objects.
void destroy_gpu_build(const VulkanContext& context, GpuBuild& build);

// upload_texture (textures.h) where the texture is built as `build` says (--build).
// build = gpu: only chain.levels[0] is read (the rest may be missing); it is uploaded as RGBA32F and the
// device builds every other level (and the summed-area table, with_sat) in one submission
// (upload_gpu_built_texture). RGBA32F textures are built in place; other float formats in an RGBA32F
// intermediate, each level then blitted into the format (the blit encodes sRGB: sRGB storage images are
// not writable on most devices). Throws tf::Error as upload_texture, as check_gpu_build, and when the
// device cannot store RGBA32F or blit into the format.
GpuTexture upload_texture(const VulkanContext& context, const MipChain& chain, bool with_sat, TextureFormat format,
                          TextureBuild build);
GpuTexture upload_gpu_built_texture(const VulkanContext& context, const Image& level0, bool with_sat,
                                    TextureFormat format);

// Uploads the texture as `build` says, runs body(texture) and destroys it again, also when body throws.
template <typename Body>
auto with_texture(const VulkanContext& context, const MipChain& chain, bool with_sat, TextureFormat format,
                  TextureBuild build, Body&& body)
{
    GpuTexture texture = upload_texture(context, chain, with_sat, format, build);
    Cleanup cleanup;
    cleanup.add([&] { destroy_texture(context, texture); });
    return body(texture);
}

// The "dynamic" procedural texture made on the device every frame: a compute shader writes level 0
// (dynamic_texture.comp.glsl, tf::dynamic_texture's integers), the GPU build completes the chain, and the
// frame's filter reads it, all in the caller's command buffer: what a render target, a reflection probe or
// any animated texture asks of an engine's MIP builder (bench --gpu-build's dynamic row, the viewer).
struct DynamicTexture {
    GpuBuild build; // RGBA32F, built in place; build.texture is what the filters bind
    int size = 0;
    bool first = true; // the images have no contents yet
    VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE; // the generator's objects: in build.objects
};

// size x size (1..16384, the device's limits). No summed-area table: its range is read back after a
// build, so a table cannot be filtered in the frame that builds it (sat filters need a static texture).
DynamicTexture create_dynamic_texture(const VulkanContext& context, int size);

// Level 0 at `frame`, then the chain, recorded into `command_buffer`; afterwards the texture is in
// SHADER_READ_ONLY_OPTIMAL, visible to fragment and compute shaders. The previous frame's reads of the
// texture (recorded earlier in this or an earlier submission) finish before level 0 is rewritten.
void record_dynamic_frame(VkCommandBuffer command_buffer, DynamicTexture& texture, int frame);

void destroy_dynamic_texture(const VulkanContext& context, DynamicTexture& texture);

} // namespace tf
