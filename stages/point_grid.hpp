#pragma once
// A uniform grid over points for fixed-radius neighbour queries: each point is filed under its
// cell of side `cell`; a query visits the cells within `radius` of a position.
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace fspm::stages {

class PointGrid {
 public:
  PointGrid(const std::vector<Eigen::Vector3d>& points, double cell)
      : points_(points), cell_(cell) {
    cells_.reserve(points.size());
    for (std::uint32_t i = 0; i < points.size(); ++i) cells_[key(cell_of(points[i]))].push_back(i);
  }

  // Calls f(index) for every point within `radius` of p.
  template <class F>
  void for_each_near(const Eigen::Vector3d& p, double radius, F&& f) const {
    const Eigen::Vector3i lo = cell_of(p - Eigen::Vector3d::Constant(radius));
    const Eigen::Vector3i hi = cell_of(p + Eigen::Vector3d::Constant(radius));
    for (int x = lo.x(); x <= hi.x(); ++x) {
      for (int y = lo.y(); y <= hi.y(); ++y) {
        for (int z = lo.z(); z <= hi.z(); ++z) {
          const auto it = cells_.find(key({x, y, z}));
          if (it == cells_.end()) continue;
          for (const std::uint32_t i : it->second) {
            if ((points_[i] - p).squaredNorm() <= radius * radius) f(i);
          }
        }
      }
    }
  }

 private:
  Eigen::Vector3i cell_of(const Eigen::Vector3d& p) const {
    return (p / cell_).array().floor().cast<int>();
  }
  static std::uint64_t key(const Eigen::Vector3i& c) {
    const auto u = [](int v) {
      return static_cast<std::uint64_t>(static_cast<std::uint32_t>(v)) & 0x1FFFFF;
    };
    return u(c.x()) | u(c.y()) << 21 | u(c.z()) << 42;
  }
  const std::vector<Eigen::Vector3d>& points_;
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

}  // namespace fspm::stages
