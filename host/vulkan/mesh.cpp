#include "vulkan/mesh.h"

namespace tf {

uint32_t mesh_vertex_count(const SceneParams& scene) { return uint32_t(3 * scene.kind_size.w); }

Buffer create_mesh_vertices(const VulkanContext& context, const SceneParams& scene, Cleanup& cleanup)
{
    const uint32_t count = mesh_vertex_count(scene);
    Buffer vertices = create_host_buffer(context, count * sizeof(MeshVertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    cleanup.add([&context, vertices]() mutable { destroy_buffer(context, vertices); });
    MeshVertex* v = static_cast<MeshVertex*>(vertices.mapped);
    for (uint32_t i = 0; i < count; ++i)
        v[i] = {{scene.positions[i].x, scene.positions[i].y, scene.positions[i].z}, {scene.uvs[i].x, scene.uvs[i].y}};
    return vertices;
}

} // namespace tf
