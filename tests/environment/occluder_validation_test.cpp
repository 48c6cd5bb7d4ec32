// Obstacles check themselves: every value out of range is refused with what was expected.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <limits>

#include "environment/light_model.hpp"
#include "environment/occluders.hpp"
#include "environment/sky.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

TEST(OccluderValidation, Spheres) {
  EXPECT_NO_THROW((Sphere{{0, 0, 1}, 0.5, 0.3, false}.validate()));
  EXPECT_THROW((Sphere{{0, 0, 1}, 0.0, 0.3, false}.validate()), ValueError);
  EXPECT_THROW((Sphere{{0, kNan, 1}, 0.5, 0.3, false}.validate()), ValueError);
  EXPECT_THROW((Sphere{{0, 0, 1}, 0.5, 1.5, false}.validate()), ValueError);
  EXPECT_THROW((Sphere{{0, 0, 1}, 0.5, -0.1, false}.validate()), ValueError);
}

TEST(OccluderValidation, BoxesAndWalls) {
  EXPECT_NO_THROW(Box::from_min_max({0, 0, 0}, {1, 2, 3}).validate());
  EXPECT_THROW(Box::from_min_max({0, 0, 0}, {1, 0, 3}).validate(), ValueError);  // flat
  EXPECT_NO_THROW(Box::wall({0, 0}, {3, 4}, 0.0, 2.0, 0.2).validate());
  EXPECT_THROW(Box::wall({1, 1}, {1, 1}, 0.0, 2.0, 0.2).validate(), ValueError);  // no length
  EXPECT_THROW(Box::wall({0, 0}, {3, 4}, 0.0, 0.0, 0.2).validate(), ValueError);  // no height
  EXPECT_THROW(Box::wall({0, 0}, {3, 4}, 0.0, 2.0, kNan).validate(), ValueError);
  Box turned = Box::from_min_max({0, 0, 0}, {1, 1, 1});
  turned.rotation = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  EXPECT_NO_THROW(turned.validate());
  turned.rotation(0, 0) *= 2.0;  // no longer a rotation
  EXPECT_THROW(turned.validate(), ValueError);
  Box see_through = Box::from_min_max({0, 0, 0}, {1, 1, 1});
  see_through.translucency = 1.01;
  EXPECT_THROW(see_through.validate(), ValueError);
}

TEST(OccluderValidation, Ground) {
  EXPECT_NO_THROW((Ground{-1.0, 0.0, true}.validate()));
  EXPECT_THROW((Ground{kNan, 0.0, true}.validate()), ValueError);
  EXPECT_THROW((Ground{0.0, 2.0, true}.validate()), ValueError);
}

// The sky checks itself too, and every light model built from a scene uses that check.
TEST(SkyValidation, RefusesWhatNoLightIntegralCanUse) {
  EXPECT_NO_THROW(Sky{}.validate());
  Sky s;
  s.directions = 0;
  EXPECT_THROW(s.validate(), ValueError);
  s.directions = (1 << 20) + 1;
  EXPECT_THROW(s.validate(), ValueError);
  s = Sky{};
  s.significance = 1.0;
  EXPECT_THROW(s.validate(), ValueError);
  s.significance = kNan;
  EXPECT_THROW(s.validate(), ValueError);
  s = Sky{};
  s.brightest = Eigen::Vector3d::Zero();
  EXPECT_THROW(s.validate(), ValueError);
  s.brightest = {0, 0, 2};  // not normalized
  EXPECT_THROW(s.validate(), ValueError);
  Scene scene;
  scene.sky.directions = -3;
  EXPECT_THROW(LightModel{scene}, ValueError);
}

// Pirk eq. 4.3's sky, I = cos^2 of the angle to the brightest point, is the same for b and -b:
// a brightest point below the horizon is allowed and lights a sphere's shadow like its mirror.
TEST(SkyValidation, BrightestBelowTheHorizonLightsLikeItsMirror) {
  Scene below;
  below.sky.brightest = Eigen::Vector3d(1, 0, -1).normalized();
  below.spheres.push_back({{-1.5, 0.0, 1.5}, 1.0, 0.0, false});  // towards the mirror of b
  Scene above = below;
  above.sky.brightest = -below.sky.brightest;
  const LightSample a = LightModel(below).evaluate({0, 0, 0});
  const LightSample b = LightModel(above).evaluate({0, 0, 0});
  EXPECT_LT(a.light, 0.9);
  EXPECT_NEAR(a.light, b.light, 1e-12);
}

}  // namespace
}  // namespace fspm::environment
