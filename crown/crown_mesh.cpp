#include "crown/crown_mesh.hpp"

#include <Eigen/Geometry>
#include <utility>

namespace fspm::crown {

double enclosed_volume(const CrownMesh& mesh, std::size_t first, std::size_t last) {
  double six_v = 0.0;
  for (std::size_t t = first; t < last; ++t) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d a = mesh.positions[tri[0]].cast<double>();
    const Eigen::Vector3d b = mesh.positions[tri[1]].cast<double>();
    const Eigen::Vector3d c = mesh.positions[tri[2]].cast<double>();
    six_v += a.dot(b.cross(c));
  }
  return six_v / 6.0;
}

std::vector<Eigen::Vector3f> vertex_normals(const CrownMesh& mesh) {
  std::vector<Eigen::Vector3f> normals(mesh.positions.size(), Eigen::Vector3f::Zero());
  for (const auto& tri : mesh.triangles) {
    const Eigen::Vector3f& a = mesh.positions[tri[0]];
    const Eigen::Vector3f n = (mesh.positions[tri[1]] - a).cross(mesh.positions[tri[2]] - a);
    for (std::uint32_t v : tri) normals[v] += n;  // |n| is twice the area: area weighting
  }
  for (Eigen::Vector3f& n : normals) {
    const float length = n.norm();
    n = length > 0.0f ? Eigen::Vector3f(n / length) : Eigen::Vector3f::UnitZ();
  }
  return normals;
}

void flip_triangles(CrownMesh& mesh, std::size_t first, std::size_t last) {
  for (std::size_t t = first; t < last; ++t) std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
}

}  // namespace fspm::crown
