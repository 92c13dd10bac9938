#include "vulkan/frame.h"
#include "harness/config.h"
#include "vulkan/barriers.h"
#include "vulkan/readback.h"

namespace tf {

namespace {

void record_dispatch(const GpuRenderer& r, VkCommandBuffer cb, VkQueryPool timestamps, uint32_t query)
{
    bind_pass(cb, VK_PIPELINE_BIND_POINT_COMPUTE, r.pipeline, r.pass, r.push);
    // The previous frame's writes to the pixel buffer come first (write after write).
    memory_barrier(cb, VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                   VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
    if (timestamps)
        vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timestamps, query);
    vkCmdDispatch(cb, (r.width + HARNESS_RENDER_TILE - 1) / HARNESS_RENDER_TILE, (r.height + HARNESS_RENDER_TILE - 1) / HARNESS_RENDER_TILE, 1);
    if (timestamps)
        vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps, query + 1);
}

void record_draw(const GpuRenderer& r, VkCommandBuffer cb, VkQueryPool timestamps, uint32_t query)
{
    const bool mesh = r.kind == RenderKind::mesh;
    record_targets_for_drawing(cb, r.targets);
    if (timestamps)
        vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timestamps, query);
    // The full-screen triangle covers every pixel; the mesh leaves the background where it has none.
    record_begin_rendering(cb, r.targets, mesh ? &r.background : nullptr);
    bind_pass(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, r.pipeline, r.pass, r.push);
    if (mesh) {
        VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cb, 0, 1, &r.vertices.buffer, &offset);
    }
    vkCmdDraw(cb, r.vertex_count, 1, 0, 0);
    vkCmdEndRendering(cb);
    if (timestamps)
        vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps, query + 1);
    record_targets_for_readback(cb, r.targets);
}

} // namespace

void record_frame(const GpuRenderer& r, VkCommandBuffer cb, VkQueryPool timestamps, uint32_t query)
{
    if (r.kind == RenderKind::compute)
        record_dispatch(r, cb, timestamps, query);
    else
        record_draw(r, cb, timestamps, query);
}

void record_frame_readback(const GpuRenderer& r, VkCommandBuffer cb)
{
    if (r.kind == RenderKind::compute) {
        memory_barrier(cb, VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                       VK_PIPELINE_STAGE_TRANSFER_BIT);
        const VkBufferCopy copy{0, 0, r.pixels.size};
        vkCmdCopyBuffer(cb, r.pixels.buffer, r.pixels_readback.buffer, 1, &copy);
        record_host_read(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    } else
        record_target_readback(cb, r.targets);
}

} // namespace tf
