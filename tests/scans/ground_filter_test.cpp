// Ground removal and the trunk's base (scans/ground_filter.hpp) on clouds built with known labels:
// a sloped, noisy ground, a vertical trunk standing on it, and a crown.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>

#include "scans/ground_filter.hpp"

namespace fspm::scans {
namespace {

double ground_z(double x, double y) { return 0.1 * x + 0.05 * y + 2.0; }

struct Labelled {
  PointSet cloud;
  std::vector<int> label;  // 0 ground, 1 trunk, 2 crown
};

// Ground over 8 x 8 m (1 cm noise), a trunk of radius 0.15 m from the ground at (1, -1) up 3 m,
// a crown ball of radius 1.5 m above it.
Labelled tree_on_ground(bool with_ground, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-4.0, 4.0), a(0.0, 2.0 * std::numbers::pi), h(0.0, 3.0);
  std::normal_distribution<double> noise(0.0, 0.01);
  Labelled l;
  const auto add = [&l](const Eigen::Vector3d& p, int label) {
    l.cloud.points.push_back(p), l.label.push_back(label);
  };
  if (with_ground) {
    for (int i = 0; i < 20000; ++i) {
      const double x = u(rng), y = u(rng);
      add({x, y, ground_z(x, y) + noise(rng)}, 0);
    }
  }
  const Eigen::Vector3d base(1.0, -1.0, ground_z(1.0, -1.0));
  for (int i = 0; i < 6000; ++i) {
    const double t = a(rng);
    add(base + Eigen::Vector3d(0.15 * std::cos(t), 0.15 * std::sin(t), h(rng)), 1);
  }
  for (int i = 0; i < 6000; ++i) {
    Eigen::Vector3d d(u(rng), u(rng), u(rng));
    if (d.norm() > 4.0 || d.norm() < 1e-3) continue;
    add(base + Eigen::Vector3d(0, 0, 4.5) + 1.5 * d / 4.0, 2);
  }
  return l;
}

TEST(GroundFilter, RemovesASlopedGroundAndKeepsTheTree) {
  std::mt19937_64 rng(5);
  const Labelled l = tree_on_ground(true, rng);
  const std::vector<std::uint32_t> kept = above_ground(l.cloud);
  std::array<std::size_t, 3> total{}, left{};
  for (int lab : l.label) ++total[static_cast<std::size_t>(lab)];
  for (std::uint32_t i : kept) ++left[static_cast<std::size_t>(l.label[i])];
  // Ground within 15 cm of the plane at 1 cm noise: all of it goes.
  EXPECT_LE(left[0], total[0] / 1000) << left[0];
  // The trunk loses only its lowest 15 cm of 3 m (5 %), the crown nothing.
  EXPECT_GE(left[1], total[1] * 93 / 100) << left[1];
  EXPECT_EQ(left[2], total[2]);
}

TEST(GroundFilter, ACloudWithoutGroundKeepsEveryPoint) {
  std::mt19937_64 rng(6);
  const Labelled l = tree_on_ground(false, rng);
  EXPECT_EQ(above_ground(l.cloud).size(), l.cloud.points.size());
}

// A few stray points lower than the trunk's base, 2 m away (a stone, a shrub): the root is still
// the trunk's base.
TEST(GroundFilter, TrunkBaseIsTheDensestColumnNotTheLowestPoint) {
  std::mt19937_64 rng(7);
  Labelled l = tree_on_ground(false, rng);
  const Eigen::Vector3d base(1.0, -1.0, ground_z(1.0, -1.0));
  for (int i = 0; i < 20; ++i) {
    l.cloud.points.push_back(base + Eigen::Vector3d(2.0 + 0.01 * i, 0.0, -0.3));
  }
  const std::uint32_t root = trunk_base_point(l.cloud);
  EXPECT_LT((l.cloud.points[root] - base).norm(), 0.2) << l.cloud.points[root].transpose();
}

}  // namespace
}  // namespace fspm::scans
