#include "environment/canopy_sweep.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "environment/canopy_light.hpp"
#include "environment/leaf_light_model.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {
namespace {

// The sweep against the exact turbid medium (CanopyLight, every path through the sphere in closed
// form, no cutoff) inside and around one large cluster.
TEST(CanopySweep, MatchesTheExactPathsThroughALargeCluster) {
  const std::vector<Sphere> cluster = {{Eigen::Vector3d(0.3, -0.2, 3.0), 2.0, 0.1, false}};
  Scene scene;
  scene.sky.directions = 64;
  scene.sky.significance = 0.0;
  const CanopyLight exact(scene, cluster);
  CanopySweep sweep(64, Eigen::Vector3d::UnitZ(), 0.4);
  const std::vector<Eigen::Vector3d> points = {cluster[0].center,
                                               cluster[0].center + Eigen::Vector3d(0.0, 0.0, 1.0),
                                               cluster[0].center + Eigen::Vector3d(1.0, 0.0, -1.0),
                                               cluster[0].center + Eigen::Vector3d(0.0, 0.5, -1.7)};
  std::vector<LightSample> out(points.size());
  sweep.evaluate(cluster, points, {}, out);
  // At the centre every path is one radius: exp(-mu r) = sqrt(gamma) = 0.316.
  EXPECT_NEAR(exact.evaluate(points[0]).light, std::sqrt(0.1), 1e-3);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const LightSample e = exact.evaluate(points[k]);
    EXPECT_NEAR(out[k].light, e.light, 0.03) << k;
    EXPECT_GT(out[k].direction.dot(e.direction), 0.99) << k;
  }
}

TEST(CanopySweep, OpenSkyAndObstacleVisibility) {
  CanopySweep sweep(64, Eigen::Vector3d::UnitZ(), 0.4);
  const std::vector<Sphere> none;
  const std::vector<Eigen::Vector3d> points = {Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, 5, 6)};
  // The east half of the sky hidden at the first point, nothing at the second.
  std::vector<float> east(64, 1.0f);
  double kept = 0.0, all = 0.0;  // the cos^2 weights of the directions left open, and of all
  for (int i = 0; i < 64; ++i) {
    const Eigen::Vector3d& d = sweep.directions().direction(i);
    all += d.z() * d.z();
    if (d.x() > 0.0) {
      east[static_cast<std::size_t>(i)] = 0.0f;
    } else {
      kept += d.z() * d.z();
    }
  }
  const std::vector<std::span<const float>> vis = {east, {}};
  std::vector<LightSample> out(2);
  sweep.evaluate(none, points, vis, out);
  EXPECT_NEAR(out[0].light, kept / all, 1e-6);
  EXPECT_LT(out[0].direction.x(), -0.1);
  EXPECT_DOUBLE_EQ(out[1].light, 1.0);
  EXPECT_THROW(CanopySweep(64, Eigen::Vector3d::UnitZ(), 0.0), ValueError);
}

TEST(LeafLightModels, EveryRegisteredModelShadesAClusterBelowAnother) {
  Sky sky;
  sky.directions = 64;
  const std::vector<Sphere> both = {{Eigen::Vector3d(0, 0, 2), 0.3, 0.7, false},
                                    {Eigen::Vector3d(0, 0, 3.5), 1.0, 0.3, false}};
  ASSERT_GE(leaf_light_models().size(), 2u);
  for (const LeafLightModelEntry& e : leaf_light_models()) {
    std::vector<LightSample> alone(1), under(2);
    const auto model = make_leaf_light_model(e.name, sky);
    model->evaluate(std::span(both).first(1), {}, alone);
    model->evaluate(both, {}, under);
    EXPECT_LT(alone[0].light, 1.0) << e.name;  // its own leaves
    EXPECT_GT(alone[0].light, 0.7) << e.name;
    EXPECT_LT(under[0].light, alone[0].light - 0.1) << e.name;  // under the big cluster
  }
  EXPECT_THROW(make_leaf_light_model("raytrace", sky), ValueError);
}

}  // namespace
}  // namespace fspm::environment
