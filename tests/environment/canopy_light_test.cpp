#include "environment/canopy_light.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "environment/growth_model.hpp"
#include "fspm/attribute_names.hpp"

namespace fspm::environment {
namespace {

Scene zenith_sky(int directions) {
  Scene s;
  s.sky.directions = directions;
  s.sky.significance = 0.0;
  return s;
}

// At the centre of a cluster every path out of it is one radius long: the light is
// exp(-mu r) = sqrt(gamma) from every direction, whatever the sky.
TEST(CanopyLight, CentreOfAClusterSeesTheSquareRootOfItsTranslucency) {
  const std::vector<Sphere> clusters{{Eigen::Vector3d(1, 2, 3), 0.4, 0.3, false}};
  const CanopyLight model(zenith_sky(256), clusters);
  EXPECT_NEAR(model.evaluate(clusters[0].center).light, std::sqrt(0.3), 1e-12);
  EXPECT_DOUBLE_EQ(model.evaluate(clusters[0].center, 0).light, 1.0);  // its own left out
}

// Beer-Lambert along the chord of a cluster straight above the point, integrated over the cap in
// one dimension by Simpson's rule (an oracle independent of the stratified directions):
// i = 1 - 3 * integral_0^alpha cos^2(t) (1 - exp(-2 mu sqrt(r^2 - D^2 sin^2 t))) sin t dt.
double light_below_cluster(double r, double dist, double gamma) {
  const double mu = -std::log(gamma) / (2 * r);
  const double alpha = std::asin(r / dist);
  const int n = 20000;
  const double h = alpha / n;
  double sum = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double t = k * h;
    const double q = std::max(0.0, r * r - dist * dist * std::sin(t) * std::sin(t));
    const double f =
        std::cos(t) * std::cos(t) * (1 - std::exp(-2 * mu * std::sqrt(q))) * std::sin(t);
    sum += f * (k == 0 || k == n ? 1 : (k % 2 == 1 ? 4 : 2));
  }
  return 1.0 - 3.0 * sum * h / 3.0;
}

TEST(CanopyLight, ClusterAboveMatchesTheOneDimensionalIntegral) {
  for (const double gamma : {0.8, 0.3, 0.01}) {
    const std::vector<Sphere> clusters{{Eigen::Vector3d(0, 0, 1.5), 0.6, gamma, false}};
    const CanopyLight model(zenith_sky(16384), clusters);
    const double expected = light_below_cluster(0.6, 1.5, gamma);
    EXPECT_NEAR(model.evaluate(Eigen::Vector3d::Zero()).light, expected, 2e-3) << gamma;
    EXPECT_LT(expected, 0.97);  // the cluster matters
  }
}

TEST(CanopyLight, LeafAreaOfAClusterAndAboveAPoint) {
  const Sphere c{Eigen::Vector3d(0, 0, 2), 0.5, 0.25, false};
  const double mu = -std::log(0.25) / 1.0;
  EXPECT_NEAR(cluster_extinction_per_m(c), mu, 1e-12);
  EXPECT_NEAR(cluster_leaf_area_m2(c), mu / 0.5 * 4.0 / 3.0 * std::numbers::pi * 0.125, 1e-12);
  const std::vector<Sphere> clusters{c};
  const CanopyLight model(zenith_sky(64), clusters);
  // Below: the whole vertical chord; at the centre: half of it; 0.3 m off axis: a shorter chord.
  EXPECT_NEAR(model.leaf_area_index_above({0, 0, 0}), mu / 0.5 * 1.0, 1e-12);
  EXPECT_NEAR(model.leaf_area_index_above({0, 0, 2}), mu / 0.5 * 0.5, 1e-12);
  EXPECT_NEAR(model.leaf_area_index_above({0.3, 0, 0}), mu / 0.5 * 2 * 0.4, 1e-12);
  EXPECT_EQ(model.leaf_area_index_above({0, 0, 2.6}), 0.0);
}

// Obstacles shade as in eq. 4.3: an opaque sphere straight above under a zenith cos^2 sky leaves
// cos^3(alpha) (sin alpha = r / D); an opaque roof over the whole sky leaves nothing.
TEST(CanopyLight, ObstaclesShadeAsInEquation43) {
  Scene s = zenith_sky(16384);
  s.spheres.push_back({Eigen::Vector3d(0, 0, 2), 1.0, 0.0, true});
  const CanopyLight model(s, {});
  // The rings of stratified directions quantize an axial cap's edge: 1 % at 16 384 directions.
  EXPECT_NEAR(model.evaluate(Eigen::Vector3d::Zero()).light, std::pow(std::sqrt(0.75), 3), 1e-2);
  s.sky.directions = 256;
  const Eigen::Vector3d p(0.3, -0.2, 0.1);
  EXPECT_NEAR(CanopyLight(s, {}).evaluate(p).light, LightModel(s).evaluate_brute_force(p).light,
              1e-12);
  s.spheres.clear();
  s.boxes.push_back(Box::from_min_max({-1000, -1000, 1}, {1000, 1000, 1.1}));
  EXPECT_EQ(CanopyLight(s, {}).evaluate(Eigen::Vector3d::Zero()).light, 0.0);
}

// Voxels of 0.1 m against the spheres themselves on a 20-year crown: the same light per cluster
// within a few hundredths, and exact for a point above everything.
TEST(CanopyLight, VoxelsAgreeWithTheSpheres) {
  GrowthParams params = growth_preset("A");
  params.years = 20;
  const GrowthResult g = grow_tree(params);
  Scene sky;
  sky.sky.directions = 64;
  const auto exact = CanopyLight(sky, g.cluster_spheres).evaluate_clusters();
  const auto voxels = CanopyLight(sky, g.cluster_spheres, 0.1).evaluate_clusters();
  double mae = 0.0, worst = 0.0;
  for (std::size_t c = 0; c < exact.size(); ++c) {
    const double e = std::abs(exact[c].light - voxels[c].light);
    mae += e / static_cast<double>(exact.size());
    worst = std::max(worst, e);
  }
  std::printf("voxels against spheres: %zu clusters, mean |difference| %.4f, largest %.3f\n",
              exact.size(), mae, worst);
  EXPECT_LT(mae, 0.02);
  EXPECT_LT(worst, 0.15);
  EXPECT_EQ(CanopyLight(sky, g.cluster_spheres, 0.1).evaluate({0, 0, 100}).light, 1.0);
}

struct Profile {
  std::vector<double> fifth_light = std::vector<double>(5, 0.0);  // mean by height fifth
  std::vector<double> fifth_top = std::vector<double>(5, 0.0);    // the same, clusters' tops
  std::vector<std::pair<double, double>> by_lai;  // (leaf area index above, light) per cluster
  double k = 0.0;                                 // fitted Beer-Lambert coefficient
  double worst_bin_error = 0.0;  // largest relative deviation of a leaf-area fifth from exp(-k L)
  // The clusters of each tree's top height fifth: the leaf area above their centres as the sky
  // sees it, their own leaves included (weight 1 / (trees * clusters in the fifth)), and its mean.
  std::vector<std::pair<double, double>> top_fifth_lai;
  double top_fifth_mean_lai = 0.0;
  double top_fifth_vertical_lai = 0.0;  // the vertical leaf area index above their centres
};

// Adds a grown tree's leaf clusters: the mean light of their leaves (the attribute "light") and
// of their tops per height fifth (weighted 1 / trees), and the light at each cluster's top against
// the leaf area above it as the sky sees it.
void add_tree(const GrowthResult& g, int trees, Profile& p) {
  const CanopyLight model(Scene{}, g.cluster_spheres);
  const std::vector<LightSample> tops = model.evaluate_cluster_tops();
  std::vector<std::array<double, 5>> by_height;
  const auto light = g.tree.attribute(kLightAttribute);
  std::size_t j = 0;
  for (NodeId i = 0; i < g.tree.size(); ++i) {
    if (g.tree.kind(i) != OrganKind::kLeaf) continue;
    const Eigen::Vector3d& centre = g.cluster_spheres[j].center;
    by_height.push_back({g.tree.start(i).z(), light[i], tops[j].light,
                         model.sky_leaf_area_index_above(centre),
                         model.leaf_area_index_above(centre)});
    p.by_lai.push_back(
        {model.sky_leaf_area_index_above(cluster_top(g.cluster_spheres[j]), j), tops[j].light});
    ++j;
  }
  std::sort(by_height.begin(), by_height.end());
  for (int f = 0; f < 5; ++f) {
    const std::size_t a = by_height.size() * f / 5, b = by_height.size() * (f + 1) / 5;
    double s = 0.0, top = 0.0;
    for (std::size_t k = a; k < b; ++k) s += by_height[k][1], top += by_height[k][2];
    p.fifth_light[f] += s / static_cast<double>(b - a) / trees;
    p.fifth_top[f] += top / static_cast<double>(b - a) / trees;
  }
  const std::size_t a = by_height.size() * 4 / 5;
  const double w = 1.0 / static_cast<double>((by_height.size() - a) * trees);
  for (std::size_t k = a; k < by_height.size(); ++k) {
    p.top_fifth_lai.push_back({by_height[k][3], w});
    p.top_fifth_mean_lai += w * by_height[k][3];
    p.top_fifth_vertical_lai += w * by_height[k][4];
  }
}

// The profile: mean light and mean leaf area above per fifth of the leaf area above; k minimises
// sum (ln I_b + k L_b)^2 over the fifths, through I/I0 = 1 at L = 0 (Monsi and Saeki 1953 fitted
// their measured profiles so).
void fit_beer(Profile& p) {
  std::sort(p.by_lai.begin(), p.by_lai.end());
  std::vector<std::pair<double, double>> bins;
  for (int f = 0; f < 5; ++f) {
    const std::size_t a = p.by_lai.size() * f / 5, b = p.by_lai.size() * (f + 1) / 5;
    double lai = 0.0, light_sum = 0.0;
    for (std::size_t k = a; k < b; ++k) lai += p.by_lai[k].first, light_sum += p.by_lai[k].second;
    bins.push_back({lai / static_cast<double>(b - a), light_sum / static_cast<double>(b - a)});
  }
  double num = 0.0, den = 0.0;
  for (const auto& [lai, i] : bins) num -= lai * std::log(i), den += lai * lai;
  p.k = num / den;
  for (const auto& [lai, i] : bins) {
    p.worst_bin_error = std::max(p.worst_bin_error, std::abs(i / std::exp(-p.k * lai) - 1.0));
  }
}

// Open-grown trees of every preset and bud light model (20 years, seeds 1-4; the height fifths
// averaged over the seeds, the clusters of the four trees pooled for Beer's law): the tops of the
// clusters, where their sunlit leaves are, get at least 0.7 of the open sky in the top fifth of
// the crown and more than in the bottom fifth, and the light falls with the leaf area above as
// Beer's law says. The mean light of the clusters' leaves (the attribute "light", checked against
// ray-traced leaves in light_yardstick_test.cpp) is printed beside it.
TEST(CanopyLight, OpenGrownCrownsAreLitFromTheTopAndFollowBeersLaw) {
  constexpr int kSeeds = 4;
  for (const char* type : {"A", "B", "C"}) {
    for (const BudLightModel m :
         {BudLightModel::kShadowGrid, BudLightModel::kSky, BudLightModel::kSpaceColonization}) {
      const std::string name = std::string(type) + " " + std::string(bud_light_model_name(m));
      Profile p;
      for (int seed = 1; seed <= kSeeds; ++seed) {
        GrowthParams params = growth_preset(type, m);
        params.years = 20;
        params.seed = static_cast<std::uint64_t>(seed);
        add_tree(grow_tree(params), kSeeds, p);
      }
      fit_beer(p);
      const auto& f = p.fifth_light;
      const auto& t = p.fifth_top;
      // What Beer's law with the fitted k gives the top fifth's leaves for the leaf area above
      // their centres (their own cluster's included): the ceiling of the goal "top fifth >= 0.7".
      double beer_top = 0.0;
      for (const auto& [lai, w] : p.top_fifth_lai) beer_top += w * std::exp(-p.k * lai);
      std::printf(
          "%-20s leaves %.2f %.2f %.2f %.2f %.2f  tops %.2f %.2f %.2f %.2f %.2f  k %.3f  "
          "worst Beer fifth %.2f  top fifth: L %.2f (vertical %.2f), Beer %.2f\n",
          name.c_str(), f[0], f[1], f[2], f[3], f[4], t[0], t[1], t[2], t[3], t[4], p.k,
          p.worst_bin_error, p.top_fifth_mean_lai, p.top_fifth_vertical_lai, beer_top);
      // Beer's law with the fitted k puts the top fifth's leaves below 0.7 of the open sky in
      // every crown (the leaf area above them, their own cluster's included, exceeds
      // ln(1 / 0.7) / k = 0.5-0.85), so a goal of 0.7 for them is out of reach of the physics;
      // their mean light lies at 0.65-1.0 of Beer's value (docs/environment.md).
      EXPECT_LT(beer_top, 0.7) << name;
      EXPECT_GT(f[4], 0.6 * beer_top) << name;
      EXPECT_LT(f[4], 1.05 * beer_top) << name;
      EXPECT_GE(t[4], 0.7) << name;
      EXPECT_GT(t[4], t[0]) << name;
      EXPECT_LE(p.worst_bin_error, 0.2) << name;
    }
  }
}

}  // namespace
}  // namespace fspm::environment
