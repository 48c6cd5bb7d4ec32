// Boxes and walls in the light model against the sky integral evaluated by a fine quadrature
// written in the test (sky_quadrature.hpp), never against LightModel's own output.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "environment/light_model.hpp"
#include "environment/sky.hpp"
#include "sky_quadrature.hpp"

namespace fspm::environment {
namespace {

using testing::ray_meets_box;
using testing::ray_meets_sphere;
using testing::sky_quadrature;
using testing::SkyIntegral;

// Product of the translucencies of the scene's boxes and spheres crossed along d from p.
SkyIntegral oracle(const Scene& s, const Eigen::Vector3d& p, int n_theta = 1000) {
  const Eigen::Vector3d b = s.sky.brightest.normalized();
  return sky_quadrature(b, n_theta, 4 * n_theta, [&](const Eigen::Vector3d& d) {
    double v = 1.0;
    for (const Box& box : s.boxes) {
      if (ray_meets_box(p, d, box.center, box.half_extent, box.rotation)) v *= box.translucency;
    }
    for (const Sphere& sp : s.spheres) {
      if (ray_meets_sphere(p, d, sp.center, sp.radius_m)) v *= sp.translucency;
    }
    return v;
  });
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 /
         std::numbers::pi;
}

// The point at the foot of a 50 m high wall, 1 m from its face: the sampled
// integral converged slowly (0.4976 at 1 024 directions); the polygon closed form is exact at
// every direction count, including the default 256 and the growth model's 64.
TEST(LightBoxes, FiftyMetreWallAtDefaultSettings) {
  Scene s;
  s.boxes.push_back(Box::wall({1.1, -50}, {1.1, 50}, 0, 50, 0.2));
  const Eigen::Vector3d p = Eigen::Vector3d::Zero();
  const SkyIntegral q = oracle(s, p, 2000);
  EXPECT_NEAR(q.light(), 0.5136, 1e-3);  // a fine numerical integral
  for (const int dirs : {256, 64, 1024}) {
    s.sky.directions = dirs;
    const LightSample a = LightModel(s).evaluate(p);
    EXPECT_NEAR(a.light, q.light(), 0.005 * q.light()) << dirs << " directions";
    EXPECT_LT(angle_deg(a.direction, q.moment), 0.2) << dirs << " directions";
  }
}

// An oriented translucent box under a tilted sky, from points beside, below and level with it.
TEST(LightBoxes, OrientedTranslucentBox) {
  Scene s;
  s.sky.brightest = direction_from_elevation_azimuth(40, 220);
  Box box;
  box.center = {1.0, 0.5, 2.5};
  box.half_extent = {1.2, 0.4, 0.8};
  box.rotation = Eigen::AngleAxisd(0.6, Eigen::Vector3d(0.2, -0.4, 1).normalized()).matrix();
  box.translucency = 0.35;
  s.boxes.push_back(box);
  for (const Eigen::Vector3d& p :
       {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(-1.5, 2, 1.8), Eigen::Vector3d(1, 0.5, 0.8)}) {
    const SkyIntegral q = oracle(s, p);
    const LightSample a = LightModel(s).evaluate(p);
    EXPECT_NEAR(a.light, q.light(), 1e-3) << p.transpose();
    EXPECT_LT(angle_deg(a.direction, q.moment), 0.1) << p.transpose();
  }
  // Inside the box every ray crosses it once.
  EXPECT_NEAR(LightModel(s).evaluate(box.center).light, box.translucency, 1e-12);
}

// Sphere clusters beside a wall: disjoint solid angles (closed form) and clusters in front of the
// wall (overlap: the residual of the product of translucencies is sampled).
TEST(LightBoxes, BoxAndSphereClusters) {
  Scene s;
  s.sky.brightest = direction_from_elevation_azimuth(55, 100);
  s.boxes.push_back(Box::wall({2, -6}, {2, 6}, 0, 5, 0.3));
  s.boxes.back().translucency = 0.1;
  const Eigen::Vector3d p(0, 0, 0.5);
  s.spheres.push_back({{-2.0, 0.5, 3.0}, 0.8, cluster_translucency(0.8), false});
  s.spheres.push_back({{0.0, -2.5, 2.0}, 0.5, cluster_translucency(0.5), false});
  const SkyIntegral disjoint = oracle(s, p);
  EXPECT_NEAR(LightModel(s).evaluate(p).light, disjoint.light(), 1e-3);
  EXPECT_LT(angle_deg(LightModel(s).evaluate(p).direction, disjoint.moment), 0.1);

  s.spheres.push_back({{1.2, 0.3, 2.0}, 0.6, cluster_translucency(0.6), false});
  s.spheres.push_back({{1.0, -1.0, 3.5}, 0.9, 0.0, false});
  const SkyIntegral overlapping = oracle(s, p);
  const LightSample a = LightModel(s).evaluate(p);
  EXPECT_NEAR(a.light, overlapping.light(), 0.005 * overlapping.light());
  EXPECT_LT(angle_deg(a.direction, overlapping.moment), 1.0);
}

// Two translucent boxes whose solid angles overlap: light through both is the product of their
// translucencies (the residual is sampled only where they overlap).
TEST(LightBoxes, OverlappingBoxes) {
  Scene s;
  s.sky.brightest = direction_from_elevation_azimuth(60, 30);
  s.boxes.push_back(Box::wall({1.5, -4}, {1.5, 4}, 0, 4, 0.2));
  s.boxes.back().translucency = 0.5;
  s.boxes.push_back(Box::wall({-3, 2.5}, {5, 2.5}, 0, 6, 0.4));
  s.boxes.back().translucency = 0.3;
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(0, 0, 0.2), Eigen::Vector3d(-1, 1, 1)}) {
    const SkyIntegral q = oracle(s, p);
    const LightSample a = LightModel(s).evaluate(p);
    EXPECT_NEAR(a.light, q.light(), 0.005 * q.light()) << p.transpose();
    EXPECT_LT(angle_deg(a.direction, q.moment), 1.0) << p.transpose();
  }
}

