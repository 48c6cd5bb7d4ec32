// View-frustum culling of instances by bounding spheres.
#include "graphics/frustum_culling.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

#include "fspm/error.hpp"

namespace fspm::graphics {

Frustum frustum_from_matrix(const Eigen::Matrix4d& m) {
  if (!m.allFinite()) throw ValueError("the view-projection matrix has non-finite entries");
  // Row 3 plus or minus rows 0, 1, 2: left, right, bottom, top, near, far.
  Frustum f;
  for (int axis = 0; axis < 3; ++axis) {
    f.planes[2 * axis] = (m.row(3) + m.row(axis)).transpose();
    f.planes[2 * axis + 1] = (m.row(3) - m.row(axis)).transpose();
  }
  for (auto& p : f.planes) {
    const double n = p.head<3>().norm();
    if (!(n > 0.0)) throw ValueError("the view-projection matrix gives a degenerate frustum");
    p /= n;
  }
  return f;
}

bool sphere_outside(const Frustum& f, const Eigen::Vector3d& c, double r) {
  return std::any_of(f.planes.begin(), f.planes.end(),
                     [&](const Eigen::Vector4d& p) { return p.head<3>().dot(c) + p.w() < -r; });
}

BoundingSphere bounding_sphere(const TriangleMesh& mesh) {
  BoundingSphere s;
  if (mesh.positions.empty()) return s;
  s.center = (0.5f * (mesh.bbox_min() + mesh.bbox_max())).cast<double>();
  for (const auto& p : mesh.positions) {
    s.radius = std::max(s.radius, (p.cast<double>() - s.center).norm());
  }
  return s;
}

std::vector<std::size_t> visible_instances(const InstancedMesh& scene,
                                           const Eigen::Matrix4d& view_projection) {
  const Frustum f = frustum_from_matrix(view_projection);
  std::vector<BoundingSphere> spheres;
  for (const auto& m : scene.meshes) spheres.push_back(bounding_sphere(m));
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const MeshInstance& inst = scene.instances[i];
    const BoundingSphere& s = spheres[inst.mesh];
    if (scene.meshes[inst.mesh].positions.empty()) continue;
    const Eigen::Matrix3d linear = inst.linear.cast<double>();
    // The largest stretch of the linear part (its largest singular value) bounds the radius.
    const double scale = linear.jacobiSvd().singularValues()(0);
    const Eigen::Vector3d c = linear * s.center + inst.translation.cast<double>();
    if (!sphere_outside(f, c, s.radius * scale)) out.push_back(i);
  }
  return out;
}

}  // namespace fspm::graphics
