#include "scans/ground_filter.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "fspm/error.hpp"

namespace fspm::scans {
namespace {

using Cell = std::pair<std::int64_t, std::int64_t>;

Cell cell_of(const Eigen::Vector3d& p, double size) {
  return {static_cast<std::int64_t>(std::floor(p.x() / size)),
          static_cast<std::int64_t>(std::floor(p.y() / size))};
}

// z = c0 x + c1 y + c2 through the cell minima within 0.5 m of the current plane, three times,
// from the horizontal plane through the lowest minimum. A plane is fitted only to at least
// `min_cells` cells and kept only below a slope of 1:2: the few cells of a trunk's foot would
// tilt it at random.
Eigen::Vector3d lower_envelope_plane(const std::vector<Eigen::Vector3d>& minima,
                                     std::size_t min_cells) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& m : minima) lowest = std::min(lowest, m.z());
  Eigen::Vector3d plane(0.0, 0.0, lowest);
  for (int round = 0; round < 3; ++round) {
    std::vector<const Eigen::Vector3d*> near;
    for (const Eigen::Vector3d& m : minima) {
      if (std::abs(m.z() - (plane.x() * m.x() + plane.y() * m.y() + plane.z())) < 0.5) {
        near.push_back(&m);
      }
    }
    if (near.size() < std::max<std::size_t>(min_cells, 3)) break;
    Eigen::MatrixXd a(near.size(), 3);
    Eigen::VectorXd b(near.size());
    for (std::size_t i = 0; i < near.size(); ++i) {
      a.row(static_cast<Eigen::Index>(i)) << near[i]->x(), near[i]->y(), 1.0;
      b(static_cast<Eigen::Index>(i)) = near[i]->z();
    }
    const Eigen::Vector3d fit = a.colPivHouseholderQr().solve(b);
    if (fit.head<2>().norm() > 0.5) break;
    plane = fit;
  }
  return plane;
}

}  // namespace

std::vector<std::uint32_t> above_ground(const PointSet& ps, const GroundOptions& o) {
  std::map<Cell, Eigen::Vector3d> lowest;
  for (const Eigen::Vector3d& p : ps.points) {
    const auto [it, fresh] = lowest.try_emplace(cell_of(p, o.cell_m), p);
    if (!fresh && p.z() < it->second.z()) it->second = p;
  }
  std::vector<Eigen::Vector3d> minima;
  for (const auto& [cell, p] : lowest) minima.push_back(p);
  std::vector<std::uint32_t> all(ps.points.size());
  for (std::uint32_t i = 0; i < all.size(); ++i) all[i] = i;
  if (minima.empty()) return all;
  const Eigen::Vector3d plane = lower_envelope_plane(minima, o.min_ground_cells);
  const auto height = [&plane](const Eigen::Vector3d& p) {
    return p.z() - (plane.x() * p.x() + plane.y() * p.y() + plane.z());
  };
  std::size_t band_cells = 0;
  for (const Eigen::Vector3d& m : minima) band_cells += height(m) < o.band_m ? 1 : 0;
  if (band_cells < o.min_ground_cells) return all;
  std::vector<std::uint32_t> kept;
  for (std::uint32_t i = 0; i < ps.points.size(); ++i) {
    if (height(ps.points[i]) >= o.band_m) kept.push_back(i);
  }
  return kept;
}

std::uint32_t trunk_base_point(const PointSet& ps) {
  if (ps.points.empty()) throw ValueError("the point set is empty");
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Eigen::Vector3d& p : ps.points) lo = std::min(lo, p.z()), hi = std::max(hi, p.z());
  const double slab = lo + std::min(1.0, 0.15 * (hi - lo));
  constexpr double kColumn = 0.25;
  std::map<Cell, std::size_t> count;
  for (const Eigen::Vector3d& p : ps.points) {
    if (p.z() <= slab) ++count[cell_of(p, kColumn)];
  }
  Cell best{};
  std::size_t best_count = 0;
  for (const auto& [c, n] : count) {
    std::size_t around = 0;
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = count.find({c.first + dx, c.second + dy});
        if (it != count.end()) around += it->second;
      }
    }
    if (around > best_count) best_count = around, best = c;
  }
  std::uint32_t root = 0;
  double root_z = std::numeric_limits<double>::infinity();
  for (std::uint32_t i = 0; i < ps.points.size(); ++i) {
    const Cell c = cell_of(ps.points[i], kColumn);
    if (std::abs(c.first - best.first) <= 1 && std::abs(c.second - best.second) <= 1 &&
        ps.points[i].z() < root_z) {
      root_z = ps.points[i].z(), root = i;
    }
  }
  return root;
}

}  // namespace fspm::scans
