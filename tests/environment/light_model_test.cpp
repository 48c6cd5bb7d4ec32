#include "environment/light_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "environment/sky.hpp"

namespace fspm::environment {
namespace {

Scene one_sphere(const Eigen::Vector3d& c, double r, double gamma, bool analytic, int dirs) {
  Scene s;
  s.sky.directions = dirs;
  s.sky.analytic = analytic;
  s.sky.significance = 0.0;
  s.spheres.push_back({c, r, gamma, false});
  return s;
}

TEST(HemisphereDirections, CountsAndEqualAreaQuadrature) {
  for (int n : {1, 7, 64, 256, 1000, 4096}) {
    HemisphereDirections d(n);
    ASSERT_EQ(d.size(), n);
    double sum_cos2 = 0.0;
    for (int i = 0; i < n; ++i) {
      EXPECT_GT(d.direction(i).z(), 0.0);
      EXPECT_NEAR(d.direction(i).norm(), 1.0, 1e-12);
      sum_cos2 += d.direction(i).z() * d.direction(i).z();
    }
    // Equal-area cells: the quadrature of cos^2 over the hemisphere approaches 2 pi / 3.
    if (n >= 256) {
      EXPECT_NEAR(sum_cos2 * d.cell_solid_angle(), 2.0 * std::numbers::pi / 3.0, 3.0 / n);
    }
  }
  EXPECT_THROW(HemisphereDirections(0), std::exception);
}

TEST(LightModel, OpenSkyIsExactlyOne) {
  Scene s;
  s.sky.brightest = direction_from_elevation_azimuth(30, 120);
  LightModel m(s);
  const LightSample a = m.evaluate({1, 2, 3});
  EXPECT_EQ(a.light, 1.0);
  // Closed form of the unoccluded mean direction: (pi/2 bx bz, pi/2 by bz, pi/4 (bx^2+by^2) +
  // pi/2 bz^2), normalised; the stratified estimate is close to it.
  const Eigen::Vector3d b = s.sky.brightest;
  const Eigen::Vector3d expect = Eigen::Vector3d(0.5 * b.x() * b.z(), 0.5 * b.y() * b.z(),
                                                 0.25 * (1 - b.z() * b.z()) + 0.5 * b.z() * b.z())
                                     .normalized();
  EXPECT_GT(a.direction.dot(expect), 0.999);
}

// An opaque sphere of radius r straight above the point at distance d, sky brightest at the
// zenith: the cap of half angle alpha (sin alpha = r / d) removes integral of cos^2 over the cap,
// 2 pi (1 - cos^3 alpha) / 3, of the hemisphere's 2 pi / 3, so light = cos^3 alpha.
TEST(LightModel, OpaqueSphereAboveMatchesClosedForm) {
  const double r = 1.0, d = 3.0;
  const double cos_a = std::sqrt(1.0 - (r / d) * (r / d));
  const double expect = std::pow(cos_a, 3);
  LightModel exact(one_sphere({0, 0, d}, r, 0.0, true, 256));
  EXPECT_NEAR(exact.evaluate(Eigen::Vector3d::Zero()).light, expect, 1e-12);
  EXPECT_NEAR(exact.evaluate(Eigen::Vector3d::Zero()).direction.z(), 1.0, 1e-12);
  LightModel sampled(one_sphere({0, 0, d}, r, 0.0, false, 65536));
  EXPECT_NEAR(sampled.evaluate(Eigen::Vector3d::Zero()).light, expect, 5e-3);
}

TEST(LightModel, TranslucentSphereAboveMatchesClosedForm) {
  const double r = 2.0, d = 5.0;
  const double gamma = cluster_translucency(r);  // Pirk eq. 4.4: 0.5^2
  EXPECT_DOUBLE_EQ(gamma, 0.25);
  const double cos_a = std::sqrt(1.0 - (r / d) * (r / d));
  const double expect = 1.0 - (1.0 - gamma) * (1.0 - std::pow(cos_a, 3));
  LightModel exact(one_sphere({0, 0, d}, r, gamma, true, 256));
  EXPECT_NEAR(exact.evaluate(Eigen::Vector3d::Zero()).light, expect, 1e-12);
  LightModel sampled(one_sphere({0, 0, d}, r, gamma, false, 65536));
  EXPECT_NEAR(sampled.evaluate(Eigen::Vector3d::Zero()).light, expect, 5e-3);
}

TEST(LightModel, InsideOpaqueSphereIsDark) {
  LightModel m(one_sphere({0, 0, 0}, 1.0, 0.0, true, 64));
  EXPECT_EQ(m.evaluate({0.1, 0, 0}).light, 0.0);
}

// Off-axis sphere under a tilted sky: the analytic cap integrals against a fine sampling.
TEST(LightModel, AnalyticCapAgreesWithFineSampling) {
  for (const auto& c : {Eigen::Vector3d(2, 1, 4), Eigen::Vector3d(-1, 3, 2.5)}) {
    Scene s = one_sphere(c, 0.8, 0.3, true, 65536);
    s.sky.brightest = direction_from_elevation_azimuth(50, 200);
    LightModel exact(s);
    s.sky.analytic = false;
    LightModel fine(s);
    const LightSample a = exact.evaluate(Eigen::Vector3d::Zero());
    const LightSample b = fine.evaluate(Eigen::Vector3d::Zero());
    EXPECT_LT(a.light, 1.0);
    EXPECT_NEAR(a.light, b.light, 5e-4);
    EXPECT_GT(a.direction.dot(b.direction), 1.0 - 1e-6);
  }
}

Scene random_scene(std::mt19937_64& rng, int spheres, int boxes) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Scene s;
  s.sky.directions = 128;
  s.sky.significance = 0.0;  // no cutoff: must equal brute force exactly
  s.sky.analytic = false;
  s.sky.brightest = direction_from_elevation_azimuth(20 + 70 * u(rng), 360 * u(rng));
  for (int i = 0; i < spheres; ++i) {
    const double r = 0.2 + 0.8 * u(rng);
    s.spheres.push_back({{10 * u(rng), 10 * u(rng), 8 * u(rng)},
                         r,
                         u(rng) < 0.3 ? 0.0 : cluster_translucency(r),
                         false});
  }
  for (int i = 0; i < boxes; ++i) {
    Box b;
    b.center = {10 * u(rng), 10 * u(rng), 4 * u(rng)};
    b.half_extent = {0.2 + u(rng), 0.2 + u(rng), 0.2 + 2 * u(rng)};
    b.rotation = Eigen::AngleAxisd(6.28 * u(rng), Eigen::Vector3d(u(rng), u(rng), 1).normalized())
                     .toRotationMatrix();
    b.translucency = 0.5 * u(rng);
    s.boxes.push_back(b);
  }
  if (boxes > 0) {
    TriangleMesh m;
    m.vertices = {{2, 2, 6}, {6, 2, 7}, {2, 6, 6.5}};
    m.triangles = {{0, 1, 2}};
    m.translucency = 0.4;
    s.meshes.push_back(m);
    s.ground = Ground{1.0, 0.1, true};
  }
  return s;
}

TEST(LightModel, ShadowVolumesMatchBruteForceRayCasting) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 6; ++trial) {
    const Scene s = random_scene(rng, 60, trial % 2 ? 3 : 0);
    LightModel m(s);
    for (int k = 0; k < 200; ++k) {
      const Eigen::Vector3d p(12 * u(rng) - 1, 12 * u(rng) - 1, 9 * u(rng) - 0.5);
      const LightSample a = m.evaluate(p);
      const LightSample b = m.evaluate_brute_force(p);
      ASSERT_NEAR(a.light, b.light, 1e-12) << "trial " << trial << " point " << p.transpose();
      ASSERT_GT(a.direction.dot(b.direction), 1.0 - 1e-12);
    }
  }
}

