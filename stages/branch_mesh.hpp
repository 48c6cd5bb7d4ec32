#pragma once
// A branch mesh as the contraction of Pirk 5.2.1 needs it: positions and triangles with shared
// vertices. Exported meshes repeat a vertex wherever its normal or texture coordinate changes
// (the seam of a tube, the rim of a cap); welding joins such copies so that the surface is
// connected where it is geometrically closed.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace fspm::stages {

struct BranchMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

// Joins vertices closer than `tolerance_fraction` of the bounding-box diagonal, splits polygons
// into triangle fans and drops triangles that lose a corner to welding. Vertices no triangle uses
// are dropped. Throws ValueError for a face index out of range or when no triangle is left.
BranchMesh weld_branch_mesh(const std::vector<Eigen::Vector3d>& vertices,
                            const std::vector<std::vector<std::uint32_t>>& faces,
                            double tolerance_fraction = 1e-6);

}  // namespace fspm::stages
