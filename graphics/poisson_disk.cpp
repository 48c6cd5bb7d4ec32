#include "graphics/poisson_disk.hpp"

#include <algorithm>
#include <cmath>

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"

namespace fspm::graphics {
namespace {

// Cells of side r / sqrt(2): a cell's diagonal is r, so it holds at most one point, and a point
// closer than r to a dart lies within two cells of the dart's cell.
class DartGrid {
 public:
  explicit DartGrid(const PoissonDiskOptions& o)
      : cell_m_(o.min_distance_m / std::sqrt(2.0)), r2_(o.min_distance_m * o.min_distance_m) {
    nx_ = static_cast<long>(std::floor(o.width_m / cell_m_)) + 1;
    ny_ = static_cast<long>(std::floor(o.depth_m / cell_m_)) + 1;
    const double cells = static_cast<double>(nx_) * static_cast<double>(ny_);
    if (cells > static_cast<double>(1L << 28)) {
      throw ValueError("the minimum distance is too small for the area (more than 2^28 cells)");
    }
    check_memory(cells * sizeof(long), "the dart grid of " + std::to_string(nx_) + " x " +
                                           std::to_string(ny_) + " cells");
    cells_.assign(static_cast<std::size_t>(nx_ * ny_), -1);
  }

  std::size_t cell_count() const { return cells_.size(); }

  bool fits(const Eigen::Vector2d& p, const std::vector<Eigen::Vector2d>& points) const {
    const long cx = cell_x(p), cy = cell_y(p);
    for (long y = std::max(0L, cy - 2); y <= std::min(ny_ - 1, cy + 2); ++y) {
      for (long x = std::max(0L, cx - 2); x <= std::min(nx_ - 1, cx + 2); ++x) {
        const long k = cells_[static_cast<std::size_t>(y * nx_ + x)];
        if (k >= 0 && (points[static_cast<std::size_t>(k)] - p).squaredNorm() < r2_) return false;
      }
    }
    return true;
  }

  void add(const Eigen::Vector2d& p, std::size_t index) {
    cells_[static_cast<std::size_t>(cell_y(p) * nx_ + cell_x(p))] = static_cast<long>(index);
  }

 private:
  long cell_x(const Eigen::Vector2d& p) const {
    return std::clamp(static_cast<long>(p.x() / cell_m_), 0L, nx_ - 1);
  }
  long cell_y(const Eigen::Vector2d& p) const {
    return std::clamp(static_cast<long>(p.y() / cell_m_), 0L, ny_ - 1);
  }

  double cell_m_;
  double r2_;
  long nx_ = 0, ny_ = 0;
  std::vector<long> cells_;
};

}  // namespace

void PoissonDiskOptions::validate() const {
  if (!(width_m > 0.0) || !(depth_m > 0.0) || !(min_distance_m > 0.0)) {
    throw ValueError("Poisson-disk sampling: width_m, depth_m and min_distance_m must be positive");
  }
}

std::vector<Eigen::Vector2d> poisson_disk_points(
    const PoissonDiskOptions& options, std::mt19937_64& rng,
    const std::function<double(const Eigen::Vector2d&)>& probability) {
  options.validate();
  DartGrid grid(options);
  std::vector<Eigen::Vector2d> points;
  const double darts = options.darts_per_cell * static_cast<double>(grid.cell_count());
  for (double d = 0; d < darts; ++d) {
    if (options.max_count > 0 && points.size() >= options.max_count) break;
    const Eigen::Vector2d p(unit_uniform(rng) * options.width_m,
                            unit_uniform(rng) * options.depth_m);
    // The thinning draw is taken for every dart, so the sequence does not depend on the map.
    const double u = unit_uniform(rng);
    if (probability && !(u < probability(p))) continue;
    if (!grid.fits(p, points)) continue;
    grid.add(p, points.size());
    points.push_back(p);
  }
  return points;
}

}  // namespace fspm::graphics
