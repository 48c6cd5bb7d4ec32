// Meshes of a growth scene's obstacles (io/obstacle_mesh, io/obstacle_crop), checked against
// the environment's own geometry: Box::contains, closed-form areas and volumes.
#include "io/obstacle_mesh.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "environment/scene_file.hpp"
#include "fspm/error.hpp"
#include "io/obstacle_crop.hpp"

namespace fspm::io {
namespace {

using graphics::Material;
using graphics::TriangleMesh;

environment::Box oriented_box() {
  environment::Box b;
  b.center = {1.0, 2.0, 3.0};
  b.half_extent = {0.5, 1.0, 2.0};  // sizes 1, 2, 4
  b.rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  return b;
}

environment::Box scaled(environment::Box b, double grow) {
  b.half_extent.array() += grow;
  return b;
}

Eigen::Vector3d corner(const TriangleMesh& m, std::uint32_t i) {
  return m.positions[i].cast<double>();
}

Eigen::Vector3d face_normal(const TriangleMesh& m, const TriangleMesh::Triangle& t) {
  return (corner(m, t[1]) - corner(m, t[0])).cross(corner(m, t[2]) - corner(m, t[0]));
}

// Signed volume enclosed by a closed mesh (positive when the triangles face outward).
double enclosed_volume(const TriangleMesh& m) {
  double v = 0.0;
  for (const auto& t : m.triangles) {
    v += corner(m, t[0]).dot(corner(m, t[1]).cross(corner(m, t[2]))) / 6.0;
  }
  return v;
}

TEST(ObstacleMesh, OrientedBoxIsTwelveTrianglesOnItsSurface) {
  const environment::Box box = oriented_box();
  TriangleMesh mesh;
  append_box_mesh(box, mesh);
  ASSERT_EQ(mesh.vertex_count(), 24u);
  ASSERT_EQ(mesh.triangle_count(), 12u);
  EXPECT_EQ(mesh.triangle_count(Material::kObstacle), 12u);
  EXPECT_EQ(mesh.uvs.size(), 24u);
  const double tol = 1e-5;
  for (std::uint32_t i = 0; i < mesh.vertex_count(); ++i) {
    EXPECT_TRUE(scaled(box, tol).contains(corner(mesh, i))) << i;    // inside or on the box,
    EXPECT_FALSE(scaled(box, -tol).contains(corner(mesh, i))) << i;  // not strictly inside
  }
  double area = 0.0;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d n = face_normal(mesh, t);
    area += 0.5 * n.norm();
    const Eigen::Vector3d centroid =
        (corner(mesh, t[0]) + corner(mesh, t[1]) + corner(mesh, t[2])) / 3.0;
    EXPECT_GT(n.dot(centroid - box.center), 0.0);  // counter-clockwise seen from outside
    for (std::uint32_t i : t) {
      EXPECT_NEAR(mesh.normals[i].cast<double>().dot(n.normalized()), 1.0, 1e-5);  // flat
    }
  }
  EXPECT_NEAR(area, 2.0 * (1 * 2 + 2 * 4 + 4 * 1), 1e-4);
  EXPECT_NEAR(enclosed_volume(mesh), 1.0 * 2.0 * 4.0, 1e-4);
}

TEST(ObstacleMesh, SphereIsClosedAndOutward) {
  const Eigen::Vector3d c(1, -2, 0.5);
  TriangleMesh mesh;
  append_sphere_mesh(c, 0.8, 32, mesh);
  EXPECT_EQ(mesh.triangle_count(), 32u * (2u * 16u - 2u));
  for (std::size_t i = 0; i < mesh.vertex_count(); ++i) {
    EXPECT_NEAR((corner(mesh, i) - c).norm(), 0.8, 1e-5);
  }
  // An inscribed polyhedron: a little under the ball's volume, all faces outward.
  const double ball = 4.0 / 3.0 * std::numbers::pi * 0.8 * 0.8 * 0.8;
  double moved = 0.0;  // the volume does not depend on where the sphere is
  for (const auto& t : mesh.triangles) {
    moved +=
        (corner(mesh, t[0]) - c).dot((corner(mesh, t[1]) - c).cross(corner(mesh, t[2]) - c)) / 6.0;
  }
  EXPECT_NEAR(moved, enclosed_volume(mesh), 1e-6);
  EXPECT_LT(moved, ball);
  EXPECT_GT(moved, 0.97 * ball);
  EXPECT_THROW(append_sphere_mesh(c, 1.0, 2, mesh), ValueError);
}

TEST(ObstacleMesh, SceneBoxesSpheresAndMeshesWithoutTheGround) {
  const environment::Scene scene = environment::parse_scene_json(R"({
    "occluders": [
      {"type": "ground", "z": 0},
      {"type": "wall", "from": [2, -20], "to": [2, 20], "height": 4},
      {"type": "box", "min": [-1, -1, 0], "max": [0, 0, 1], "axis": [0, 0, 1], "angle_deg": 30},
      {"type": "sphere", "center": [0, 3, 1], "radius": 0.5, "solid": true},
      {"type": "mesh", "vertices": [[0, 0, 5], [1, 0, 5], [0, 1, 5]], "triangles": [[0, 1, 2]]}
    ]})");
  const TriangleMesh mesh = mesh_obstacles(scene, 8);
  EXPECT_EQ(mesh.triangle_count(), 12u + 12u + 8u * (2u * 4u - 2u) + 1u);
  // The sphere lets light through (0.5^0.5 by Pirk eq. 4.4): drawn see-through; the rest opaque.
  EXPECT_EQ(mesh.triangle_count(Material::kTranslucentObstacle), 8u * (2u * 4u - 2u));
  EXPECT_EQ(mesh.triangle_count(Material::kObstacle), 12u + 12u + 1u);
  // Every vertex carries its obstacle's translucency: the sphere's, 0 for the opaque ones.
  const auto gamma = mesh.attribute("translucency");
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const bool translucent = mesh.materials[t] == Material::kTranslucentObstacle;
    for (std::uint32_t v : mesh.triangles[t]) {
      EXPECT_NEAR(gamma[v], translucent ? std::sqrt(0.5) : 0.0, 1e-6);
    }
  }
  EXPECT_EQ(mesh.normals.size(), mesh.vertex_count());
  // The mesh's triangle faces up (counter-clockwise from above): so does its normal.
  EXPECT_NEAR(mesh.normals.back().z(), 1.0f, 1e-6f);
  // The 40 m wall: x in [1.9, 2.1], y in [-20, 20], z in [0, 4].
  EXPECT_NEAR(mesh.bbox_max().y(), 20.0f, 1e-4f);
  EXPECT_TRUE(
      mesh_obstacles(environment::parse_scene_json(R"({"occluders": [{"type": "ground"}]})"))
          .empty());
}

