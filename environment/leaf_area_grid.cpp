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
  // The coarse level: each block's mean coefficient (voxels beyond the grid count as empty).
  coarse_.assign(block_full_.size(), 0.0f);
  for (int z = 0; z < n_.z(); ++z) {
    for (int y = 0; y < n_.y(); ++y) {
      for (int x = 0; x < n_.x(); ++x) {
        coarse_[block_index({x, y, z})] +=
            kappa_[(static_cast<std::size_t>(z) * n_.y() + y) * n_.x() + x] /
            static_cast<float>(kBlock * kBlock * kBlock);
      }
    }
  }
}

namespace {

// One level of voxels, read by march().
struct Level {
  Eigen::Vector3d lo;
  Eigen::Vector3i n;
  double h;
  const float* kappa;
  const std::uint8_t* block_full;  // nullptr: no empty-block jumps
  Eigen::Vector3i blocks;
  int block;
};

// Optical depth along p + t d for t in [t_from, t_to] through one level (3D DDA, Amanatides and
// Woo 1987), stopping beyond `enough`.
double march(const Level& g, const Eigen::Vector3d& p, const Eigen::Vector3d& d, double t_from,
             double t_to, double enough) {
  const Eigen::Vector3d hi = g.lo + g.h * g.n.cast<double>();
  double t0 = t_from, t1 = t_to;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0) {
      if (p[k] < g.lo[k] || p[k] > hi[k]) return 0.0;
      continue;
    }
    double a = (g.lo[k] - p[k]) / d[k], b = (hi[k] - p[k]) / d[k];
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
      v[k] = std::clamp(static_cast<int>(std::floor((q[k] - g.lo[k]) / g.h)), 0, g.n[k] - 1);
      if (d[k] > 0.0) {
        step[k] = 1;
        t_max[k] = t + (g.lo[k] + (v[k] + 1) * g.h - q[k]) / d[k];
        t_delta[k] = g.h / d[k];
      } else if (d[k] < 0.0) {
        step[k] = -1;
        t_max[k] = t + (g.lo[k] + v[k] * g.h - q[k]) / d[k];
        t_delta[k] = -g.h / d[k];
      } else {
        step[k] = 0;
        t_max[k] = t_delta[k] = std::numeric_limits<double>::infinity();
      }
    }
  };
  start_at(t0);
  double depth = 0.0, t = t0;
  while (true) {
    if (g.block_full != nullptr &&
        !g.block_full[(static_cast<std::size_t>(v.z() / g.block) * g.blocks.y() + v.y() / g.block) *
                          g.blocks.x() +
                      v.x() / g.block]) {
      // An empty block: jump to where the ray leaves it (always forward).
      double exit = t1;
      for (int k = 0; k < 3; ++k) {
        if (step[k] == 0) continue;
        const int edge = (v[k] / g.block + (step[k] > 0 ? 1 : 0)) * g.block;
        exit = std::min(exit, (g.lo[k] + edge * g.h - p[k]) / d[k]);
      }
      if (exit >= t1) break;
      t = std::max(exit, t + 1e-6 * g.h);
      start_at(t + 1e-9 * g.h);
      continue;
    }
    int axis = 0;
    if (t_max[1] < t_max[axis]) axis = 1;
    if (t_max[2] < t_max[axis]) axis = 2;
    const double t_next = std::min(t_max[axis], t1);
    depth += g.kappa[(static_cast<std::size_t>(v.z()) * g.n.y() + v.y()) * g.n.x() + v.x()] *
             (t_next - t);
    if (t_next >= t1 || depth > enough) break;
    t = t_next;
    v[axis] += step[axis];
    if (v[axis] < 0 || v[axis] >= g.n[axis]) break;
    t_max[axis] += t_delta[axis];
  }
  return depth;
}

}  // namespace

double LeafAreaGrid::optical_depth(const Eigen::Vector3d& p, const Eigen::Vector3d& d,
                                   double enough) const {
  if (kappa_.empty()) return 0.0;
  // Fine voxels near p, their 4^3 means beyond kNear_m (a far leaf's exact place matters less).
  const Level fine{lo_, n_, h_, kappa_.data(), block_full_.data(), blocks_, kBlock};
  const double near = kNear_m;
  double depth = march(fine, p, d, 0.0, near, enough);
  if (depth > enough) return depth;
  const Level coarse{lo_, blocks_, h_ * kBlock, coarse_.data(), nullptr, blocks_, kBlock};
  return depth + march(coarse, p, d, near, std::numeric_limits<double>::infinity(), enough - depth);
}

}  // namespace fspm::environment
