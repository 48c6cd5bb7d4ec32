// Curved PN triangles (Vlachos et al. 2001) against closed forms: a flat triangle stays flat; on
// a circle of radius 1 through two corners with radial normals, the edge's cubic has control
// points ((3 - cos t) P0 + P1) / 3 and (P0 + (3 - cos t) P1) / 3, so its midpoint lies at
// (5 - cos t) cos(t / 2) / 4 from the centre, whatever the third corner; the uniform
// tessellation's counts, corners and interpolated attributes.
#include "graphics/pn_triangles.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "fspm/error.hpp"

namespace fspm::graphics {
namespace {

constexpr double kPi = 3.141592653589793;

TEST(PnTriangle, FlatTriangleStaysFlat) {
  const Eigen::Vector3f z = Eigen::Vector3f::UnitZ();
  const PnTriangle t = pn_triangle(
      {Eigen::Vector3f(0, 0, 1), Eigen::Vector3f(2, 0, 1), Eigen::Vector3f(0.5f, 1.5f, 1)},
      {z, z, z});
  for (const Eigen::Vector3f& w : {Eigen::Vector3f(1, 0, 0), Eigen::Vector3f(0.2f, 0.3f, 0.5f),
                                   Eigen::Vector3f(1 / 3.0f, 1 / 3.0f, 1 / 3.0f)}) {
    EXPECT_NEAR(pn_point(t, w).z(), 1.0f, 1e-6f);
    EXPECT_NEAR((pn_normal(t, w) - z).norm(), 0.0f, 1e-6f);
  }
  // A flat PN triangle is the linear one: the point at weights w is the weighted corners.
  const Eigen::Vector3f w(0.2f, 0.3f, 0.5f);
  const Eigen::Vector3f linear = 0.2f * Eigen::Vector3f(0, 0, 1) + 0.3f * Eigen::Vector3f(2, 0, 1) +
                                 0.5f * Eigen::Vector3f(0.5f, 1.5f, 1);
  EXPECT_NEAR((pn_point(t, w) - linear).norm(), 0.0f, 1e-5f);
}

TEST(PnTriangle, EdgeMidpointOfACircularArcIsTheClosedForm) {
  for (const double degrees : {30.0, 90.0}) {
    const double t = degrees * kPi / 180.0;
    const Eigen::Vector3f p0(1, 0, 0),
        p1(static_cast<float>(std::cos(t)), static_cast<float>(std::sin(t)), 0);
    const double expected = (5.0 - std::cos(t)) * std::cos(t / 2.0) / 4.0;
    for (const Eigen::Vector3f& third :
         {Eigen::Vector3f(0, 0, 1), Eigen::Vector3f(0.6f, 0, 0.8f)}) {
      const PnTriangle pn = pn_triangle({p0, p1, third}, {p0, p1, third});
      const Eigen::Vector3f mid = pn_point(pn, Eigen::Vector3f(0.5f, 0.5f, 0.0f));
      EXPECT_NEAR(mid.norm(), expected, 1e-5) << degrees << " degrees";
      EXPECT_NEAR(mid.z(), 0.0f, 1e-6f);  // the edge's curve stays in the circle's plane
    }
    // Nearer the circle than the chord: at 30 degrees 0.9983 against cos 15 = 0.9659.
    EXPECT_GT(expected, std::cos(t / 2.0));
  }
}

TEST(TessellatePn, SplitsEachTriangleIntoLevelSquared) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.normals.assign(4, Eigen::Vector3f::UnitZ());
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.materials = {Material::kBark, Material::kLeaf};
  m.add_attribute("age") = {0.0f, 3.0f, 6.0f, 9.0f};
  const TriangleMesh t = tessellate_pn(m, 3);
  ASSERT_EQ(t.triangle_count(), 18u);
  EXPECT_EQ(t.triangle_count(Material::kBark), 9u);
  EXPECT_EQ(t.vertex_count(), 20u);  // 10 grid points per triangle
  double area = 0.0;
  for (const auto& tri : t.triangles) {
    const Eigen::Vector3f n = (t.positions[tri[1]] - t.positions[tri[0]])
                                  .cross(t.positions[tri[2]] - t.positions[tri[0]]);
    EXPECT_GT(n.z(), 0.0f);  // counter-clockwise as the input
    area += 0.5 * n.norm();
  }
  EXPECT_NEAR(area, 1.0, 1e-5);
  // The first triangle's grid point (i, j) = (1, 1) has weights (1/3, 1/3, 1/3): its centroid.
  const std::span<const float> age = t.attribute("age");
  EXPECT_NEAR(age[5], 3.0f, 1e-5f);  // row 0 has 4 points, (1, 1) is the second of row 1
  EXPECT_NEAR((t.positions[5] - Eigen::Vector3f(2 / 3.0f, 1 / 3.0f, 0)).norm(), 0.0f, 1e-6f);
  EXPECT_NEAR((t.uvs[5] - Eigen::Vector2f(2 / 3.0f, 1 / 3.0f)).norm(), 0.0f, 1e-6f);
  EXPECT_EQ(tessellate_pn(m, 1).triangle_count(), 2u);
  EXPECT_THROW(tessellate_pn(m, 0), ValueError);
}

}  // namespace
}  // namespace fspm::graphics