TEST(ObstacleCrop, RegionAroundThePlants) {
  Eigen::Vector2d lo, hi;
  obstacle_region({-1, -0.5, 0}, {1, 0.5, 8}, lo, hi);  // sizes 2, 1, 8: margin 4
  EXPECT_TRUE(lo.isApprox(Eigen::Vector2d(-5, -4.5)));
  EXPECT_TRUE(hi.isApprox(Eigen::Vector2d(5, 4.5)));
  obstacle_region({0, 0, 0}, {0.1, 0.1, 0.5}, lo, hi);  // small: at least 1 m
  EXPECT_TRUE(lo.isApprox(Eigen::Vector2d(-1, -1)));
}

TEST(ObstacleCrop, LongWallCutToTheRegionFarOnesDropped) {
  environment::Scene scene;
  scene.boxes.push_back(environment::Box::wall({2, -20}, {2, 20}, 0, 4, 0.2));
  scene.boxes.push_back(environment::Box::wall({10, -20}, {10, 20}, 0, 4, 0.2));
  scene.spheres.push_back({{0, 2, 1}, 0.5, 0.0, true});
  scene.spheres.push_back({{0, 9, 1}, 0.5, 0.0, true});
  scene.ground = environment::Ground{};
  const environment::Scene near = obstacles_near(scene, {-3, -3}, {3, 3});
  ASSERT_EQ(near.boxes.size(), 1u);
  EXPECT_EQ(near.spheres.size(), 1u);
  EXPECT_FALSE(near.ground.has_value());
  TriangleMesh mesh;
  append_box_mesh(near.boxes[0], mesh);
  EXPECT_NEAR(mesh.bbox_min().x(), 1.9f, 1e-5f);
  EXPECT_NEAR(mesh.bbox_max().x(), 2.1f, 1e-5f);
  EXPECT_NEAR(mesh.bbox_min().y(), -3.0f, 1e-5f);
  EXPECT_NEAR(mesh.bbox_max().y(), 3.0f, 1e-5f);
  EXPECT_NEAR(mesh.bbox_min().z(), 0.0f, 1e-5f);
  EXPECT_NEAR(mesh.bbox_max().z(), 4.0f, 1e-5f);  // the height is kept
}

TEST(ObstacleCrop, SlantedBoxKeepsEverythingInsideTheRegion) {
  environment::Box box;
  box.half_extent = {6, 0.5, 1};
  box.rotation = Eigen::AngleAxisd(0.6, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  environment::Scene scene;
  scene.boxes.push_back(box);
  const Eigen::Vector2d lo(-2, -1), hi(2, 1.5);
  const environment::Scene near = obstacles_near(scene, lo, hi);
  ASSERT_EQ(near.boxes.size(), 1u);
  const environment::Box& cut = near.boxes[0];
  EXPECT_LT(cut.half_extent.x(), box.half_extent.x());
  // Every point of the box within the region is in the cut box, which lies within the box.
  for (double a = -1; a <= 1; a += 0.05) {
    for (double b = -1; b <= 1; b += 0.25) {
      const Eigen::Vector3d p = box.center + box.rotation * Eigen::Vector3d(6 * a, 0.5 * b, 0.3);
      const bool in_region =
          p.x() >= lo.x() && p.x() <= hi.x() && p.y() >= lo.y() && p.y() <= hi.y();
      if (in_region) {
        EXPECT_TRUE(scaled(cut, 1e-9).contains(p)) << p.transpose();
      }
      if (cut.contains(p)) {
        EXPECT_TRUE(scaled(box, 1e-9).contains(p));
      }
    }
  }
}

}  // namespace
}  // namespace fspm::io
