#include "environment/site_sky.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "environment/growth_model.hpp"
#include "environment/growth_params.hpp"
#include "environment/plastic_adaptation.hpp"
#include "environment/tree_analysis.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {
namespace {

SiteSky equinox_at(double latitude_deg) {
  SiteSky s;
  s.sky.site = {latitude_deg, 0.0, 0.0, 0.0};
  s.sky.date = {2024, 3, 20};
  return s;
}

double tilt_deg(const Eigen::Vector3d& d) { return std::acos(d.z()) * 180.0 / std::numbers::pi; }

// On the equinox the sun's daily path lies in the plane through the east-west axis tilted by the
// latitude from the zenith toward the equator, so the sun's mean direction is tilted by the
// latitude to the south (north in the southern hemisphere); the diffuse sky pulls it toward the
// zenith. Mirrored sites give mirrored directions.
TEST(SiteSky, MeanLightDirectionLeansTowardTheEquator) {
  const Eigen::Vector3d north = mean_light_direction(equinox_at(50.0));
  const Eigen::Vector3d south = mean_light_direction(equinox_at(-50.0));
  const Eigen::Vector3d equator = mean_light_direction(equinox_at(0.0));
  std::printf("equinox mean light: 50 N (%.3f %.3f %.3f) tilt %.1f deg, equator tilt %.1f deg\n",
              north.x(), north.y(), north.z(), tilt_deg(north), tilt_deg(equator));
  EXPECT_LT(north.y(), -0.2);  // toward the south
  EXPECT_NEAR(north.x(), 0.0, 0.03);
  EXPECT_GT(tilt_deg(north), 15.0);
  EXPECT_LT(tilt_deg(north), 50.0);
  EXPECT_NEAR(south.y(), -north.y(), 0.02);
  EXPECT_NEAR(south.z(), north.z(), 0.02);
  EXPECT_LT(tilt_deg(equator), 3.0);
  // Whole days average the same sun: three days around the equinox stay close to the one day.
  SiteSky days = equinox_at(50.0);
  days.sky.date = {2024, 3, 19};
  days.days = 3;
  EXPECT_GT(mean_light_direction(days).dot(north), 0.999);
}

TEST(SiteSky, ParsedFromAGrowthParameterFile) {
  const GrowthParams p = parse_growth_params(
      "preset = \"A\"\nsky = { site = { latitude = 45.5, longitude = 7, elevation = 300 }, "
      "date = \"2024-06-21\", hours = \"6:18\" }\n",
      "tree.toml");
  ASSERT_TRUE(p.site_sky.has_value());
  EXPECT_DOUBLE_EQ(p.site_sky->sky.site.latitude_deg, 45.5);
  EXPECT_EQ(p.site_sky->sky.date.month, 6);
  EXPECT_DOUBLE_EQ(p.site_sky->sky.first_hour, 6.0);
  EXPECT_DOUBLE_EQ(p.site_sky->sky.last_hour, 18.0);
  EXPECT_EQ(p.site_sky->days, 0);
  const GrowthParams d = parse_growth_params(
      "sky = { site = { latitude = -33, longitude = 151 }, date = 2024-01-01, days = 30 }\n",
      "tree.toml");
  ASSERT_TRUE(d.site_sky.has_value());
  EXPECT_EQ(d.site_sky->days, 30);
  const auto message = [](const std::string& text) {
    try {
      parse_growth_params(text, "tree.toml");
    } catch (const ValueError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string both = message(
      "sky = { site = { latitude = 1, longitude = 2 }, date = \"2024-06-21\", hours = \"6:18\", "
      "days = 2 }\n");
  EXPECT_NE(both.find("not both"), std::string::npos) << both;
  EXPECT_NE(both.find("tree.toml"), std::string::npos) << both;
  const std::string typo =
      message("sky = { site = { latitud = 1, longitude = 2 }, date = \"2024-06-21\" }\n");
  EXPECT_NE(typo.find("latitude"), std::string::npos) << typo;
  const std::string no_date = message("sky = { site = { latitude = 1, longitude = 2 } }\n");
  EXPECT_NE(no_date.find("date"), std::string::npos) << no_date;
}

// Internodes' mean y (north positive) of a tree grown with a bud light (the sky's by default)
// under a real sky.
// latitude NaN: the default sky, brightest at the zenith.
double mean_y(double latitude_deg, BudLightModel model = BudLightModel::kSky) {
  GrowthParams p = growth_preset("A", model);
  p.years = 12;
  if (!std::isnan(latitude_deg)) p.site_sky = equinox_at(latitude_deg);
  const GrowthResult g = grow_tree(p);
  double y = 0.0;
  int n = 0;
  for (NodeId i = 0; i < g.tree.size(); ++i) {
    if (g.tree.kind(i) != OrganKind::kInternode) continue;
    y += g.tree.end(i).y();
    ++n;
  }
  return y / n;
}

// A tree grown under the sun of a northern site grows toward the south, one of a southern site
// toward the north, against the same tree under the default sky (brightest at the zenith).
TEST(SiteSky, TreesGrowTowardTheSun) {
  const double north_site = mean_y(55.0), south_site = mean_y(-55.0), zenith = mean_y(std::nan(""));
  std::printf("mean internode y: grown at 55 N %.3f m, at 55 S %.3f m, zenith sky %.3f m\n",
              north_site, south_site, zenith);
  EXPECT_LT(north_site, -0.05);
  EXPECT_GT(south_site, 0.05);
  EXPECT_LT(north_site, zenith - 0.05);
  EXPECT_GT(south_site, zenith + 0.05);
}

// The same with the default bud light, the shadow grid: its pyramids lean along the real sky's
// mean light direction, so the shade of the crown falls to its north at a northern site and the
// tree grows toward the south (toward the north at a southern site).
TEST(SiteSky, ShadowGridTreesGrowTowardTheSun) {
  const BudLightModel grid = BudLightModel::kShadowGrid;
  const double north_site = mean_y(55.0, grid), south_site = mean_y(-55.0, grid),
               zenith = mean_y(std::nan(""), grid);
  std::printf(
      "shadow grid, mean internode y: grown at 55 N %.3f m, at 55 S %.3f m, zenith %.3f m\n",
      north_site, south_site, zenith);
  EXPECT_LT(north_site, zenith - 0.05);
  EXPECT_GT(south_site, zenith + 0.05);
}

// Adapted under a northern site's sun (the scene's brightest point its mean light direction), a
// tree grown under the zenith sky turns its tips to the south.
TEST(SiteSky, AdaptationTurnsTowardTheSun) {
  GrowthParams p = growth_preset("A");
  p.years = 12;
  const GrowthResult g = grow_tree(p);
  const TreeAnalysis a = analyze_tree(g.tree);
  Scene scene;
  scene.sky.brightest = mean_light_direction(equinox_at(55.0));
  const AdaptationResult r = adapt_tree(g.tree, a, scene);
  std::printf("adapted under the sun of 55 N: mean tip shift (%.3f %.3f %.3f) m\n",
              r.mean_tip_shift.x(), r.mean_tip_shift.y(), r.mean_tip_shift.z());
  EXPECT_LT(r.mean_tip_shift.y(), -0.1);
  EXPECT_LT(std::abs(r.mean_tip_shift.x()), std::abs(r.mean_tip_shift.y()));
}

}  // namespace
}  // namespace fspm::environment