TEST(LightModel, SignificanceCutoffErrorIsSmall) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Scene s = random_scene(rng, 200, 0);
  for (auto& sp : s.spheres) sp.translucency = cluster_translucency(sp.radius_m);
  LightModel exact(s);
  s.sky.significance = 1e-3;
  LightModel culled(s);
  double worst = 0.0;
  for (int k = 0; k < 300; ++k) {
    const Eigen::Vector3d p(10 * u(rng), 10 * u(rng), 8 * u(rng));
    worst = std::max(worst, std::abs(exact.evaluate(p).light - culled.evaluate(p).light));
  }
  EXPECT_LT(worst, 0.05);
}

TEST(LightModel, IgnoredSphereCastsNoShadow) {
  LightModel m(one_sphere({0, 0, 3}, 1.0, 0.0, true, 64));
  EXPECT_LT(m.evaluate(Eigen::Vector3d::Zero()).light, 1.0);
  EXPECT_EQ(m.evaluate(Eigen::Vector3d::Zero(), 0).light, 1.0);
}

TEST(LightModel, WallShadesOneSideMore) {
  Scene s;
  s.sky.brightest = direction_from_elevation_azimuth(45, 90);  // sun in the east (+x)
  s.boxes.push_back(Box::wall({1, -10}, {1, 10}, 0, 6, 0.2));
  LightModel m(s);
  const double west = m.evaluate({0, 0, 1}).light;  // wall between point and sun
  const double east = m.evaluate({2, 0, 1}).light;
  EXPECT_LT(west, east);
  EXPECT_LT(m.evaluate({0, 0, 1}).direction.x(), m.evaluate({2, 0, 1}).direction.x());
}

TEST(Sky, SunPositions) {
  const Eigen::Vector3d up = direction_from_elevation_azimuth(90, 0);
  EXPECT_NEAR(up.z(), 1.0, 1e-12);
  const Eigen::Vector3d east = direction_from_elevation_azimuth(0, 90);
  EXPECT_NEAR(east.x(), 1.0, 1e-12);
  // Equinox at the equator: sun near the zenith at noon; 50 N at midsummer: elevation about 63.4.
  EXPECT_GT(noon_sun_direction(0, 80).z(), std::sin(88.0 * std::numbers::pi / 180));
  const Eigen::Vector3d s = noon_sun_direction(50, 172);
  EXPECT_NEAR(std::asin(s.z()) * 180 / std::numbers::pi, 63.45, 0.1);
  EXPECT_LT(s.y(), 0.0);  // due south
}

}  // namespace
}  // namespace fspm::environment
