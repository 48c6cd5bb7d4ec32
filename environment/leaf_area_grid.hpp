#pragma once
// The crown's extinction coefficient in voxels: every leaf cluster (a turbid medium of extinction
// mu = -ln(gamma) / (2 r), canopy_light.hpp) adds mu times the share of each voxel it fills
// (2 x 2 x 2 samples per voxel), and a ray's optical depth is the sum of the coefficients times
// the lengths of the voxels it crosses (3D DDA, Amanatides and Woo 1987): within 1 m of its start
// through the voxels, beyond it through the means of blocks of 4 x 4 x 4 voxels. The cost of a ray
// is the number of voxels it crosses, whatever the number of clusters, where following every
// cluster's sphere costs each point all the clusters within its shadow reach (the voxel-based
// turbid-medium approach of FSPM light models such as RATP, Sinoquet et al. 2001).
#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "environment/occluders.hpp"

namespace fspm::environment {

class LeafAreaGrid {
 public:
  // Throws ValueError unless voxel_m > 0.
  LeafAreaGrid(std::span<const Sphere> clusters, double voxel_m);

  // Optical depth along p + t d (t > 0, d unit) to the edge of the grid, or the first value
  // beyond `enough` (a transmission of exp(-12) = 6e-6 is dark enough for any light).
  double optical_depth(const Eigen::Vector3d& p, const Eigen::Vector3d& d,
                       double enough = 12.0) const;
  double voxel_m() const { return h_; }

 private:
  Eigen::Vector3d lo_ = Eigen::Vector3d::Zero();
  Eigen::Vector3i n_ = Eigen::Vector3i::Zero();
  double h_ = 1.0;
  std::vector<float> kappa_;  // extinction per metre, x fastest
  // Blocks of kBlock^3 voxels, flagged when any of their voxels holds leaves: a ray jumps over
  // empty blocks.
  static constexpr int kBlock = 4;
  Eigen::Vector3i blocks_ = Eigen::Vector3i::Zero();
  std::vector<std::uint8_t> block_full_;
  // Beyond kNear_m from the point a ray marches through the blocks' mean coefficients.
  static constexpr double kNear_m = 1.0;
  std::vector<float> coarse_;
  std::size_t block_index(const Eigen::Vector3i& v) const {
    return (static_cast<std::size_t>(v.z() / kBlock) * blocks_.y() + v.y() / kBlock) * blocks_.x() +
           v.x() / kBlock;
  }
};

}  // namespace fspm::environment
