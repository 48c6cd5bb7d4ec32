// Cascaded shadow maps: Zhang et al.'s split distances against their closed forms, and every
// cascade checked by sampling: its slice's points land inside its map, away from the edge, with
// every caster between them and the sun in its depth range; the map moves in whole texels; the
// caster test never drops a sphere that reaches into the map.
#include "graphics/shadow_cascades.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fspm/error.hpp"

namespace fspm::graphics {
namespace {

TEST(CascadeSplits, LogarithmicUniformAndTheirBlend) {
  const double n = 0.5, f = 400.0;
  const auto log = cascade_splits(n, f, 4, 1.0);
  const auto uni = cascade_splits(n, f, 4, 0.0);
  const auto half = cascade_splits(n, f, 4, 0.5);
  ASSERT_EQ(log.size(), 5u);
  EXPECT_DOUBLE_EQ(log.front(), n);
  EXPECT_DOUBLE_EQ(log.back(), f);
  // Logarithmic: a constant ratio (f / n)^(1/4) between neighbours; uniform: a constant step.
  const double ratio = std::pow(f / n, 0.25);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(log[i + 1] / log[i], ratio, 1e-9);
    EXPECT_NEAR(uni[i + 1] - uni[i], (f - n) / 4, 1e-9);
    EXPECT_NEAR(half[i], 0.5 * (log[i] + uni[i]), 1e-9);
  }
  EXPECT_THROW(cascade_splits(0.0, 1.0, 3, 0.5), ValueError);
  EXPECT_THROW(cascade_splits(2.0, 1.0, 3, 0.5), ValueError);
  EXPECT_THROW(cascade_splits(0.1, 1.0, 0, 0.5), ValueError);
  EXPECT_THROW(cascade_splits(0.1, 1.0, 3, 1.5), ValueError);
}

TEST(CascadeSplits, SliceCornersOnTheFrustumsEdges) {
  CascadeCamera cam;
  cam.eye = {1, 2, 3};
  cam.forward = Eigen::Vector3d(1, 1, -0.3).normalized();
  cam.aspect = 1.6;
  const auto corners = frustum_slice_corners(cam, 2.0, 10.0);
  ASSERT_EQ(corners.size(), 8u);
  for (std::size_t k = 0; k < 8; ++k) {
    const Eigen::Vector3d v = corners[k] - cam.eye;
    const double d = k < 4 ? 2.0 : 10.0;
    EXPECT_NEAR(v.dot(cam.forward), d, 1e-9);
    // Vertically at half the field of view from the axis, horizontally aspect times as far.
    const Eigen::Vector3d right = cam.forward.cross(cam.up).normalized();
    const Eigen::Vector3d up = right.cross(cam.forward);
    EXPECT_NEAR(std::abs(v.dot(up)) / d, std::tan(0.5 * cam.vertical_fov_rad), 1e-9);
    EXPECT_NEAR(std::abs(v.dot(right)) / d, cam.aspect * std::tan(0.5 * cam.vertical_fov_rad),
                1e-9);
  }
}

// A camera 30 m above the middle of a 1 km landscape, looking down at 25 degrees.
struct Landscape {
  CascadeCamera camera;
  Eigen::Vector3d sun = Eigen::Vector3d(0.5, -0.4, 1.0).normalized();
  Eigen::AlignedBox3d scene{Eigen::Vector3d(-500, -500, 0), Eigen::Vector3d(500, 500, 60)};
  std::vector<double> splits = cascade_splits(0.3, 300.0, 3, 0.75);
  Landscape() {
    camera.eye = {10, -20, 30};
    camera.forward = Eigen::Vector3d(std::cos(0.44), 0, -std::sin(0.44)).normalized();
    camera.aspect = 1280.0 / 720.0;
  }
};

Eigen::Vector3d clip(const ShadowCascade& c, const Eigen::Vector3d& p) {
  const Eigen::Vector4d q = c.light_view_projection * p.homogeneous();
  return q.head<3>() / q.w();
}

TEST(ShadowCascades, SlicePointsAndTheirCastersInsideTheMap) {
  const Landscape l;
  constexpr int kResolution = 1024;
  const auto cascades = fit_shadow_cascades(l.camera, l.splits, l.sun, l.scene, kResolution);
  ASSERT_EQ(cascades.size(), 3u);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Eigen::Vector3d f = l.camera.forward;
  const Eigen::Vector3d right = f.cross(l.camera.up).normalized(), up = right.cross(f);
  const double t = std::tan(0.5 * l.camera.vertical_fov_rad);
  // The viewer uses a map from kCascadeGuardTexels - 1 texels inside its edge.
  const double inner = 1.0 - 2.0 * (kCascadeGuardTexels - 1) / kResolution;
  for (const ShadowCascade& c : cascades) {
    int inside_scene = 0;
    for (int k = 0; k < 20000; ++k) {
      const double d = c.near_m + (c.far_m - c.near_m) * u(rng);
      const Eigen::Vector3d p = l.camera.eye + d * f + (2 * u(rng) - 1) * d * t * up +
                                (2 * u(rng) - 1) * d * t * l.camera.aspect * right;
      const Eigen::Vector3d q = clip(c, p);
      EXPECT_LE(std::abs(q.x()), inner);
      EXPECT_LE(std::abs(q.y()), inner);
      if (!l.scene.contains(p)) continue;
      ++inside_scene;
      EXPECT_LE(std::abs(q.z()), 1.0 + 1e-9);
      // Casters towards the sun inside the scene: same texel, nearer the sun, depth >= -1.
      for (double s = 1.0; l.scene.contains(p + s * l.sun); s *= 2.0) {
        const Eigen::Vector3d o = clip(c, p + s * l.sun);
        EXPECT_NEAR(o.x(), q.x(), 1e-9);
        EXPECT_NEAR(o.y(), q.y(), 1e-9);
        EXPECT_LT(o.z(), q.z());
        EXPECT_GE(o.z(), -1.0 - 1e-9);
      }
    }
    EXPECT_GT(inside_scene, 100) << "the slice " << c.near_m << ".." << c.far_m;
  }
  // Nearer slices, finer maps: each at least twice as fine as the next here.
  for (std::size_t i = 0; i + 1 < cascades.size(); ++i) {
    EXPECT_LT(2.0 * cascades[i].texel_m, cascades[i + 1].texel_m);
  }
}

TEST(ShadowCascades, MapsMoveInWholeTexelsAndKeepTheirSizeAsTheCameraTurns) {
  Landscape l;
  const auto before = fit_shadow_cascades(l.camera, l.splits, l.sun, l.scene, 1024);
  l.camera.eye += Eigen::Vector3d(0.013, 0.007, 0.0);
  l.camera.forward = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) * l.camera.forward;
  const auto after = fit_shadow_cascades(l.camera, l.splits, l.sun, l.scene, 1024);
  for (std::size_t i = 0; i < before.size(); ++i) {
    EXPECT_NEAR(after[i].texel_m, before[i].texel_m, 1e-9 * before[i].texel_m);
    for (const auto* c : {&before[i], &after[i]}) {
      for (int a = 0; a < 2; ++a) {
        const double texels = c->center_xy[a] / c->texel_m;
        EXPECT_NEAR(texels, std::round(texels), 1e-6);
      }
    }
  }
}

