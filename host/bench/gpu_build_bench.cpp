#include "bench/gpu_build_bench.h"
#include "bench/metrics.h"
#include "core/procedural.h"
#include "scene/scene.h"
#include "texture/error.h"
#include "texture/mip.h"
#include "texture/sat.h"
#include "texture/threads.h"
#include "vulkan/memory.h"
#include "vulkan/timing.h"
#include "vulkan/gpu_build.h"
#include "vulkan/render.h"
#include "vulkan/textures.h"
#include <algorithm>
#include <chrono>
#include <cstring>
#include <ctime>
#include <random>

namespace tf {

namespace {

template <typename Prepare, typename Work>
double median_host_ms(int repeats, Prepare prepare, Work work)
{
    std::vector<double> ms;
    for (int r = 0; r < repeats; ++r) {
        prepare();
        const auto start = std::chrono::steady_clock::now();
        work();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    return median(ms);
}

// Every level read once and written once, as bench --mip-build counts the host's build.
double mip_bytes(int side)
{
    double bytes = 0;
    for (int w = side; w > 1; w = std::max(1, w >> 1))
        bytes += (double(w) * w + double(w >> 1) * (w >> 1)) * sizeof(glm::vec4);
    return bytes;
}

// Level 0 read twice (range, rows), the low table written (rows), read and written again with the high
// table (columns).
double sat_bytes(int side)
{
    const double entries = double(side + 1) * (side + 1);
    return 2.0 * double(side) * side * sizeof(glm::vec4) + entries * (16 + 16 + 16 + 4);
}

constexpr VkDeviceSize copy_chunk = VkDeviceSize(256) << 20; // the copy's source buffer: beyond any cache

// `bytes` from a device-local buffer into level 0 of `image` (side x side RGBA32F, GENERAL), in chunks of at
// most the level's size from a buffer of at most copy_chunk bytes.
void record_copy(VkCommandBuffer cb, const Buffer& source, VkImage image, int side, double bytes)
{
    image_barrier(cb, {.image = image,
                       .from = {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                                VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT, VK_IMAGE_LAYOUT_GENERAL},
                       .to = scope::transfer_dst});
    const VkDeviceSize row = VkDeviceSize(side) * sizeof(glm::vec4);
    const VkDeviceSize chunk_rows = std::max<VkDeviceSize>(1, std::min<VkDeviceSize>(source.size / row, VkDeviceSize(side)));
    for (VkDeviceSize left = VkDeviceSize(bytes / double(row)); left > 0;) {
        const VkDeviceSize rows = std::min(left, chunk_rows);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        copy.imageExtent = {uint32_t(side), uint32_t(rows), 1};
        vkCmdCopyBufferToImage(cb, source.buffer, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
        left -= rows;
    }
    image_barrier(cb, {.image = image, .from = scope::transfer_dst, .to = scope::compute_read_write});
}

void visible_to_compute(VkCommandBuffer cb)
{
    memory_barrier(cb, {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                        VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT},
                       {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT});
}

GpuBuildRow run_side(const VulkanContext& context, int side, int repeats, FrameTimer timer)
{
    GpuBuildRow row;
    row.side = side;
    row.levels = mip_level_count(side, side);
    row.passes = int(plan_mip_build(side, side).size());
    row.sat = side <= sat_max_dimension;
    row.mip.bytes = mip_bytes(side);
    row.table.bytes = row.sat ? sat_bytes(side) : 0;

    Image level0 = make_image(side, side);
    std::mt19937 rng(14);
    std::uniform_real_distribution<float> value(0.0f, 1.0f);
    for (glm::vec4& t : level0.texels)
        t = glm::vec4(value(rng), value(rng), value(rng), 1.0f);

    // The host: the builders and memcpy of the same bytes (touched memory, as the builders' output is).
    volatile float sink = 0;
    Image copy;
    row.mip.cpu_ms = median_host_ms(repeats, [&] { copy = level0; }, [&] {
        sink = sink + build_mip_chain(std::move(copy)).levels.back().texels[0].r;
    });
    if (row.sat)
        row.table.cpu_ms = median_host_ms(repeats, [] {}, [&] { sink = sink + float(build_sat(level0).low[4]); });
    for (BuildTimes* t : {&row.mip, &row.table}) {
        if (t->bytes <= 0)
            continue;
        const size_t n = size_t(t->bytes / 2);
        std::vector<char> from(n, 1), to(n, 0);
        t->memcpy_ms = median_host_ms(repeats, [] {}, [&] {
            std::memcpy(to.data(), from.data(), n);
            sink = sink + float(to[n / 3]);
        });
    }

    // The device: level 0 up once; then each build and the copies, timed alone.
    Cleanup cleanup;
    GpuImage chain = create_image(context, VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t(side), uint32_t(side),
                                  uint32_t(row.levels), gpu_build_chain_usage, VK_IMAGE_ASPECT_COLOR_BIT);
    cleanup.add([&] { destroy_image(context, chain); });
    const GpuBuildKernels kernels = create_gpu_build_kernels(context, cleanup);
    const MipBuildTarget mip = create_mip_build_target(context, kernels, chain.image, side, side, cleanup);
    SatBuildTarget sat;
    if (row.sat) {
        SatImages images = create_sat_images(context, side, side);
        cleanup.add([&context, images]() mutable { destroy_sat_images(context, images); });
        sat = create_sat_build_target(context, kernels, mip.level_views[0], images, side, side, cleanup);
    }
    {
        Buffer staging = create_host_buffer(context, level0.texels.size() * sizeof(glm::vec4), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        Cleanup staging_cleanup;
        staging_cleanup.add([&] { destroy_buffer(context, staging); });
        std::memcpy(staging.mapped, level0.texels.data(), level0.texels.size() * sizeof(glm::vec4));
        submit_and_wait(context, [&](VkCommandBuffer cb) {
            image_barrier(cb, {.image = chain.image, .from = scope::undefined, .to = scope::transfer_dst,
                               .levels = uint32_t(row.levels)});
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = {uint32_t(side), uint32_t(side), 1};
            vkCmdCopyBufferToImage(cb, staging.buffer, chain.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
            image_barrier(cb, {.image = chain.image, .from = scope::transfer_dst, .to = scope::compute_read_write,
                               .levels = uint32_t(row.levels)});
            if (row.sat)
                record_sat_layouts(cb, sat);
        });
    }
    const int warmup = 1;
    row.mip.gpu_ms = median(time_commands(context, [&](VkCommandBuffer cb) {
        visible_to_compute(cb);
        record_mip_build(cb, kernels, mip);
    }, warmup, repeats, timer));
    if (row.sat)
        row.table.gpu_ms = median(time_commands(context, [&](VkCommandBuffer cb) {
            visible_to_compute(cb);
            record_sat_build(cb, kernels, sat);
        }, warmup, repeats, timer));
    const double largest = std::max(row.mip.bytes, row.table.bytes) / 2;
    Buffer source = create_device_buffer(context, VkDeviceSize(std::min(largest, double(copy_chunk))),
                                         VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    cleanup.add([&] { destroy_buffer(context, source); });
    submit_and_wait(context, [&](VkCommandBuffer cb) { vkCmdFillBuffer(cb, source.buffer, 0, VK_WHOLE_SIZE, 0x3f000000u); });
    for (BuildTimes* t : {&row.mip, &row.table}) {
        if (t->bytes <= 0)
            continue;
        t->device_copy_ms = median(time_commands(context, [&](VkCommandBuffer cb) {
            memory_barrier(cb, {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT},
                               {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT});
            record_copy(cb, source, chain.image, side, t->bytes / 2);
        }, warmup, repeats, timer));
    }
    return row;
}

DynamicRow run_dynamic(const VulkanContext& context, int side, int repeats, FrameTimer timer)
{
    DynamicRow row;
    row.side = side;
    row.width = row.height = 256;
    SamplerOptions options;
    options.filter = Filter::trilinear;
    const SceneParams scene = make_scene(SceneKind::plane, row.width, row.height, side);
    const RenderOptions render = make_render_options(SceneKind::plane, Stage::compute, Gradients::fine);
    DynamicTexture dynamic = create_dynamic_texture(context, side);
    Cleanup cleanup;
    cleanup.add([&] { destroy_dynamic_texture(context, dynamic); });
    std::unique_ptr<GpuRenderer> moving = create_renderer(context, dynamic.build.texture, scene, options, render);
    std::memcpy(moving->uniforms.mapped, &scene, sizeof scene);
    int frame = 0;
    row.frame_ms = median(time_commands(context, [&](VkCommandBuffer cb) {
        record_dynamic_frame(cb, dynamic, frame++);
        record_frame(*moving, cb, VK_NULL_HANDLE, 0);
    }, 2, repeats, timer));
    const MipChain fixed = build_mip_chain(dynamic_texture(side, 0));
    with_texture(context, fixed, false, [&](const GpuTexture& texture) {
        std::unique_ptr<GpuRenderer> still = create_renderer(context, texture, scene, options, render);
        std::memcpy(still->uniforms.mapped, &scene, sizeof scene);
        row.static_ms = median(time_commands(context, [&](VkCommandBuffer cb) { record_frame(*still, cb, VK_NULL_HANDLE, 0); },
                                             2, repeats, timer));
        return 0;
    });
    return row;
}

} // namespace

void check_gpu_build_bench(const std::vector<int>& sides, int dynamic_side, const DeviceLimits& device,
                           uint64_t budget)
{
    for (int side : sides) {
        const std::string what = "bench --gpu-build --sizes " + std::to_string(side);
        const bool sat = side <= sat_max_dimension;
        TextureMemory need = estimate_texture_memory(side, side, sat, TextureLoad::device, false, device.host_memory);
        // run_side: level 0 stays; beside it a chain built from a copy, the table, memcpy's two buffers of half a
        // build's bytes, or a staging copy with the device's images and the copy's source buffer.
        const double bytes = std::max(mip_bytes(side), sat ? sat_bytes(side) : 0.0);
        const uint64_t source = uint64_t(std::min(bytes / 2, double(copy_chunk)));
        need.device += source;
        need.staging = need.decode;
        need.host_peak = need.decode + std::max({need.chain, need.sat, uint64_t(bytes),
                                                 need.staging + (device.host_memory ? need.device : 0)});
        check_device_limits(what, side, side, need, device);
        check_memory_budget(what, side, side, need, budget);
    }
    if (dynamic_side > 0) { // run_dynamic: the device's own chain, and a static copy built on the host and uploaded
        const std::string what = "bench --gpu-build --dynamic-size " + std::to_string(dynamic_side);
        TextureMemory need = estimate_texture_memory(dynamic_side, dynamic_side, false, TextureLoad::device, false,
                                                     device.host_memory);
        need.device *= 2;
        if (device.host_memory)
            need.host_peak += need.chain;
        check_device_limits(what, dynamic_side, dynamic_side, need, device);
        check_memory_budget(what, dynamic_side, dynamic_side, need, budget);
    }
}

GpuBuildBench run_gpu_build_bench(const VulkanContext& context, const std::vector<int>& sides, int repeats,
                                  FrameTimer timer, int dynamic_side)
{
    GpuBuildBench b;
    b.device = context.info.name;
    b.driver = context.info.driver_name + " " + context.info.driver_info;
    b.date = utc_date();
    b.timer = timer;
    b.repeats = repeats;
    for (int side : sides) {
        try {
            b.rows.push_back(run_side(context, side, repeats, timer));
        } catch (const Error& e) { // out of device or host memory for this side: say so, go on
            GpuBuildRow skipped;
            skipped.side = side;
            skipped.skipped = e.what();
            b.rows.push_back(skipped);
        }
    }
    if (dynamic_side > 0)
        b.dynamic = run_dynamic(context, dynamic_side, repeats, timer);
    return b;
}

std::string format_gpu_build_bench(const GpuBuildBench& b)
{
    std::string out = "gpu-build on " + b.device + " (" + b.driver + "), " + b.date + ", " + to_string(b.timer) +
                      " timer, median of " + std::to_string(b.repeats) + " (host: " +
                      std::to_string(hardware_threads()) + " threads)\n";
    char line[512];
    auto times = [&](const char* what, const BuildTimes& t, double goal) {
        const double gb = t.bytes / 1e9;
        std::snprintf(line, sizeof line,
                      "  %-4s %7.3f GB  device: build %9.3f ms %7.2f GB/s, copy %9.3f ms %7.2f GB/s, build/copy %5.2fx "
                      "(goal <= %.0fx %s)\n"
                      "                   host:   build %9.3f ms %7.2f GB/s, memcpy %7.3f ms %7.2f GB/s, build/memcpy %5.2fx\n",
                      what, gb, t.gpu_ms, gb / (t.gpu_ms * 1e-3), t.device_copy_ms, gb / (t.device_copy_ms * 1e-3),
                      t.gpu_ms / t.device_copy_ms, goal, t.gpu_ms <= goal * t.device_copy_ms ? "met" : "missed",
                      t.cpu_ms, gb / (t.cpu_ms * 1e-3), t.memcpy_ms, gb / (t.memcpy_ms * 1e-3), t.cpu_ms / t.memcpy_ms);
        out += line;
    };
    for (const GpuBuildRow& r : b.rows) {
        if (!r.skipped.empty()) {
            out += std::to_string(r.side) + "x" + std::to_string(r.side) + " RGBA32F: skipped: " + r.skipped + "\n";
            continue;
        }
        std::snprintf(line, sizeof line, "%dx%d RGBA32F, %d levels in %d dispatch(es)%s\n", r.side, r.side, r.levels,
                      r.passes, r.sat ? "" : "; no SAT (sides up to 4096)");
        out += line;
        times("MIP", r.mip, 2.0);
        if (r.sat)
            times("SAT", r.table, 4.0);
    }
    if (b.dynamic.side > 0) {
        std::snprintf(line, sizeof line,
                      "dynamic %dx%d: generate + MIP build + plane %dx%d trilinear (compute) in one submission "
                      "%.3f ms a frame; the same frame with a texture built once %.3f ms (rebuild %.3f ms)\n",
                      b.dynamic.side, b.dynamic.side, b.dynamic.width, b.dynamic.height, b.dynamic.frame_ms,
                      b.dynamic.static_ms, b.dynamic.frame_ms - b.dynamic.static_ms);
        out += line;
    }
    out += "(bytes: what one build reads and writes; the copies move half of it, as they read and write it)\n";
    return out;
}

} // namespace tf
