#include "environment/shadow_grid.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <utility>
#include <vector>

#include "environment/site_sky.hpp"
#include "fspm/error.hpp"
#include "tests/scoped_memory_limit.hpp"

namespace fspm::environment {
namespace {

// Palubicki's pyramid written out directly: the shade a source at voxel (si, sj, sk) casts on
// voxel (i, j, k) is strength * b^-q with q = sk - k when max(|i - si|, |j - sj|) <= q <= q_max.
double pyramid_shade(const ShadowGridParams& p, const Eigen::Vector3i& source, double strength,
                     const Eigen::Vector3i& at) {
  const int q = source.z() - at.z();
  if (q < 0 || q > p.depth_voxels) return 0.0;
  if (std::abs(at.x() - source.x()) > q || std::abs(at.y() - source.y()) > q) return 0.0;
  return strength * std::pow(p.shade_b, -q);
}

Eigen::Vector3d center_of(const Eigen::Vector3i& v, double h) {
  return h * (v.cast<double>() + Eigen::Vector3d::Constant(0.5));
}

TEST(ShadowGrid, LoneBudHasFullLightAndCastsThePyramid) {
  ShadowGridParams p;
  ShadowGrid grid(p);
  const double h = p.voxel_size_m;
  const Eigen::Vector3i bud(10, 10, 20);
  grid.reset(center_of(bud, h) - Eigen::Vector3d::Constant(3 * h), center_of(bud, h));
  grid.add_bud(center_of(bud, h));
  grid.propagate();
  EXPECT_DOUBLE_EQ(grid.bud_light(center_of(bud, h)), 1.0);
  EXPECT_DOUBLE_EQ(grid.shade(center_of(bud, h)), p.shade_a);
  // One layer down, the 3 x 3 square gets a / b; two layers down the 5 x 5 square a / b^2.
  EXPECT_DOUBLE_EQ(grid.shade(center_of(bud + Eigen::Vector3i(1, -1, -1), h)), 0.5);
  EXPECT_DOUBLE_EQ(grid.shade(center_of(bud + Eigen::Vector3i(2, 0, -1), h)), 0.0);
  EXPECT_DOUBLE_EQ(grid.shade(center_of(bud + Eigen::Vector3i(-2, 2, -2), h)), 0.25);
  EXPECT_DOUBLE_EQ(grid.shade(center_of(bud + Eigen::Vector3i(0, 0, 1), h)), 0.0);
  // Its optimal direction avoids the shade below: the mean of the 17 unshaded neighbours is up.
  const Eigen::Vector3d v = grid.growth_direction(center_of(bud, h));
  EXPECT_NEAR(v.x(), 0.0, 1e-12);
  EXPECT_NEAR(v.y(), 0.0, 1e-12);
  EXPECT_GT(v.z(), 0.5);
}

TEST(ShadowGrid, BudBelowAnotherHasPalubickisLight) {
  ShadowGridParams p;
  ShadowGrid grid(p);
  const double h = p.voxel_size_m;
  const Eigen::Vector3i top(4, 4, 9), below(4, 4, 8);
  grid.reset(center_of(below, h), center_of(top, h));
  grid.add_bud(center_of(top, h));
  grid.add_bud(center_of(below, h));
  grid.propagate();
  // Q = C - s + a with s = a (its own) + a / b (the bud above), as a share of C.
  EXPECT_DOUBLE_EQ(grid.bud_light(center_of(below, h)), (p.full_light - 0.5) / p.full_light);
  EXPECT_DOUBLE_EQ(grid.bud_light(center_of(top, h)), 1.0);
}

TEST(ShadowGrid, ShadeOfManyBudsEqualsTheDirectSum) {
  ShadowGridParams p;
  p.depth_voxels = 5;
  p.shade_b = 1.7;
  const double h = p.voxel_size_m;
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> coord(0, 12);
  std::vector<Eigen::Vector3i> buds;
  for (int n = 0; n < 60; ++n) buds.emplace_back(coord(rng), coord(rng), coord(rng));
  ShadowGrid grid(p);
  grid.reset(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(13 * h));
  for (const auto& b : buds) grid.add_bud(center_of(b, h));
  grid.propagate();
  for (int k = 0; k < 13; ++k) {
    for (int j = 0; j < 13; ++j) {
      for (int i = 0; i < 13; ++i) {
        double expect = 0.0;
        for (const auto& b : buds) expect += pyramid_shade(p, b, p.shade_a, {i, j, k});
        EXPECT_NEAR(grid.shade(center_of({i, j, k}, h)), expect, 1e-9) << i << " " << j << " " << k;
      }
    }
  }
}

TEST(ShadowGrid, WallShadesOnlyNearbyBudsAndTurnsThemAway) {
  ShadowGridParams p;
  const double h = p.voxel_size_m;
  Scene scene;
  scene.boxes.push_back(Box::wall({2.0, -20}, {2.0, 20}, 0.0, 4.0, 0.2));
  ShadowGrid grid(p);
  grid.reset(Eigen::Vector3d(-4, -1, 0), Eigen::Vector3d(1.9, 1, 3));
  grid.add_obstacles(scene);
  // Buds side by side at one height do not shade each other (shade only falls).
  const Eigen::Vector3d far_bud(2.0 - (p.depth_voxels + 2) * h, -1.0, 1.0), mid_bud(1.2, 0.0, 1.0),
      near_bud(1.75, 1.0, 1.0);
  for (const auto& b : {far_bud, mid_bud, near_bud}) grid.add_bud(b);
  grid.propagate();
  EXPECT_TRUE(grid.obstacle({2.0, 0.0, 1.0}));
  EXPECT_FALSE(grid.obstacle({1.5, 0.0, 1.0}));
  // Light falls towards the wall, and nothing beyond q_max voxels of it is shaded.
  const double far = grid.bud_light(far_bud);
  const double mid = grid.bud_light(mid_bud);
  const double near = grid.bud_light(near_bud);
  EXPECT_DOUBLE_EQ(far, 1.0);
  EXPECT_LT(mid, 1.0);
  EXPECT_LT(near, mid);
  EXPECT_DOUBLE_EQ(grid.bud_light({2.0, 0.0, 1.0}), 0.0);  // inside the wall
  EXPECT_LT(grid.growth_direction({1.5, 0.0, 1.0}).x(), -0.1);
  // Above the wall's top there is no shade from it.
  EXPECT_DOUBLE_EQ(grid.shade({1.75, 0.0, 4.3}), 0.0);
}

TEST(ShadowGrid, OpaqueRoofDarkensWhatLiesBelow) {
  ShadowGridParams p;
  Scene scene;
  scene.boxes.push_back(Box::from_min_max({-1, -1, 2.0}, {1, 1, 2.2}));
  ShadowGrid grid(p);
  grid.reset(Eigen::Vector3d(-0.1, -0.1, 1.5), Eigen::Vector3d(0.1, 0.1, 1.6));
  grid.add_obstacles(scene);
  grid.add_bud({0.01, 0.01, 1.85});
  grid.propagate();
  // The roof fills 3 of the 4 sample heights of the layers [1.95, 2.1) and [2.1, 2.25) m, 1 and
  // 2 voxels above the bud: s = 0.1 C * 3/4 * (9 / 2 + 25 / 4), so Q / C = 1 - 0.075 * 10.75.
  EXPECT_NEAR(grid.bud_light({0.01, 0.01, 1.85}), 1.0 - 0.075 * 10.75, 1e-9);
  EXPECT_TRUE(grid.obstacle({0.0, 0.0, 2.1}));
  EXPECT_THROW(ShadowGrid(ShadowGridParams{0.0}), ValueError);
}

// The grid checks its buffers against the memory limit before it allocates them. With the
// default grid (0.15 m voxels, q_max = 8) a 1 m cube of buds spans (6 + 9 + 9 + 1)^2 x
// (6 + 9 + 1 + 1) = 10 625 voxels, about 0.6 MB with 37 bytes per voxel and half again of room:
// inside 1 MiB. A 10 m cube spans 85^2 x 77 = 556 325 voxels, about 31 MB: refused.
// Every obstacle voxel casts obstacle_shade * C * (1 - translucency) times the share of its 4 x 4 x
// 4 sample points inside the obstacle. The oracle counts the samples with Box::contains for every
// voxel and sums the pyramids directly; the grid takes a per-axis shortcut for boxes whose axes
// lie along the world axes (an axis-aligned box, a wall along y) and samples the others (a wall at
// an angle).
TEST(ShadowGrid, ObstacleShadeIsTheSampledShareOfEachVoxel) {
  ShadowGridParams p;
  p.voxel_size_m = 0.3;
  p.depth_voxels = 4;
  p.obstacle_shade = 0.5;
  const double h = p.voxel_size_m;
  Box block = Box::from_min_max({0.35, 0.4, 0.5}, {1.2, 0.95, 1.37});
  block.translucency = 0.3;
  const std::vector<Box> boxes = {Box::wall({3.0, -2.0}, {3.0, 2.0}, 0.0, 3.0, 0.2), block,
                                  Box::wall({0.0, 0.0}, {2.0, 1.3}, 0.0, 2.0, 0.25)};
  for (const Box& box : boxes) {
    ShadowGrid grid(p);
    grid.reset({-1.0, -3.0, 0.0}, {4.0, 3.0, 3.5});
    Scene scene;
    scene.boxes.push_back(box);
    grid.add_obstacles(scene);
    grid.propagate();
    // Oracle sources, in world voxel indices (voxel w spans [w h, (w + 1) h)).
    std::vector<std::pair<Eigen::Vector3i, double>> sources;
    for (int k = -1; k <= 12; ++k) {
      for (int j = -11; j <= 11; ++j) {
        for (int i = -4; i <= 14; ++i) {
          int hits = 0;
          for (int s = 0; s < 64; ++s) {
            const Eigen::Vector3d f((s % 4 + 0.5) / 4, (s / 4 % 4 + 0.5) / 4, (s / 16 + 0.5) / 4);
            hits += box.contains(h * (Eigen::Vector3d(i, j, k) + f)) ? 1 : 0;
          }
          if (hits > 0) {
            const double strength =
                p.obstacle_shade * p.full_light * (1.0 - box.translucency) * hits / 64.0;
            sources.emplace_back(Eigen::Vector3i(i, j, k), strength);
          }
        }
      }
    }
    ASSERT_GT(sources.size(), 20u);
    int checked = 0;
    for (int k = 0; k <= 11; k += 2) {
      for (int j = -9; j <= 9; j += 2) {
        for (int i = -2; i <= 13; ++i) {
          const Eigen::Vector3i at(i, j, k);
          double expected = 0.0;
          for (const auto& [src, strength] : sources)
            expected += pyramid_shade(p, src, strength, at);
          EXPECT_NEAR(grid.shade(center_of(at, h)), expected, 1e-9) << i << " " << j << " " << k;
          checked += expected > 0.0;
        }
      }
    }
    EXPECT_GT(checked, 50);  // voxels the obstacle shades, among those checked
  }
}

TEST(ShadowGrid, MemoryLimitRefusesAGridTooLargeForIt) {
  const test_support::ScopedMemoryLimit limit(std::uint64_t{1} << 20);
  ShadowGrid grid{ShadowGridParams{}};
  EXPECT_NO_THROW(grid.reset(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()));
  EXPECT_EQ(grid.dimensions(), Eigen::Vector3i(25, 25, 17));
  try {
    grid.reset(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(10.0));
    FAIL() << "no error";
  } catch (const MemoryLimitError& e) {
    EXPECT_NE(std::string(e.what()).find("556325 voxels"), std::string::npos) << e.what();
  }
}

// The leaning pyramid written out directly: a source at voxel s shades voxel v by strength * b^-q
// with q = s.z - v.z in [0, q_max] when s lies in the square of half width q around
// v + q (lean_x, lean_y) rounded to a voxel.
double leaning_shade(const ShadowGridParams& p, const Eigen::Vector2d& lean,
                     const Eigen::Vector3i& source, double strength, const Eigen::Vector3i& at) {
  const int q = source.z() - at.z();
  if (q < 0 || q > p.depth_voxels) return 0.0;
  const long cx = at.x() + std::lround(q * lean.x()), cy = at.y() + std::lround(q * lean.y());
  if (std::abs(source.x() - cx) > q || std::abs(source.y() - cy) > q) return 0.0;
  return strength * std::pow(p.shade_b, -q);
}

TEST(ShadowGrid, LeaningPyramidEqualsTheDirectSum) {
  ShadowGridParams p;
  p.depth_voxels = 6;
  p.shade_b = 1.7;
  const double h = p.voxel_size_m;
  const Eigen::Vector3d toward_light(0.3, -0.8, 1.0);  // lean (0.3, -0.8) per layer
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> coord(0, 12);
  std::vector<Eigen::Vector3i> buds;
  for (int n = 0; n < 60; ++n) buds.emplace_back(coord(rng), coord(rng), coord(rng));
  ShadowGrid grid(p);
  grid.set_light_direction(toward_light);
  grid.reset(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(13 * h));
  for (const auto& b : buds) grid.add_bud(center_of(b, h));
  grid.propagate();
  // The grid reaches the buds that can shade the corner voxels from up the lean.
  EXPECT_TRUE(grid.covers(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(13 * h)));
  for (int k = 0; k < 13; ++k) {
    for (int j = 0; j < 13; ++j) {
      for (int i = 0; i < 13; ++i) {
        double expect = 0.0;
        for (const auto& b : buds) expect += leaning_shade(p, {0.3, -0.8}, b, p.shade_a, {i, j, k});
        EXPECT_NEAR(grid.shade(center_of({i, j, k}, h)), expect, 1e-9) << i << " " << j << " " << k;
      }
    }
  }
  // A lone bud under the lean still sees its own voxel as open, spread or not.
  ShadowGrid lone(p);
  lone.set_light_direction(toward_light);
  const Eigen::Vector3d at(0.37, 0.41, 0.52);
  lone.reset(at, at);
  lone.add_bud_spread(at);
  lone.propagate();
  EXPECT_NEAR(lone.spread_bud_light(at), 1.0, 1e-12);
  EXPECT_THROW(lone.set_light_direction({1.0, 0.0, 0.0}), ValueError);
  // New parameters (a grid taken from a pool) bring back the vertical pyramid.
  lone.set_params(p);
  EXPECT_EQ(lone.light_axis(), Eigen::Vector3d::UnitZ());
}

// Light from the zenith is Palubicki's vertical pyramid, shade for shade.
TEST(ShadowGrid, ZenithLightDirectionChangesNothing) {
  ShadowGridParams p;
  const double h = p.voxel_size_m;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coord(0.0, 2.0);
  std::vector<Eigen::Vector3d> buds;
  for (int n = 0; n < 200; ++n) buds.emplace_back(coord(rng), coord(rng), coord(rng));
  ShadowGrid plain(p), zenith(p);
  zenith.set_light_direction({0.0, 0.0, 2.0});
  for (ShadowGrid* g : {&plain, &zenith}) {
    g->reset(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(2.0));
    for (const auto& b : buds) g->add_bud(b);
    g->propagate();
  }
  EXPECT_EQ(plain.dimensions(), zenith.dimensions());
  for (const auto& b : buds) {
    EXPECT_EQ(plain.bud_light(b), zenith.bud_light(b));
    EXPECT_EQ(plain.growth_direction(b), zenith.growth_direction(b));
    EXPECT_EQ(plain.light_direction(b), zenith.light_direction(b));
  }
  EXPECT_EQ(zenith.light_axis(), Eigen::Vector3d::UnitZ());
  (void)h;
}

// Under the equinox sun of 55 N (the real sky's mean light direction leans about 40 degrees to
// the south, y north), an opaque ball above a point to its south shades it: a point 0.6 m below
// the ball and 0.45 m north of it is darker than the point as far south of it, and the shadow
// falls where the ball's shadow line along the light meets the layer, not straight below. Under
// the default (zenith) light both points get the same shade.
TEST(ShadowGrid, OccluderShadesThePointAwayFromTheSun) {
  SiteSky site;
  site.sky.site = {55.0, 0.0, 0.0, 0.0};
  site.sky.date = {2024, 3, 20};
  const Eigen::Vector3d light = mean_light_direction(site);
  ASSERT_LT(light.y(), -0.3);
  ShadowGridParams p;
  Scene scene;
  const Eigen::Vector3d ball(0.075, 0.075, 3.075);  // a voxel centre
  scene.spheres.push_back({ball, 0.3, 0.0});
  const Eigen::Vector3d north = ball + Eigen::Vector3d(0.0, 0.45, -0.6);
  const Eigen::Vector3d south = ball + Eigen::Vector3d(0.0, -0.45, -0.6);
  // Where the line from the ball away from the light meets the layer 0.6 m down.
  const Eigen::Vector3d shadow = ball - 0.6 / light.z() * light;
  const Eigen::Vector3d below = ball - Eigen::Vector3d(0.0, 0.0, 0.6);
  // A bud's light, alone under the ball (bud_light removes the bud's own shade).
  const auto light_at = [&](bool lean, const Eigen::Vector3d& bud) {
    ShadowGrid grid(p);
    if (lean) grid.set_light_direction(light);
    grid.reset(Eigen::Vector3d(-1, -1, 2), Eigen::Vector3d(1, 1, 2.5));
    grid.add_obstacles(scene);
    grid.add_bud(bud);
    grid.propagate();
    return grid.bud_light(bud);
  };
  const auto lights = [&](bool lean) {
    return std::array<double, 4>{light_at(lean, north), light_at(lean, south),
                                 light_at(lean, shadow), light_at(lean, below)};
  };
  const auto leaning = lights(true), vertical = lights(false);
  std::printf(
      "55 N light (%.3f %.3f %.3f): north %.3f south %.3f shadow %.3f below %.3f; "
      "zenith: north %.3f south %.3f below %.3f\n",
      light.x(), light.y(), light.z(), leaning[0], leaning[1], leaning[2], leaning[3], vertical[0],
      vertical[1], vertical[3]);
  EXPECT_LT(leaning[0], leaning[1] - 0.05);
  EXPECT_GT(leaning[1], vertical[1]);  // the ball is no longer up the light from it
  EXPECT_LT(leaning[2], leaning[3]);
  EXPECT_LT(leaning[2], 1.0);
  EXPECT_DOUBLE_EQ(vertical[0], vertical[1]);
  EXPECT_LT(vertical[0], 1.0);
}

}  // namespace
}  // namespace fspm::environment
