#include "fspm/vertex_normals.hpp"

#include <Eigen/Geometry>

namespace fspm {

std::vector<Eigen::Vector3f> area_weighted_vertex_normals(
    std::span<const Eigen::Vector3f> positions,
    std::span<const std::array<std::uint32_t, 3>> triangles) {
  std::vector<Eigen::Vector3f> normals(positions.size(), Eigen::Vector3f::Zero());
  for (const auto& t : triangles) {
    const Eigen::Vector3f& a = positions[t[0]];
    const Eigen::Vector3f n = (positions[t[1]] - a).cross(positions[t[2]] - a);
    for (const std::uint32_t v : t) normals[v] += n;  // |n| is twice the area: area weighting
  }
  for (Eigen::Vector3f& n : normals) {
    const float length = n.norm();
    n = length > 0.0f ? Eigen::Vector3f(n / length) : Eigen::Vector3f::UnitZ();
  }
  return normals;
}

}  // namespace fspm
