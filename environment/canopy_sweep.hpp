#pragma once
// Light of leaf clusters as turbid media (canopy_light.hpp), through a coarse voxel grid swept once
// per sky direction: the short-characteristics method of discrete-ordinates radiative transfer
// (Kunasz and Auer 1988). For a direction d the optical depth to the sky of every voxel centre is
// that of the point one voxel upstream (toward the sky along d, in the neighbouring layer across
// the axis d is most aligned with; bilinear in that layer) plus the path between them times the
// voxels' mean extinction (trapezoid rule). One sweep costs the voxels, whatever the number of
// clusters or points; a point's depth is the trilinear interpolation of its voxel centres'.
//
// Used where a whole crown's light is needed again and again (the plastic adaptation, one sweep
// set per age level). Coarser than CanopyLight's spheres or 0.1 m voxels: the voxels smear each
// cluster over its neighbourhood (the clusters' extinction times volume is conserved), and the
// bilinear step diffuses a ray's shadow by up to a voxel per layer.
#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "environment/hemisphere.hpp"
#include "environment/light_model.hpp"
#include "environment/occluders.hpp"

namespace fspm::environment {

inline constexpr double kCanopySweepVoxel_m = 0.5;

class CanopySweep {
 public:
  // The sky of Pirk eq. 4.3 (`directions` stratified directions, I = cos^2 to `brightest`).
  // Throws ValueError unless voxel_m > 0 and directions >= 1.
  CanopySweep(int directions, const Eigen::Vector3d& brightest, double voxel_m);
  // The sky's own weights per direction (sky_weights: cos^2 or a real sky's light).
  CanopySweep(const Sky& sky, double voxel_m);

  // Light at every point relative to the open sky, and its mean direction, through the clusters
  // (extinction mu = -ln(gamma) / (2 r), canopy_light.hpp) and the obstacles' transmission per
  // direction: visibility[k] (one value per direction, in directions() order) at point k, or empty
  // for an open sky (visibility itself may be empty: no obstacles anywhere).
  void evaluate(std::span<const Sphere> clusters, std::span<const Eigen::Vector3d> points,
                std::span<const std::span<const float>> visibility, std::span<LightSample> out);

  // Transmission through the clusters from every point along each of `directions` (unit, z > 0):
  // out[i * points.size() + k] for direction i at point k (the sun's beam at every step of a day).
  void transmissions(std::span<const Sphere> clusters, std::span<const Eigen::Vector3d> points,
                     std::span<const Eigen::Vector3d> directions, std::span<float> out);

  const HemisphereDirections& directions() const { return dirs_; }
  double voxel_m() const { return h_; }

  // Trilinear corner and fractions of a point in the grid of voxel centres.
  struct Cell {
    std::size_t base = 0;
    float fx = 0.0f, fy = 0.0f, fz = 0.0f;
  };

 private:
  // Bins the clusters and locates the points.
  void prepare(std::span<const Sphere> clusters, std::span<const Eigen::Vector3d> points);
  // Transmission at every prepared point along d.
  void transmit(const Eigen::Vector3d& d, std::span<float> out);
  void bin(std::span<const Sphere> clusters, std::span<const Eigen::Vector3d> points);
  void sweep(const Eigen::Vector3d& d);
  std::size_t index(int x, int y, int z) const {
    return (static_cast<std::size_t>(z) * n_.y() + y) * n_.x() + x;
  }

  HemisphereDirections dirs_;
  std::vector<double> weight_;
  double weight_sum_ = 0.0;
  Eigen::Vector3d open_direction_ = Eigen::Vector3d::UnitZ();
  double h_;
  // Grid of voxel centres lo_ + h (i - 1) per axis, with one empty voxel of padding on every side
  // (n_ includes it): rays that leave the crown read zero there.
  Eigen::Vector3d lo_ = Eigen::Vector3d::Zero();
  Eigen::Vector3i n_ = Eigen::Vector3i::Zero();
  std::vector<float> kappa_;  // extinction per metre
  // Per voxel: depth + half the step times its extinction (the trapezoid's upstream term).
  std::vector<float> a_;
  std::vector<Cell> cells_;           // per prepared point
  std::vector<float> kappa_at_;       // the extinction interpolated at each prepared point
  std::vector<std::uint8_t> inside_;  // scratch of bin()
  // Rows along x (index z * n_.y + y) and along y (z * n_.x + x) that hold leaves, and the rows
  // of the current sweep that carry shade.
  std::vector<std::uint8_t> row_leaves_x_, row_leaves_y_, row_lit_;
  std::vector<double> offset2_[3], near2_[3], far2_[3];  // scratch of bin()
};

}  // namespace fspm::environment
