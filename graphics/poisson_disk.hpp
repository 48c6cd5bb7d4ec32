#pragma once
// Blue-noise points in a rectangle: dart throwing with a background grid (Cook 1986; the grid of
// cells r / sqrt(2) wide, each holding at most one point, as in Bridson 2007), thinned by a
// probability per point. Darts fall uniformly; one is kept with the probability the map gives
// at it and when no kept point lies closer than the minimum distance. Kept points never come
// closer than min_distance_m whatever the probabilities, and with probabilities below one the
// kept points thin out in proportion (Argudo 2014, 6.2: trees where the map says trees).
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

namespace fspm::graphics {

struct PoissonDiskOptions {
  double width_m = 1.0;  // x in [0, width_m]
  double depth_m = 1.0;  // y in [0, depth_m]
  double min_distance_m = 0.1;
  std::size_t max_count = 0;  // stop after this many points; 0: as many as the darts find
  // Darts per grid cell before stopping: enough to fill the rectangle nearly to saturation
  // (dart throwing's coverage grows slowly at the end; 30 per cell leaves few holes).
  double darts_per_cell = 30.0;

  // Throws ValueError naming the first field out of range.
  void validate() const;
};

// A uniform number in [0, 1) from the top 53 bits of one draw: the same on every platform, unlike
// std::uniform_real_distribution.
inline double unit_uniform(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

// The points, in the order they were kept. `probability` (optional) gives the chance a dart at
// a point is kept, in [0, 1]. Throws ValueError for a non-positive size or distance, or for a
// rectangle needing more than 2^28 grid cells.
std::vector<Eigen::Vector2d> poisson_disk_points(
    const PoissonDiskOptions& options, std::mt19937_64& rng,
    const std::function<double(const Eigen::Vector2d&)>& probability = {});

}  // namespace fspm::graphics
