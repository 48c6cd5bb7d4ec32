#include "environment/scene.hpp"

namespace fspm::environment {

bool Scene::inside_solid(const Eigen::Vector3d& p) const {
  if (ground && ground->solid && p.z() < ground->height_m) return true;
  for (const auto& b : boxes) {
    if (b.solid && b.contains(p)) return true;
  }
  for (const auto& s : spheres) {
    if (s.solid && (p - s.center).squaredNorm() < s.radius_m * s.radius_m) return true;
  }
  return false;
}

bool Scene::segment_blocked(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  if (inside_solid(b)) return true;
  const Eigen::Vector3d d = b - a;
  const double len = d.norm();
  if (len <= 0.0) return false;
  const Eigen::Vector3d u = d / len;
  for (const auto& box : boxes) {
    if (!box.solid) continue;
    const double t = box.ray_entry(a, u);
    if (t >= 0.0 && t <= len) return true;
  }
  for (const auto& s : spheres) {
    if (s.solid && ray_hits_sphere(a, u, s.center, s.radius_m, len)) return true;
  }
  for (const auto& m : meshes) {
    if (m.solid && m.crossings(a, u, len) > 0) return true;
  }
  return false;
}

Scene translated(const Scene& scene, const Eigen::Vector3d& offset_m) {
  Scene out = scene;
  for (Sphere& s : out.spheres) s.center += offset_m;
  for (Box& b : out.boxes) b.center += offset_m;
  for (TriangleMesh& m : out.meshes) {
    for (Eigen::Vector3d& v : m.vertices) v += offset_m;
    m.update_bounds();
  }
  if (out.ground) out.ground->height_m += offset_m.z();
  return out;
}

}  // namespace fspm::environment
