#pragma once
// Space colonization (Runions et al. 2007 as used by Palubicki et al. 2009, section 4.1): marker
// points fill the space the crown may take. A bud perceives the markers within its perception
// radius and inside the cone of its perception angle around its heading; each marker belongs to
// the nearest bud that perceives it. A bud with markers has Q = 1 and the optimal growth
// direction V = the normalised sum of the unit vectors to its markers; a bud without has Q = 0.
// Markers within the occupancy radius of the tree's nodes are removed, as are markers inside
// solid obstacles and markers a bud could only reach through one.
#include <Eigen/Core>
#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include "environment/scene.hpp"

namespace fspm::environment {

struct SpaceColonizationParams {
  double marker_density_per_m3 = 30.0;
  double perception_radius_m = 0.9;    // 6 internode lengths (Palubicki: 4-6)
  double perception_angle_deg = 90.0;  // full opening angle of the cone
  double occupancy_radius_m = 0.3;
  // Markers fill a vertical cylinder of this radius and height standing on the tree's base.
  double region_radius_m = 8.0;
  double region_height_m = 14.0;
  // Throws ValueError naming the first parameter out of range.
  void validate() const;
};

struct BudQuery {
  Eigen::Vector3d position;
  Eigen::Vector3d heading;  // unit
};

struct BudPerception {
  double light = 0.0;  // Q: 1 with markers, 0 without
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
};

class MarkerField {
 public:
  // Draws the markers (Poisson count, uniform in the cylinder) from `rng` and removes those inside
  // solid occluders. Throws ValueError for parameters out of range or more than 10^7 markers.
  MarkerField(const SpaceColonizationParams& params, const Scene& scene,
              const Eigen::Vector3d& base, std::mt19937_64& rng);

  // Removes the markers within the occupancy radius of any of `nodes`.
  void occupy(std::span<const Eigen::Vector3d> nodes);
  // Q and V of every bud; `out` has one entry per bud.
  void perceive(std::span<const BudQuery> buds, std::span<BudPerception> out);

  std::size_t live_markers() const { return live_; }
  // The positions of the live markers (for tests and pictures).
  std::vector<Eigen::Vector3d> live_marker_positions() const;

 private:
  std::int64_t cell_key(const Eigen::Vector3d& p) const;
  template <typename Visit>
  void for_markers_near(const Eigen::Vector3d& p, Visit&& visit) const;

  SpaceColonizationParams p_;
  Scene scene_;  // its solids hide markers behind them
  bool solids_ = false;
  double cos_half_angle_ = 0.0;
  std::vector<Eigen::Vector3d> markers_;
  std::vector<std::uint8_t> alive_;
  std::size_t live_ = 0;
  // Markers sorted by cell of edge perception_radius_m (CSR over a hash of the cell).
  double cell_ = 1.0;
  std::vector<std::int64_t> cell_keys_;  // sorted, one per non-empty cell
  std::vector<std::uint32_t> cell_start_, order_;
  std::vector<double> best_distance_;
  std::vector<std::int32_t> owner_;
};

}  // namespace fspm::environment
