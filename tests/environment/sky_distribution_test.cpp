#include "environment/sky_distribution.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "environment/growth_model.hpp"
#include "environment/growth_params.hpp"
#include "environment/leaf_light.hpp"
#include "environment/leaf_light_model.hpp"
#include "environment/light_model.hpp"
#include "environment/plastic_adaptation.hpp"
#include "environment/tree_analysis.hpp"

namespace fspm::environment {
namespace {

constexpr double kPi = std::numbers::pi;

// Three hours around noon on the equinox at the equator, Greenwich: the sun stays within 30
// degrees of the zenith.
RealSky equatorial_noon() {
  RealSky sky;
  sky.site = {0.0, 0.0, 0.0, 0.0};
  sky.date = {2024, 3, 20};
  sky.first_hour = 10.5;
  sky.last_hour = 13.5;
  return sky;
}

// The share of a CIE overcast sky's horizontal irradiance, L = (1 + 2 cos theta) / 3, left by an
// opaque cap of half angle a at the zenith: 1 - [(1 - cos^2 a) / 2 + 2 (1 - cos^3 a) / 3] / (7/6).
double overcast_left_by_zenith_cap(double a) {
  const double c = std::cos(a);
  return 1.0 - ((1 - c * c) / 2 + 2 * (1 - c * c * c) / 3) / (7.0 / 6.0);
}

// An unobstructed horizontal point receives the given global radiation: direct + diffuse.
TEST(SkyDistribution, OpenPointReceivesTheGlobalRadiation) {
  RealSky sky;
  sky.site = {45.0, 7.0, 300.0, 1.0};
  sky.date = {2024, 6, 21};
  sky.first_hour = 8.0, sky.last_hour = 16.0;
  sky.global_W_m2 = 500.0;
  const SkyDistribution d = sky_distribution(sky);
  const double expected = 500.0 * 0.5 * 4.57 * 8 * 3600 * 1e-6;  // 32.904 mol m-2
  EXPECT_NEAR(d.open_mol_m2(), expected, 1e-9);
  EXPECT_GT(d.open_direct_mol_m2(), 0.3 * expected);
  EXPECT_GT(d.open_diffuse_mol_m2(), 0.1 * expected);
  double cells = 0.0;
  for (double v : d.cell_mol_m2(HemisphereDirections(64))) cells += v;
  EXPECT_NEAR(cells, expected, 1e-9);
  const std::vector<Eigen::Vector3d> points{{0, 0, 0}, {5, 5, 1}};
  for (const DaylightSample& s : daylight_through_voxels({}, Scene{}, d, points, 0.5)) {
    EXPECT_NEAR(s.daily_par_mol_m2, expected, 1e-6);
    EXPECT_NEAR(s.par_umol_m2_s, 500.0 * 0.5 * 4.57, 1e-4);
    EXPECT_NEAR(s.open_fraction, 1.0, 1e-7);
  }
}

// Several clear days: the open PAR is the clear-sky global radiation integrated over the days
// (a one-minute midpoint rule written here), whatever the merging of the sun's positions; the PAR
// of a day is its mean.
TEST(SkyDistribution, SeveralDaysIntegrateTheClearSky) {
  SiteSky site;
  site.sky.site = {52.0, 5.0, 10.0, 1.0};
  site.sky.date = {2024, 5, 30};
  site.days = 3;
  const SkyDistribution d = sky_distribution(site);
  double expected = 0.0;
  for (int day = 0; day < 3; ++day) {
    const CalendarDate date{2024, 5, 30 + day < 32 ? 30 + day : 1};
    const CalendarDate at = 30 + day < 32 ? date : CalendarDate{2024, 6, 1};
    for (int m = 0; m < 24 * 60; ++m) {
      const double hour = (m + 0.5) / 60.0;
      const SolarPosition sun = solar_position(site.sky.site, at, hour);
      if (sun.elevation_deg() <= 0.0) continue;
      const double g =
          clear_sky_global_W_m2(sun.elevation_deg(), day_of_year(at), site.sky.site.elevation_m);
      expected += par_umol_m2_s(g) * 60.0 * 1e-6;
    }
  }
  std::printf("3 clear days at 52 N: %.3f mol m-2 (one-minute integral %.3f), %zu sun bins\n",
              d.open_mol_m2(), expected, d.suns.size());
  EXPECT_NEAR(d.open_mol_m2(), expected, 0.002 * expected);
  EXPECT_LT(d.suns.size(), 3u * 96u);  // positions of the three days share bins
  EXPECT_EQ(d.days, 3);
  const std::vector<Eigen::Vector3d> p{{0, 0, 0}};
  EXPECT_NEAR(daylight_through_voxels({}, Scene{}, d, p, 0.5)[0].daily_par_mol_m2,
              d.open_mol_m2() / 3.0, 1e-6 * expected);
}

// A point under an opaque roof (a sphere at the zenith of half angle 40 degrees) that hides the
// sun all the time gets only the diffuse light the roof leaves: the CIE overcast sky's share in
// closed form. Through the PAR of daylight_through_voxels, and as the relative light of eq. 4.3
// (the growth model's `sky` bud light) and of every leaf light model under the real sky.
TEST(SkyDistribution, UnderAnOpaqueRoofOnlyTheDiffuseLightItLeaves) {
  const RealSky sky = equatorial_noon();
  const auto d = std::make_shared<const SkyDistribution>(sky_distribution(sky));
  for (const Eigen::Vector3d& s : d->suns) ASSERT_GT(s.z(), std::cos(30.0 * kPi / 180.0));
  const double a = 40.0 * kPi / 180.0;
  const Sphere roof{Eigen::Vector3d(0, 0, 2), 2.0 * std::sin(a), 0.0, true};
  const double expected_mol = d->open_diffuse_mol_m2() * overcast_left_by_zenith_cap(a);
  const double expected_share = expected_mol / d->open_mol_m2();

  // The cap's rim is a circle of constant z, which the rings of equal-area cells quantize: at
  // 16 384 (1 024) directions the rings' share of the overcast sky inside 40 degrees is 1.7 %
  // (2 %) above the continuous cap's, whence the tolerances.
  Scene scene;
  scene.sky.directions = 16384;
  scene.spheres.push_back(roof);
  const std::vector<Eigen::Vector3d> p{{0, 0, 0}};
  const DaylightSample par = daylight_through_voxels({}, scene, *d, p, 0.5)[0];
  std::printf("under the roof: %.4f mol m-2 (closed form %.4f), open %.4f, diffuse %.4f\n",
              par.daily_par_mol_m2, expected_mol, d->open_mol_m2(), d->open_diffuse_mol_m2());
  EXPECT_NEAR(par.daily_par_mol_m2, expected_mol, 0.025 * expected_mol);

  scene.sky.directions = 1024;
  apply_sky_distribution(scene.sky, d);
  const LightModel eq43(scene);
  const double light = eq43.evaluate(p[0]).light;
  std::printf("eq. 4.3 under the real sky: %.4f (closed form %.4f)\n", light, expected_share);
  EXPECT_NEAR(light, expected_share, 0.03 * expected_share);

  // The leaf light models (growth's leaves, the adaptation's canopy): one far, thin cluster, the
  // roof as an obstacle per direction.
  const std::vector<Sphere> clusters{{Eigen::Vector3d(0, 0, 0), 0.01, 0.999, false}};
  const HemisphereDirections dirs(scene.sky.directions);
  const std::vector<float> vis = obstacle_visibility(scene, dirs, p[0]);
  const std::vector<std::span<const float>> views{vis};
  for (const LeafLightModelEntry& e : leaf_light_models()) {
    std::vector<LightSample> out(1);
    make_leaf_light_model(e.name, scene.sky)->evaluate(clusters, views, out);
    std::printf("leaf light model %s: %.4f\n", e.name, out[0].light);
    EXPECT_NEAR(out[0].light, expected_share, 0.03 * expected_share) << e.name;
  }
}

// Every sun position lands in the cell of the directions that holds it, so the real sky's weights
// keep the sun where it is: its cell's centre lies within a cell's width of it.
TEST(SkyDistribution, TheSunFallsInItsOwnCell) {
  RealSky sky;
  sky.site = {45.0, 7.0, 300.0, 1.0};
  sky.date = {2024, 6, 21};
  const SkyDistribution d = sky_distribution(sky);
  SkyDistribution direct_only = d;
  std::fill(direct_only.diffuse_mol_m2.begin(), direct_only.diffuse_mol_m2.end(), 0.0);
  const HemisphereDirections dirs(256);
  const double width = std::sqrt(dirs.cell_solid_angle());
  for (std::size_t k = 0; k < d.suns.size(); ++k) {
    if (d.direct_mol_m2[k] <= 0.0) continue;
    SkyDistribution one = direct_only;
    std::fill(one.direct_mol_m2.begin(), one.direct_mol_m2.end(), 0.0);
    one.direct_mol_m2[k] = 1.0;
    const std::vector<double> w = one.cell_mol_m2(dirs);
    int cell = -1;
    for (int i = 0; i < dirs.size(); ++i) {
      if (w[static_cast<std::size_t>(i)] > 0.0) cell = i;
    }
    ASSERT_GE(cell, 0);
    EXPECT_LT(std::acos(std::min(1.0, dirs.direction(cell).dot(d.suns[k]))), width);
  }
}

// Grown under a real sky, every leaf cluster carries its PAR (absolute, at most the open sky's),
// and the share of the open PAR goes with the relative light; without a real sky none.
TEST(SkyDistribution, GrownLeavesCarryTheirPar) {
  GrowthParams p = growth_preset("A");
  p.years = 10;
  const GrowthResult plain = grow_tree(p);
  EXPECT_FALSE(plain.tree.has_attribute(kParAttribute));
  SiteSky site;
  site.sky.site = {50.0, 8.0, 200.0, 1.0};
  site.sky.date = {2024, 6, 1};
  p.site_sky = site;
  const GrowthResult g = grow_tree(p);
  ASSERT_TRUE(g.tree.has_attribute(kParAttribute));
  ASSERT_TRUE(g.tree.has_attribute(kDailyParAttribute));
  const double open = sky_distribution(site).open_mol_m2();
  const auto daily = g.tree.attribute(kDailyParAttribute);
  const auto flux = g.tree.attribute(kParAttribute);
  const auto light = g.tree.attribute("light");
  double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
  int n = 0;
  for (NodeId i = 0; i < g.tree.size(); ++i) {
    if (g.tree.kind(i) != OrganKind::kLeaf) {
      EXPECT_TRUE(std::isnan(daily[i]));
      continue;
    }
    ASSERT_TRUE(std::isfinite(daily[i]));
    EXPECT_GE(daily[i], 0.0);
    EXPECT_LE(daily[i], open * (1 + 1e-9));
    EXPECT_NEAR(flux[i], daily[i] * 1e6 / 86400.0, 1e-9 * flux[i] + 1e-12);
    const double x = light[i], y = daily[i] / open;
    sx += x, sy += y, sxx += x * x, syy += y * y, sxy += x * y, ++n;
  }
  const double r = (n * sxy - sx * sy) / std::sqrt((n * sxx - sx * sx) * (n * syy - sy * sy));
  std::printf(
      "%d clusters: mean share of the open PAR %.3f (open %.1f mol m-2), mean light %.3f, "
      "r %.2f\n",
      n, sy / n, open, sx / n, r);
  EXPECT_GT(n, 10);
  EXPECT_GT(sy / n, 0.1);
  EXPECT_LT(sy / n, 0.95);
  EXPECT_GT(r, 0.7);
}

}  // namespace
}  // namespace fspm::environment

