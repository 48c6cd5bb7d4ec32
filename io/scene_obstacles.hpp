#pragma once
// The obstacles of a scene added to a picture or mesh file of plants, so a tree grown beside a
// wall is shown with the wall.
#include <string>

#include "environment/scene.hpp"
#include "graphics/instanced_mesh.hpp"

namespace fspm::io {

// Adds the walls, boxes, spheres and meshes of `obstacles` to `scene` as one more mesh (material
// obstacle, or translucent obstacle) placed once; returns its triangle count. `near_plants`: only
// the obstacles near the plants already in `scene`, boxes cut to that region (renders, so a long
// wall does not shrink the tree to a dot); otherwise all of them whole (mesh files). `file` names
// the scene in the warning given when there is nothing to draw.
std::size_t add_scene_obstacles(graphics::InstancedMesh& scene, environment::Scene obstacles,
                                const std::string& file, bool near_plants);

// Triangles of material obstacle or translucent obstacle in the placed scene (each instance
// counted), for the --json reports of render and mesh.
std::size_t obstacle_triangle_count(const graphics::InstancedMesh& scene);

}  // namespace fspm::io
