#pragma once
// Joining contracted vertices (Pirk 2013, eq. 5.1-5.2): vertices closer than a threshold
// d(x, y) <= t_dist are joined into one, placed at their average V_new = AVG(v_1, ..., v_n), and
// the new vertex takes over their connectivity. Done once, after the Laplacian contraction: in
// vertex order, each vertex not yet joined gathers every vertex not yet joined within t_dist of
// it (mesh vertices come ring by ring along a tube, so the joined vertices follow the tube).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace fspm::stages {

struct JoinedVertices {
  std::vector<std::uint32_t> node_of;               // for each input vertex, its joined vertex
  std::vector<Eigen::Vector3d> positions;           // eq. 5.2: the average of each joined group
  std::vector<std::vector<std::uint32_t>> members;  // the input vertices of each joined vertex
};

JoinedVertices join_vertices(const Eigen::MatrixX3d& positions, double t_dist);

}  // namespace fspm::stages