namespace fspm::environment {
namespace {

// The adaptation's light models under the equinox sky of 55 N as a light per direction: each turns
// the 12-year tree's tips to the south, and its `sky` cluster light differs from that of the cos^2
// sky around the same mean direction.
TEST(SkyDistribution, AdaptationTakesTheRealSky) {
  GrowthParams p = growth_preset("A");
  p.years = 12;
  const GrowthResult g = grow_tree(p);
  SiteSky site;
  site.sky.site = {55.0, 0.0, 0.0, 0.0};
  site.sky.date = {2024, 3, 20};
  const auto d = std::make_shared<const SkyDistribution>(sky_distribution(site));
  for (const ClusterLightModel model : {ClusterLightModel::kCanopy, ClusterLightModel::kSky}) {
    AnalysisParams ap;
    ap.light_model = model;
    const TreeAnalysis a = analyze_tree(g.tree, ap);
    Scene mean_only;
    mean_only.sky.brightest = d->mean_direction();
    Scene real = mean_only;
    real.sky.distribution = d;
    const AdaptationResult r = adapt_tree(g.tree, a, real);
    const AdaptationResult m = adapt_tree(g.tree, a, mean_only);
    std::printf("adapted under 55 N (model %d): tip shift y %.3f m (mean direction only %.3f m)\n",
                static_cast<int>(model), r.mean_tip_shift.y(), m.mean_tip_shift.y());
    EXPECT_LT(r.mean_tip_shift.y(), -0.1);
    EXPECT_GT(std::abs(r.mean_tip_shift.y() - m.mean_tip_shift.y()), 1e-6);
  }
}

}  // namespace
}  // namespace fspm::environment
