#include "environment/space_colonization.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "fspm/error.hpp"
#include "tests/scoped_memory_limit.hpp"

namespace fspm::environment {
namespace {

SpaceColonizationParams small_region() {
  SpaceColonizationParams p;
  p.marker_density_per_m3 = 200.0;
  p.region_radius_m = 1.5;
  p.region_height_m = 3.0;
  return p;
}

// Runions et al. 2007 written out over every marker and bud: each marker inside a bud's radius
// and cone goes to the nearest such bud; Q = 1 with markers, V = the normalised sum of the unit
// vectors to them.
std::vector<BudPerception> brute_force(const SpaceColonizationParams& p,
                                       const std::vector<Eigen::Vector3d>& markers,
                                       const std::vector<BudQuery>& buds) {
  std::vector<BudPerception> out(buds.size(), {0.0, Eigen::Vector3d::Zero()});
  const double cos_half = std::cos(0.5 * p.perception_angle_deg * std::numbers::pi / 180.0);
  for (const Eigen::Vector3d& m : markers) {
    int best = -1;
    double best_d = 1e300;
    for (std::size_t b = 0; b < buds.size(); ++b) {
      const Eigen::Vector3d d = m - buds[b].position;
      const double n = d.norm();
      if (n > p.perception_radius_m || d.dot(buds[b].heading) < cos_half * n) continue;
      if (n < best_d) {
        best_d = n;
        best = static_cast<int>(b);
      }
    }
    if (best < 0) continue;
    out[best].light = 1.0;
    out[best].direction += (m - buds[best].position).normalized();
  }
  for (auto& o : out)
    o.direction = o.light > 0 ? o.direction.normalized() : Eigen::Vector3d::UnitZ();
  return out;
}

TEST(SpaceColonization, MarkersFillTheRegionOutsideSolids) {
  Scene scene;
  scene.boxes.push_back(Box::from_min_max({0.2, -2, 0}, {2, 2, 1}));
  std::mt19937_64 rng(3);
  const SpaceColonizationParams p = small_region();
  MarkerField field(p, scene, Eigen::Vector3d::Zero(), rng);
  const auto markers = field.live_marker_positions();
  // Poisson count of the cylinder minus what the box takes (about a seventh of its volume).
  const double cylinder = p.marker_density_per_m3 * std::numbers::pi * 1.5 * 1.5 * 3.0;
  EXPECT_GT(static_cast<double>(markers.size()), 0.6 * cylinder);
  EXPECT_LT(static_cast<double>(markers.size()), 0.95 * cylinder);
  for (const auto& m : markers) {
    EXPECT_FALSE(scene.boxes[0].contains(m));
    EXPECT_LE(std::hypot(m.x(), m.y()), 1.5 + 1e-12);
    EXPECT_GE(m.z(), 0.0);
    EXPECT_LE(m.z(), 3.0);
  }
}

TEST(SpaceColonization, PerceptionEqualsTheBruteForceAssignment) {
  std::mt19937_64 rng(11);
  const SpaceColonizationParams p = small_region();
  MarkerField field(p, Scene{}, Eigen::Vector3d::Zero(), rng);
  // Nodes occupy their surroundings first: exactly the markers within the radius go.
  const std::vector<Eigen::Vector3d> nodes = {{0, 0, 0.5}, {0.3, 0.1, 1.2}};
  std::size_t inside = 0;
  for (const auto& m : field.live_marker_positions()) {
    bool near = false;
    for (const auto& n : nodes) near = near || (m - n).norm() <= p.occupancy_radius_m;
    inside += near;
  }
  const std::size_t before = field.live_markers();
  field.occupy(nodes);
  EXPECT_EQ(field.live_markers(), before - inside);
  const std::vector<BudQuery> buds = {{{0, 0, 0.5}, Eigen::Vector3d::UnitZ()},
                                      {{0.3, 0.1, 1.2}, Eigen::Vector3d(1, 0, 1).normalized()},
                                      {{-0.4, 0, 1.0}, -Eigen::Vector3d::UnitX()}};
  std::vector<BudPerception> got(buds.size());
  field.perceive(buds, got);
  const auto expect = brute_force(p, field.live_marker_positions(), buds);
  for (std::size_t b = 0; b < buds.size(); ++b) {
    EXPECT_EQ(got[b].light, expect[b].light) << b;
    EXPECT_LT((got[b].direction - expect[b].direction).norm(), 1e-9) << b;
  }
  EXPECT_EQ(got[0].light, 1.0);
  EXPECT_GT(got[0].direction.z(), 0.0);  // an upward bud turns to markers above it
}

TEST(SpaceColonization, RejectsBadParameters) {
  std::mt19937_64 rng(1);
  SpaceColonizationParams p = small_region();
  p.perception_angle_deg = 0.0;
  EXPECT_THROW(MarkerField(p, Scene{}, Eigen::Vector3d::Zero(), rng), ValueError);
  p = small_region();
  p.marker_density_per_m3 = 1e9;  // more than 10^7 markers
  EXPECT_THROW(MarkerField(p, Scene{}, Eigen::Vector3d::Zero(), rng), ValueError);
}

// The marker field checks its markers against the memory limit before it draws them: the
// default region (r = 8 m, h = 14 m) at 30 markers per m^3 holds about 84 000 markers (about
// 5 MB at 57 bytes each), refused under a 1 MiB limit; the small region (200 per m^3 in
// r = 1.5 m, h = 3 m: about 4 200 markers, 0.3 MB) is drawn.
TEST(SpaceColonization, MemoryLimitRefusesTooManyMarkers) {
  const test_support::ScopedMemoryLimit limit(std::uint64_t{1} << 20);
  std::mt19937_64 rng(5);
  EXPECT_NO_THROW(MarkerField(small_region(), Scene{}, Eigen::Vector3d::Zero(), rng));
  EXPECT_THROW(MarkerField(SpaceColonizationParams{}, Scene{}, Eigen::Vector3d::Zero(), rng),
               MemoryLimitError);
}

}  // namespace
}  // namespace fspm::environment