// Brute force: a sphere with any sampled point inside a map's square and not beyond its far
// plane must be kept as a caster.
TEST(ShadowCascades, CasterTestKeepsEverySphereReachingIntoTheMap) {
  const Landscape l;
  const auto cascades = fit_shadow_cascades(l.camera, l.splits, l.sun, l.scene, 1024);
  const Eigen::Matrix3d axes = sun_axes(l.sun);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int kept = 0, dropped = 0;
  for (int k = 0; k < 4000; ++k) {
    const Eigen::Vector3d center(250 * u(rng), 250 * u(rng), 30 + 30 * u(rng));
    const double radius = 8.0 * (1.0 + u(rng));
    for (const ShadowCascade& c : cascades) {
      bool reaches = false;
      for (int s = 0; s < 400 && !reaches; ++s) {
        Eigen::Vector3d d(u(rng), u(rng), u(rng));
        if (d.norm() > 1.0 || d.norm() < 1e-9) continue;
        const Eigen::Vector3d q = clip(c, center + radius * d.normalized());
        reaches = std::abs(q.x()) <= 1.0 && std::abs(q.y()) <= 1.0 && q.z() <= 1.0;
      }
      const bool casts = casts_into(c, axes, center, radius);
      if (reaches) {
        EXPECT_TRUE(casts) << center.transpose() << " r " << radius;
      }
      (casts ? kept : dropped)++;
    }
  }
  EXPECT_GT(dropped, kept);  // the test culls: most spheres are far from the near maps
}

TEST(ShadowCascades, SunAxesAreRightHandedWithTheSunAsZ) {
  for (const Eigen::Vector3d& sun :
       {Eigen::Vector3d(0.5, -0.4, 1.0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1)}) {
    const Eigen::Matrix3d a = sun_axes(sun);
    EXPECT_NEAR((a.transpose() * a - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-12);
    EXPECT_NEAR(a.determinant(), 1.0, 1e-12);
    EXPECT_NEAR((a.col(2) - sun.normalized()).norm(), 0.0, 1e-12);
  }
  const Landscape l;
  EXPECT_THROW(fit_shadow_cascades(l.camera, {1.0}, l.sun, l.scene, 1024), ValueError);
  EXPECT_THROW(fit_shadow_cascades(l.camera, l.splits, l.sun, l.scene, 8), ValueError);
  EXPECT_THROW(fit_shadow_cascades(l.camera, l.splits, l.sun, Eigen::AlignedBox3d(), 1024),
               ValueError);
}

}  // namespace
}  // namespace fspm::graphics
