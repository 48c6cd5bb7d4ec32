// Impostor geometry: the view chosen for a direction against hand-computed angles, the quad of a
// rotated, scaled plant against its placed bounding sphere and the eye, the quads toward the sun.
#include "graphics/impostor.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "fspm/error.hpp"

namespace fspm::graphics {
namespace {

constexpr double kPi = 3.141592653589793;

Eigen::Vector3d at(double azimuth_deg, double elevation_deg) {
  const double a = azimuth_deg * kPi / 180.0, e = elevation_deg * kPi / 180.0;
  return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

TEST(Impostor, NearestViewByAngle) {
  const ImpostorViews v;  // 8 azimuths (45 degrees apart) at 0, 35 and 70 degrees
  EXPECT_EQ(impostor_view_count(v), 24);
  EXPECT_EQ(nearest_impostor_view(v, {1, 0, 0}), 0);
  EXPECT_EQ(nearest_impostor_view(v, at(44.0, 0.0)), 1);
  EXPECT_EQ(nearest_impostor_view(v, at(-44.0, 5.0)), 7);
  EXPECT_EQ(nearest_impostor_view(v, at(181.0, 0.0)), 4);
  // 20 degrees up: 15 degrees from the 35-degree ring, 20 from the horizon.
  EXPECT_EQ(nearest_impostor_view(v, at(0.0, 20.0)), 8);
  EXPECT_EQ(nearest_impostor_view(v, at(0.0, 15.0)), 0);
  EXPECT_EQ(nearest_impostor_view(v, at(90.0, 60.0)), 16 + 2);
  // Straight down is nearest the horizon ring (90 degrees), not the 70-degree one (160).
  EXPECT_EQ(nearest_impostor_view(v, {0, 0, -1}) / 8, 0);
  EXPECT_EQ(nearest_impostor_view(v, {0, 0, 1}) / 8, 2);
  for (int k = 0; k < 24; ++k) {
    EXPECT_NEAR(impostor_view_direction(v, k).norm(), 1.0, 1e-12);
    EXPECT_EQ(nearest_impostor_view(v, impostor_view_direction(v, k)), k);
  }
}

TEST(Impostor, RejectsTooFewViews) {
  ImpostorViews v;
  v.azimuths = 2;
  EXPECT_THROW(v.validate(), ValueError);
  v = ImpostorViews{};
  v.elevations_deg.clear();
  EXPECT_THROW(v.validate(), ValueError);
  v.elevations_deg = {95.0};
  EXPECT_THROW(v.validate(), ValueError);
}

// One plant whose bounding sphere has centre (0, 0, 1) and radius 1, placed twice: turned by 90
// degrees about +z and doubled at (10, 0, 0), and as it is at (-10, 0, 0).
LodScene two_plants() {
  LodScene scene;
  LodPlant plant;
  plant.variants = {{TriangleMesh{}}};
  plant.sphere.center = {0, 0, 1};
  plant.sphere.radius = 1.0;
  scene.plants.push_back(plant);
  PartPlacement turned;
  turned.linear =
      2.0f *
      Eigen::AngleAxisf(static_cast<float>(kPi / 2), Eigen::Vector3f::UnitZ()).toRotationMatrix();
  turned.translation = {10, 0, 0};
  PartPlacement plain;
  plain.translation = {-10, 0, 0};
  scene.placements = {turned, plain};
  return scene;
}

Eigen::Vector3d corner(const ImpostorVertex& v) {
  return {v.position[0], v.position[1], v.position[2]};
}

TEST(Impostor, QuadFacesTheEyeAndSpansThePlacedSphere) {
  const LodScene scene = two_plants();
  std::vector<InstanceLod> choice(2);
  choice[0].visible = choice[0].impostor = true;  // the second is drawn as a mesh
  choice[1].visible = true;
  const Eigen::Vector3d eye(10, -50, 2);  // in front of the turned plant, looking along +y
  std::vector<ImpostorVertex> quads;
  append_impostor_quads(scene, choice, ImpostorViews{}, eye, Eigen::Vector3d::UnitY(), quads);
  ASSERT_EQ(quads.size(), 4u);
  const Eigen::Vector3d center(10, 0, 2);  // turned and doubled: (0, 0, 2) + (10, 0, 0)
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& q : quads) mean += corner(q) / 4.0;
  EXPECT_NEAR((mean - center).norm(), 0.0, 1e-5);
  for (const auto& q : quads) {
    EXPECT_NEAR((corner(q) - center).norm(), 2.0 * std::sqrt(2.0), 1e-5);  // radius 2
    // Seen from the eye the image's right (u = 1) is +x and its up (v = 1) nearly +z.
    EXPECT_EQ(corner(q).x() > center.x(), q.uv[0] > 0.5f);
    EXPECT_EQ(corner(q).z() > center.z(), q.uv[1] > 0.5f);
  }
  const Eigen::Vector3d normal =
      (corner(quads[1]) - corner(quads[0])).cross(corner(quads[2]) - corner(quads[0]));
  EXPECT_GT(normal.normalized().dot((eye - center).normalized()), 0.9999);
  // The eye lies along -y of the world, which the turn maps from -x of the plant: azimuth 180
  // degrees, elevation atan(0 / 50) = 0: view 4 of plant 0.
  EXPECT_EQ(quads[0].layer, 4.0f);
  // The sun along +y of the world is along +x of the turned plant; the radius is the placed one.
  EXPECT_NEAR(quads[0].sun_local[0], 1.0f, 1e-6f);
  EXPECT_NEAR(quads[0].sun_local[1], 0.0f, 1e-6f);
  EXPECT_FLOAT_EQ(quads[0].radius, 2.0f);
}

TEST(Impostor, QuadsTowardTheSunShowItsView) {
  const LodScene scene = two_plants();
  std::vector<InstanceLod> choice(2);
  for (auto& c : choice) c.visible = c.impostor = true;
  choice[0].visible = false;  // culled: no quad
  const Eigen::Vector3d sun = at(90.0, 65.0);
  std::vector<ImpostorVertex> quads;
  append_impostor_quads_toward(scene, choice, ImpostorViews{}, sun, quads);
  ASSERT_EQ(quads.size(), 4u);
  const Eigen::Vector3d normal =
      (corner(quads[1]) - corner(quads[0])).cross(corner(quads[2]) - corner(quads[0]));
  EXPECT_GT(normal.normalized().dot(sun), 0.9999);
  EXPECT_EQ(quads[0].layer, 16.0f + 2.0f);  // azimuth 90, nearest ring 70 degrees
}

}  // namespace
}  // namespace fspm::graphics
