#pragma once
// The cluster-based tree representation (Pirk sec. 3.3): the main skeleton with allometric radii
// (eq. 3.1), the leaf clusters as hulls hanging at seed points p_i of the skeleton (eq. 3.2), and
// the species whose parameters produced them. Stored in .clusters files (docs/formats.md).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "fspm/tree_graph.hpp"

namespace fspm::scans {

struct ClusterHull {
  NodeId seed_node = kNoNode;     // node of the skeleton the cluster hangs at (p_i)
  std::uint32_t point_count = 0;  // points of the scan in the cluster
  // Length of the skeleton segments that fell into the cluster (before the split): the branch
  // length the scan showed there, which decoding textures up to. 0 when unknown (version 1 files).
  double branch_length_m = 0.0;
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

struct ClusterModel {
  std::string species = "default";
  double beta = 0.0;
  double gamma = 0.0;
  double f_s = 0.0;
  double root_diameter_m = 0.0;
  TreeGraph skeleton;  // segments start at the parent's end; radii of eq. 3.1
  std::vector<ClusterHull> clusters;
};

}  // namespace fspm::scans
