#include "io/scene_obstacles.hpp"

#include "fspm/warning.hpp"
#include "io/obstacle_crop.hpp"
#include "io/obstacle_mesh.hpp"

namespace fspm::io {

std::size_t add_scene_obstacles(graphics::InstancedMesh& scene, environment::Scene obstacles,
                                const std::string& file, bool near_plants) {
  if (near_plants) {
    Eigen::Vector3f lo, hi;
    scene.bounds(lo, hi);
    Eigen::Vector2d region_lo, region_hi;
    obstacle_region(lo.cast<double>(), hi.cast<double>(), region_lo, region_hi);
    obstacles = obstacles_near(obstacles, region_lo, region_hi);
  }
  graphics::TriangleMesh mesh = mesh_obstacles(obstacles);
  const std::size_t triangles = mesh.triangle_count();
  if (triangles == 0) {
    warn(file + ": no walls, boxes, spheres or meshes" + (near_plants ? " near the plants" : "") +
         " to draw");
    return 0;
  }
  graphics::MeshInstance instance;
  instance.mesh = static_cast<std::uint32_t>(scene.meshes.size());
  scene.meshes.push_back(std::move(mesh));
  scene.instances.push_back(instance);
  return triangles;
}

std::size_t obstacle_triangle_count(const graphics::InstancedMesh& scene) {
  std::size_t n = 0;
  for (const graphics::MeshInstance& instance : scene.instances) {
    const graphics::TriangleMesh& mesh = scene.meshes[instance.mesh];
    n += mesh.triangle_count(graphics::Material::kObstacle) +
         mesh.triangle_count(graphics::Material::kTranslucentObstacle);
  }
  return n;
}

}  // namespace fspm::io
