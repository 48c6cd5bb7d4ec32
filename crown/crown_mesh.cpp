#include "crown/crown_mesh.hpp"
#include "fspm/vertex_normals.hpp"

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
  return area_weighted_vertex_normals(mesh.positions, mesh.triangles);
}

void flip_triangles(CrownMesh& mesh, std::size_t first, std::size_t last) {
  for (std::size_t t = first; t < last; ++t) std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
}

}  // namespace fspm::crown
