#pragma once
// Stratified directions over the upper hemisphere: rings of equal-area cells (each cell covers
// 2*pi/N sr), the cell centre taken as its direction. Rings run from the zenith down; the ring
// structure lets a spherical cap be rasterized by visiting only the cells it can cover.
#include <Eigen/Core>
#include <vector>

namespace fspm::environment {

class HemisphereDirections {
 public:
  // Throws ValueError when count < 1.
  explicit HemisphereDirections(int count);

  int size() const { return static_cast<int>(dirs_.size()); }
  const Eigen::Vector3d& direction(int i) const { return dirs_[i]; }
  double cell_solid_angle() const { return cell_sr_; }

  int ring_count() const { return static_cast<int>(ring_first_.size()); }
  int ring_first(int r) const { return ring_first_[r]; }
  int ring_size(int r) const { return ring_size_[r]; }
  double ring_z(int r) const { return ring_z_[r]; }            // cos(polar angle) of the centres
  double ring_offset(int r) const { return ring_offset_[r]; }  // azimuth of cell 0's left edge

  // Direction components as arrays, for vectorized loops over all cells.
  const Eigen::ArrayXd& xs() const { return xs_; }
  const Eigen::ArrayXd& ys() const { return ys_; }
  const Eigen::ArrayXd& zs() const { return zs_; }

  // Calls visit(i) for every cell whose centre d satisfies d . axis >= cos_half_angle (axis unit).
  template <typename Visit>
  void for_each_in_cap(const Eigen::Vector3d& axis, double cos_half_angle, Visit&& visit) const;

 private:
  std::vector<Eigen::Vector3d> dirs_;
  std::vector<int> ring_first_, ring_size_;
  std::vector<double> ring_z_, ring_offset_;
  Eigen::ArrayXd xs_, ys_, zs_;
  double cell_sr_ = 0.0;
};

}  // namespace fspm::environment

#include "environment/hemisphere_impl.hpp"
