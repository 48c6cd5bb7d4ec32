#include "graphics/foliage.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "fspm/error.hpp"
#include "graphics/tree_mesher.hpp"
#include "tests/graphics/test_trees.hpp"

namespace fspm::graphics {
namespace {

using testing::add;

// One vertical internode (radius 0.05: 16 sides, one segment) and two leaf clusters of length 0
// at its top (as grown trees keep them), radius 0.3 and 0.2, light 0.25 and 0.75.
TreeGraph clustered_tree() {
  TreeGraph t;
  const Eigen::Vector3d o(0, 0, 0), top(0, 0, 1);
  const NodeId trunk = add(t, kNoNode, o, top, 0.05, 0, 0);
  add(t, trunk, Eigen::Vector3d(1, 0, 2), Eigen::Vector3d(1, 0, 2), 0.3, 1, 1, OrganKind::kLeaf);
  add(t, trunk, Eigen::Vector3d(-1, 0, 2), Eigen::Vector3d(-1, 0, 2), 0.2, 1, 1, OrganKind::kLeaf);
  t.add_attribute("light", 0.0);
  t.attribute("light")[1] = 0.25;
  t.attribute("light")[2] = 0.75;
  return t;
}

// The tube alone: (1 + 1) rings and two caps of 17 vertices, 2 * 16 wall and 2 * 16 cap
// triangles.
constexpr std::size_t kTubeVertices = 4 * 17;
constexpr std::size_t kTubeTriangles = 64;

MeshOptions with_foliage(FoliageMode mode, std::uint64_t seed = 7) {
  MeshOptions o;
  o.leaves = true;
  o.foliage.mode = mode;
  o.foliage_seed = seed;
  return o;
}

TEST(Foliage, LeafCloudCountsFollowTheClosedForm) {
  const TriangleMesh mesh = mesh_tree(clustered_tree(), with_foliage(FoliageMode::kLeaves));
  // 32 leaves per cluster, each a quad of 4 vertices and 2 triangles.
  EXPECT_EQ(mesh.vertex_count(), kTubeVertices + 2 * 32 * 4);
  EXPECT_EQ(mesh.triangle_count(), kTubeTriangles + 2 * 32 * 2);
  EXPECT_EQ(mesh.triangle_count(Material::kLeaf), 128u);
  const MeshCounts counts = count_mesh(clustered_tree(), with_foliage(FoliageMode::kLeaves));
  EXPECT_EQ(counts.vertices, mesh.vertex_count());
  EXPECT_EQ(counts.triangles, mesh.triangle_count());
  EXPECT_EQ(counts.clusters, 2u);
  EXPECT_EQ(counts.leaves, 0u);
  // Without --leaves the clusters add nothing.
  EXPECT_EQ(mesh_tree(clustered_tree()).triangle_count(), kTubeTriangles);
}

TEST(Foliage, LeavesStayInsideTheirClusterSphere) {
  const TreeGraph tree = clustered_tree();
  const TriangleMesh mesh = mesh_tree(tree, with_foliage(FoliageMode::kLeaves));
  std::size_t far_from_centre = 0;
  for (std::size_t v = kTubeVertices; v < mesh.vertex_count(); ++v) {
    const std::size_t cluster = v < kTubeVertices + 128 ? 1 : 2;
    const double d = (mesh.positions[v].cast<double>() - tree.start(cluster)).norm();
    EXPECT_LE(d, tree.radius(cluster) * (1 + 1e-6)) << "vertex " << v;
    // The cloud fills the sphere rather than a point: some vertices reach its outer half.
    if (d > 0.5 * tree.radius(cluster)) ++far_from_centre;
  }
  EXPECT_GT(far_from_centre, 64u);
  // Every vertex carries its cluster's attributes.
  const auto light = mesh.attribute("light");
  EXPECT_FLOAT_EQ(light[kTubeVertices], 0.25f);
  EXPECT_FLOAT_EQ(light[mesh.vertex_count() - 1], 0.75f);
}

TEST(Foliage, SameSeedSamePicture) {
  const TreeGraph tree = clustered_tree();
  const TriangleMesh a = mesh_tree(tree, with_foliage(FoliageMode::kLeaves, 3));
  const TriangleMesh b = mesh_tree(tree, with_foliage(FoliageMode::kLeaves, 3));
  const TriangleMesh c = mesh_tree(tree, with_foliage(FoliageMode::kLeaves, 4));
  ASSERT_EQ(a.vertex_count(), c.vertex_count());
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_NE(a.positions, c.positions);
}

TEST(Foliage, CrownVolumesAreClosedSpheres) {
  const TreeGraph tree = clustered_tree();
  const TriangleMesh mesh = mesh_tree(tree, with_foliage(FoliageMode::kVolumes));
  // 8 stacks, 12 slices: 9 * 13 vertices, 2 * 12 * 7 triangles (one per cell at the poles).
  EXPECT_EQ(mesh.vertex_count(), kTubeVertices + 2 * 117);
  EXPECT_EQ(mesh.triangle_count(Material::kCrown), 2u * 168);
  // Vertices on the sphere; triangles facing outwards; the enclosed volume (divergence theorem,
  // sum of a . (b x c) / 6) close to 4/3 pi r^3 and below it (an inscribed polyhedron).
  for (std::size_t cluster : {1u, 2u}) {
    const Eigen::Vector3d c = tree.start(cluster);
    const double r = tree.radius(cluster);
    double volume = 0.0;
    const std::size_t first = kTubeTriangles + (cluster - 1) * 168;
    for (std::size_t t = first; t < first + 168; ++t) {
      ASSERT_EQ(mesh.materials[t], Material::kCrown);
      const Eigen::Vector3d a = mesh.positions[mesh.triangles[t][0]].cast<double>() - c;
      const Eigen::Vector3d b = mesh.positions[mesh.triangles[t][1]].cast<double>() - c;
      const Eigen::Vector3d d = mesh.positions[mesh.triangles[t][2]].cast<double>() - c;
      for (const Eigen::Vector3d* p : {&a, &b, &d}) EXPECT_NEAR(p->norm(), r, 1e-5);
      EXPECT_GT((b - a).cross(d - a).dot(a + b + d), 0.0) << "triangle " << t;
      volume += a.dot(b.cross(d)) / 6.0;
    }
    const double sphere = 4.0 / 3.0 * std::numbers::pi * r * r * r;
    EXPECT_LT(volume, sphere);
    EXPECT_GT(volume, 0.9 * sphere);
  }
}

TEST(Foliage, BadNamesAndOptionsAreUserErrors) {
  EXPECT_EQ(foliage_mode_from_name("volumes"), FoliageMode::kVolumes);
  EXPECT_EQ(foliage_mode_from_name("leaves"), FoliageMode::kLeaves);
  EXPECT_THROW(foliage_mode_from_name("fog"), ValueError);
  MeshOptions o = with_foliage(FoliageMode::kLeaves);
  o.foliage.leaf_length_ratio = 1.5;  // a leaf longer than the cluster's radius
  EXPECT_THROW(mesh_tree(clustered_tree(), o), ValueError);
  o = with_foliage(FoliageMode::kVolumes);
  o.foliage.sphere_stacks = 1;
  EXPECT_THROW(mesh_tree(clustered_tree(), o), ValueError);
}

// Every leaf and crown triangle is wound counter-clockwise about its vertex normals: the normal
// of its corners (b - a) x (c - a) points the way they do. Renderers light the front side along
// the normal and flip it for the back, so a normal against the winding would leave every leaf
// facing away from the light and the viewer (nearly black).
TEST(Foliage, TrianglesAreWoundAboutTheirNormals) {
  for (const FoliageMode mode : {FoliageMode::kLeaves, FoliageMode::kVolumes}) {
    const TriangleMesh mesh = mesh_tree(clustered_tree(), with_foliage(mode));
    std::size_t checked = 0;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
      if (mesh.materials[t] == Material::kBark) continue;
      const auto& tri = mesh.triangles[t];
      const Eigen::Vector3f a = mesh.positions[tri[0]], b = mesh.positions[tri[1]],
                            c = mesh.positions[tri[2]];
      const Eigen::Vector3f face = (b - a).cross(c - a);
      if (face.norm() < 1e-9f) continue;  // a degenerate cell at a pole of a sphere
      const Eigen::Vector3f n = mesh.normals[tri[0]] + mesh.normals[tri[1]] + mesh.normals[tri[2]];
      EXPECT_GT(face.normalized().dot(n.normalized()), 0.5f) << "triangle " << t;
      ++checked;
    }
    EXPECT_GT(checked, 100u);
  }
}

}  // namespace
}  // namespace fspm::graphics
