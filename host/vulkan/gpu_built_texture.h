#pragma once
// A texture whose levels (and summed-area table) the device builds, in three steps so the build can share
// a submission with what fills level 0 and what filters the result: prepare_gpu_build makes the images and
// the build's objects, record_gpu_build records the build (any number of times: a dynamic texture is
// rebuilt every frame), finish_gpu_build reads the table's range once a submission has completed.
// upload_gpu_built_texture (upload.h) is the three in one submission.
#include "core/texture_format.h"
#include "vulkan/gpu_build.h"
#include "vulkan/upload.h"
#include <memory>

namespace tf {

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
    std::shared_ptr<Cleanup> objects; // the build's own objects (not texture's images)
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

} // namespace tf
