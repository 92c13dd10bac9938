#pragma once
// The mesh scene's vertex buffer: each triangle of SceneParams as three vertices with position and uv,
// the layout mesh.vert.glsl reads.
#include "scene/scene.h"
#include "vulkan/cleanup.h"
#include "vulkan/resources.h"

namespace tf {

struct MeshVertex {
    float position[3];
    float uv[2];
};

uint32_t mesh_vertex_count(const SceneParams& scene);

// A host-visible vertex buffer holding the scene's triangles, destroyed by `cleanup`.
Buffer create_mesh_vertices(const VulkanContext& context, const SceneParams& scene, Cleanup& cleanup);

} // namespace tf
