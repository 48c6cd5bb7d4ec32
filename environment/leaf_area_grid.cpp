#include "environment/leaf_area_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "environment/canopy_light.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {

LeafAreaGrid::LeafAreaGrid(std::span<const Sphere> clusters, double voxel_m) : h_(voxel_m) {
  if (!(voxel_m > 0.0)) {
    throw ValueError("voxel size must be > 0 m, got " + std::to_string(voxel_m));
  }
  if (clusters.empty()) return;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const Sphere& c : clusters) {
    lo = lo.cwiseMin(c.center - Eigen::Vector3d::Constant(c.radius_m));
    hi = hi.cwiseMax(c.center + Eigen::Vector3d::Constant(c.radius_m));
  }
  lo_ = lo;
  n_ = (((hi - lo) / h_).array().ceil().cast<int>()).max(1).matrix();
  kappa_.assign(static_cast<std::size_t>(n_.x()) * n_.y() * n_.z(), 0.0f);
  blocks_ = ((n_.array() + kBlock - 1) / kBlock).matrix();
  block_full_.assign(static_cast<std::size_t>(blocks_.x()) * blocks_.y() * blocks_.z(), 0);
  for (const Sphere& c : clusters) {
    const double mu = cluster_extinction_per_m(c);
    if (mu == 0.0) continue;
    const double r2 = c.radius_m * c.radius_m;
    Eigen::Vector3i a, b;
    for (int k = 0; k < 3; ++k) {
      a[k] = std::max(0, static_cast<int>(std::floor((c.center[k] - c.radius_m - lo_[k]) / h_)));
      b[k] = std::min(n_[k] - 1,
                      static_cast<int>(std::floor((c.center[k] + c.radius_m - lo_[k]) / h_)));
    }
    for (int z = a.z(); z <= b.z(); ++z) {
      for (int y = a.y(); y <= b.y(); ++y) {
        for (int x = a.x(); x <= b.x(); ++x) {
          int inside = 0;
          for (int s = 0; s < 8; ++s) {
            const Eigen::Vector3d q = lo_ + h_ * Eigen::Vector3d(x + 0.25 + 0.5 * (s & 1),
                                                                 y + 0.25 + 0.5 * ((s >> 1) & 1),
                                                                 z + 0.25 + 0.5 * (s >> 2));
            inside += (q - c.center).squaredNorm() < r2;
          }
          if (inside == 0) continue;
          kappa_[(static_cast<std::size_t>(z) * n_.y() + y) * n_.x() + x] +=
              static_cast<float>(std::min(mu, 1e30) * inside / 8.0);
          block_full_[block_index({x, y, z})] = 1;
        }
      }
    }
  }
}

double LeafAreaGrid::optical_depth(const Eigen::Vector3d& p, const Eigen::Vector3d& d,
                                   double enough) const {
  if (kappa_.empty()) return 0.0;
  // Enter the grid's box (slab test).
  const Eigen::Vector3d hi = lo_ + h_ * n_.cast<double>();
  double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0) {
      if (p[k] < lo_[k] || p[k] > hi[k]) return 0.0;
      continue;
    }
    double a = (lo_[k] - p[k]) / d[k], b = (hi[k] - p[k]) / d[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a), t1 = std::min(t1, b);
  }
  if (t0 >= t1) return 0.0;
  Eigen::Vector3i v, step;
  Eigen::Vector3d t_max, t_delta;
  // The DDA state at parameter t (the voxel holding p + t d, the next boundary per axis).
  const auto start_at = [&](double t) {
    const Eigen::Vector3d q = p + t * d;
    for (int k = 0; k < 3; ++k) {
      v[k] = std::clamp(static_cast<int>(std::floor((q[k] - lo_[k]) / h_)), 0, n_[k] - 1);
      if (d[k] > 0.0) {
        step[k] = 1;
        t_max[k] = t + (lo_[k] + (v[k] + 1) * h_ - q[k]) / d[k];
        t_delta[k] = h_ / d[k];
      } else if (d[k] < 0.0) {
        step[k] = -1;
        t_max[k] = t + (lo_[k] + v[k] * h_ - q[k]) / d[k];
        t_delta[k] = -h_ / d[k];
      } else {
        step[k] = 0;
        t_max[k] = t_delta[k] = std::numeric_limits<double>::infinity();
      }
    }
  };
  start_at(t0);
  double depth = 0.0, t = t0;
  while (true) {
    const std::size_t b = block_index(v);
    if (!block_full_[b]) {
      // An empty block: jump to where the ray leaves it.
      double exit = t1;
      for (int k = 0; k < 3; ++k) {
        if (step[k] == 0) continue;
        const int edge = (v[k] / kBlock + (step[k] > 0 ? 1 : 0)) * kBlock;
        exit = std::min(exit, (lo_[k] + edge * h_ - p[k]) / d[k]);
      }
      if (exit >= t1) break;
      t = exit;
      start_at(t + 1e-9 * h_);
      continue;
    }
    int axis = 0;
    if (t_max[1] < t_max[axis]) axis = 1;
    if (t_max[2] < t_max[axis]) axis = 2;
    const double t_next = std::min(t_max[axis], t1);
    depth +=
        kappa_[(static_cast<std::size_t>(v.z()) * n_.y() + v.y()) * n_.x() + v.x()] * (t_next - t);
    if (t_next >= t1 || depth > enough) break;
    t = t_next;
    v[axis] += step[axis];
    if (v[axis] < 0 || v[axis] >= n_[axis]) break;
    t_max[axis] += t_delta[axis];
  }
  return depth;
}

}  // namespace fspm::environment