// Degenerate input never crashes: a point with NaN coordinates, a flat box, the closed form off.
TEST(LightBoxes, DegenerateInputStaysInRange) {
  Scene s;
  s.boxes.push_back(Box::wall({1, -3}, {1, 3}, 0, 4, 0.0));  // zero thickness
  s.boxes.push_back(Box::wall({-1, -3}, {-1, 3}, 0, 4, 0.2));
  const LightModel m(s);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(nan, 0, 1), Eigen::Vector3d(0, 0, 1)}) {
    const LightSample a = m.evaluate(p);
    EXPECT_GE(a.light, 0.0);
    EXPECT_LE(a.light, 1.0);
    EXPECT_TRUE(a.direction.allFinite());
  }
  const SkyIntegral q = oracle(s, Eigen::Vector3d(0, 0, 1));
  EXPECT_NEAR(m.evaluate(Eigen::Vector3d(0, 0, 1)).light, q.light(), 1e-3);
  s.sky.analytic_boxes = false;  // ray-cast over the directions, as before
  EXPECT_NEAR(LightModel(s).evaluate(Eigen::Vector3d(0, 0, 1)).light, q.light(), 0.05);
}

// The branch-free slab tests over a fixed set of directions hit exactly where the per-ray slab
// test does, and where the test's own slab test does; directions with exactly zero components
// (parallel to a box face) included.
TEST(LightBoxes, BatchedSlabTestsHitWhereSingleRaysDo) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Vector3d> dirs = {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(),
                                       -Eigen::Vector3d::UnitY(),
                                       Eigen::Vector3d(1, 1, 0).normalized()};
  while (dirs.size() < 200) {
    const Eigen::Vector3d d(u(rng), u(rng), u(rng));
    if (d.norm() > 0.1) dirs.push_back(d.normalized());
  }
  const std::vector<Box> boxes = {Box::from_min_max({-1, -2, 0}, {1, 2, 3}),
                                  Box::wall({3.0, -30}, {3.0, 30}, 0.0, 12.0, 0.2),
                                  Box::wall({2.0, -10}, {4.0, 10}, 0.0, 6.0, 0.3)};
  int hits = 0;
  for (const Box& box : boxes) {
    std::vector<Eigen::Vector3d> local(dirs.size());
    for (std::size_t i = 0; i < dirs.size(); ++i) local[i] = box.local_direction(dirs[i]);
    const BoxRayDirections batch(local);
    std::vector<std::uint8_t> hit(dirs.size());
    for (int k = 0; k < 300; ++k) {
      // Origins around the box, some on its faces' planes (zero-width slabs) and inside it.
      Eigen::Vector3d p(6 * u(rng), 6 * u(rng), 3 + 4 * u(rng));
      if (k % 10 == 0) p = box.center + box.rotation * box.half_extent;
      batch.hits(box, box.to_local(p), hit);
      for (std::size_t i = 0; i < dirs.size(); ++i) {
        const bool single = box.ray_entry_local(box.to_local(p), local[i]) >= 0.0;
        ASSERT_EQ(hit[i] != 0, single) << "origin " << p.transpose() << " direction " << i;
        if (k % 10 != 0) {
          EXPECT_EQ(single,
                    testing::ray_meets_box(p, dirs[i], box.center, box.half_extent, box.rotation));
        }
        hits += hit[i];
      }
    }
  }
  EXPECT_GT(hits, 1000);  // the rays do meet the boxes often
}

}  // namespace
}  // namespace fspm::environment
