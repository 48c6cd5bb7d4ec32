#include "graphics/tree_mesher.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "fspm/error.hpp"
#include "tests/graphics/mesh_checks.hpp"
#include "tests/graphics/test_trees.hpp"

namespace fspm::graphics {
namespace {

using testing::binary_tree;
using testing::small_tree;

// Closed form per tube of m segments and s sides, with caps: (m+1)(s+1) ring vertices plus
// two caps of s+1; 2ms wall triangles plus 2s cap triangles.
std::size_t tube_vertices(std::size_t m, std::size_t s) { return (m + 1) * (s + 1) + 2 * (s + 1); }
std::size_t tube_triangles(std::size_t m, std::size_t s) { return 2 * m * s + 2 * s; }

// Junction modes and materials by the names the command line, scene files and Python use.
TEST(MeshNames, JunctionModesAndMaterialsRoundTripTheirNames) {
  for (JunctionMode m : {JunctionMode::kSeparate, JunctionMode::kContinuous}) {
    EXPECT_EQ(junction_mode_from_name(junction_mode_name(m)), m);
  }
  EXPECT_THROW(junction_mode_from_name("smooth"), ValueError);
  for (Material m : kMaterials) EXPECT_EQ(material_from_name(material_name(m)), m);
  EXPECT_FALSE(find_material("marble").has_value());
  try {
    material_from_name("marble");
    FAIL() << "expected ValueError";
  } catch (const ValueError& e) {
    EXPECT_NE(std::string(e.what()).find("terrain"), std::string::npos) << e.what();
  }
}

TEST(SidesForRadius, ClampsCircumferenceOverEdge) {
  MeshOptions o;
  o.edge_length_m = 0.01;
  EXPECT_EQ(sides_for_radius(0.05, o), 16);       // ceil(31.4) clamped to 16
  EXPECT_EQ(sides_for_radius(0.01, o), 7);        // ceil(6.28)
  EXPECT_EQ(sides_for_radius(0.0001, o), 3);      // ceil(0.06) raised to 3
  EXPECT_EQ(sides_for_radius(0.01, o, 50.0), 3);  // 10x coarser at 10x the LOD distance
}

TEST(TreeMesher, SmallTreeCountsMatchClosedForm) {
  const TreeGraph tree = small_tree();
  MeshOptions o;
  // Trunk: 3 segments, r 0.05 -> 16 sides; two branches: 2 segments, r 0.01 -> 7 sides.
  const std::size_t nv = tube_vertices(3, 16) + 2 * tube_vertices(2, 7);
  const std::size_t nt = tube_triangles(3, 16) + 2 * tube_triangles(2, 7);
  EXPECT_EQ(nv, 182u);
  EXPECT_EQ(nt, 212u);
  TriangleMesh mesh = mesh_tree(tree, o);
  EXPECT_EQ(mesh.vertex_count(), nv);
  EXPECT_EQ(mesh.triangle_count(), nt);
  testing::expect_valid_mesh(mesh);
  testing::expect_closed_bark(mesh);

  o.leaves = true;  // three flat quads: 4 vertices, 2 triangles each
  mesh = mesh_tree(tree, o);
  EXPECT_EQ(mesh.vertex_count(), nv + 12);
  EXPECT_EQ(mesh.triangle_count(), nt + 6);
  EXPECT_EQ(mesh.triangle_count(Material::kLeaf), 6u);
  const MeshCounts c = count_mesh(tree, o);
  EXPECT_EQ(c.vertices, mesh.vertex_count());
  EXPECT_EQ(c.triangles, mesh.triangle_count());
  EXPECT_EQ(c.tubes, 3u);
  EXPECT_EQ(c.leaves, 3u);
  testing::expect_valid_mesh(mesh);
  testing::expect_closed_bark(mesh);
  // Bark first, then leaves.
  EXPECT_TRUE(std::is_sorted(mesh.materials.begin(), mesh.materials.end()));
}

TEST(TreeMesher, BinaryTreeCountsMatchClosedForm) {
  const int depth = 5, segments = 3;
  const TreeGraph tree = binary_tree(depth, segments);
  const MeshOptions o;
  std::size_t nv = 0, nt = 0;
  for (int level = 0; level < depth; ++level) {
    const double r = 0.05 * std::pow(0.7, level);
    const auto s =
        static_cast<std::size_t>(std::clamp(std::ceil(2 * M_PI * r / o.edge_length_m), 3.0, 16.0));
    nv += (std::size_t{1} << level) * tube_vertices(segments, s);
    nt += (std::size_t{1} << level) * tube_triangles(segments, s);
  }
  const TriangleMesh mesh = mesh_tree(tree, o);
  EXPECT_EQ(mesh.vertex_count(), nv);
  EXPECT_EQ(mesh.triangle_count(), nt);
  testing::expect_valid_mesh(mesh);
  testing::expect_closed_bark(mesh);
}

TEST(TreeMesher, AttributesCarriedToVertices) {
  const TreeGraph tree = small_tree();
  MeshOptions o;
  o.leaves = true;
  const TriangleMesh mesh = mesh_tree(tree, o);
  for (const char* name : {"age", "birth_time", "order", "physiological_age", "light"}) {
    EXPECT_TRUE(mesh.has_attribute(name)) << name;
  }
  const auto light = mesh.attribute("light");
  const auto order = mesh.attribute("order");
  const auto age = mesh.attribute("age");
  std::set<float> leaf_light, leaf_order;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (mesh.materials[t] != Material::kLeaf) continue;
    for (auto v : mesh.triangles[t]) {
      leaf_light.insert(light[v]);
      leaf_order.insert(order[v]);
    }
  }
  // Leaves are nodes 2, 6 and 9 (light = 10 * id), orders 1, 2, 2.
  EXPECT_EQ(leaf_light, (std::set<float>{20.0f, 60.0f, 90.0f}));
  EXPECT_EQ(leaf_order, (std::set<float>{1.0f, 2.0f}));
  // Vertex 0 is on the trunk's base ring: node 0, born at 0; ages count from the latest birth 4.5.
  EXPECT_FLOAT_EQ(light[0], 0.0f);
  EXPECT_FLOAT_EQ(age[0], 4.5f);
  EXPECT_THROW(mesh.attribute("nope"), ValueError);
}

// The viewer culls the bark's back faces, which needs closed tubes wound counter-clockwise seen
// from outside: every bark edge (by position) is shared by exactly two bark triangles, every
// triangle's winding agrees with its vertex normals, and the enclosed volume (divergence
// theorem) is that of the tubes, positive: sum over the chains of pi r^2 L with the rings'
// inscribed polygons, so between 0.9 and 1.0 of it with 16 sides.
TEST(TreeMesher, BarkTubesAreClosedAndWoundOutwards) {
  constexpr double kPi = 3.141592653589793;
  MeshOptions o;
  o.min_sides = o.max_sides = 16;
  const TriangleMesh m = mesh_tree(testing::small_tree(), o);
  std::map<std::pair<std::array<long, 3>, std::array<long, 3>>, int> edges;
  const auto key = [&](std::uint32_t v) {
    const Eigen::Vector3f& p = m.positions[v];
    return std::array<long, 3>{std::lround(p.x() * 1e5), std::lround(p.y() * 1e5),
                               std::lround(p.z() * 1e5)};
  };
  double volume = 0.0;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    if (m.materials[t] != Material::kBark) continue;
    const auto& tri = m.triangles[t];
    const Eigen::Vector3f a = m.positions[tri[0]], b = m.positions[tri[1]], c = m.positions[tri[2]];
    const Eigen::Vector3f n = (b - a).cross(c - a);
    if (n.norm() < 1e-12f) continue;  // degenerate (a cap's centre on a zero-length side)
    EXPECT_GT(n.dot(m.normals[tri[0]] + m.normals[tri[1]] + m.normals[tri[2]]), 0.0f) << t;
    volume += a.dot(b.cross(c)) / 6.0;
    for (int k = 0; k < 3; ++k) {
      auto e = std::make_pair(key(tri[k]), key(tri[(k + 1) % 3]));
      if (e.second < e.first) std::swap(e.first, e.second);
      ++edges[e];
    }
  }
  for (const auto& [edge, count] : edges) EXPECT_EQ(count, 2);
  // small_tree: a trunk of three internodes of radius 0.05 (lengths 1, about 1.005 and 1.005),
  // two branches of two internodes of radius 0.01 (lengths about 0.707 and 0.574).
  const double trunk = kPi * 0.05 * 0.05 * (1.0 + 2.0 * std::sqrt(1.0 + 0.01));
  const double branches =
      2.0 * kPi * 0.01 * 0.01 * (std::sqrt(0.5) + std::sqrt(0.16 + 0.01 + 0.16));
  EXPECT_GT(volume, 0.9 * (trunk + branches));
  EXPECT_LT(volume, 1.0 * (trunk + branches));
}

// B-spline refinement of the axis (Pirk eq. 6.7): a chain of three internodes bent by 45 and 90
// degrees, meshed with 4 rings per internode. Ring centres (the mean of a ring's distinct
// vertices) against the closed forms of eq. 6.7: at the chain's ends the end points themselves
// (reflected phantom points), at the inner joints (P_{i-1} + 4 P_i + P_{i+1}) / 6; the counts
// follow; the turn between consecutive rings is spread over the rings, far below the joints'.
TEST(TreeMesher, AxisSubdivisionsRoundTheChainThroughBSplineRings) {
  TreeGraph t;
  const std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {0, 0, 1}, {0.5, 0, 1.5}, {1.0, 0, 1.5}};
  NodeId parent = kNoNode;
  for (int i = 0; i < 3; ++i) parent = testing::add(t, parent, p[i], p[i + 1], 0.05, i, 0);
  MeshOptions o;
  o.min_sides = o.max_sides = 8;
  o.axis_subdivisions = 4;
  const TriangleMesh m = mesh_tree(t, o);
  constexpr int kSides = 8, kRings = 3 * 4 + 1;
  ASSERT_EQ(m.vertex_count(), static_cast<std::size_t>((kRings + 2) * (kSides + 1)));
  ASSERT_EQ(m.triangle_count(), static_cast<std::size_t>(2 * 3 * 4 * kSides + 2 * kSides));
  std::vector<Eigen::Vector3d> centres(kRings, Eigen::Vector3d::Zero());
  for (int r = 0; r < kRings; ++r) {
    for (int k = 0; k < kSides; ++k) centres[r] += m.positions[r * (kSides + 1) + k].cast<double>();
    centres[r] /= kSides;
  }
  EXPECT_LT((centres.front() - p[0]).norm(), 1e-5);
  EXPECT_LT((centres.back() - p[3]).norm(), 1e-5);
  for (int i = 1; i <= 2; ++i) {
    const Eigen::Vector3d joint = (p[i - 1] + 4.0 * p[i] + p[i + 1]) / 6.0;
    EXPECT_LT((centres[4 * i] - joint).norm(), 1e-5) << i;
  }
  double largest_turn = 0.0;
  for (int r = 1; r + 1 < kRings; ++r) {
    const Eigen::Vector3d a = (centres[r] - centres[r - 1]).normalized();
    const Eigen::Vector3d b = (centres[r + 1] - centres[r]).normalized();
    largest_turn = std::max(largest_turn, std::acos(std::clamp(a.dot(b), -1.0, 1.0)));
  }
  EXPECT_LT(largest_turn, 0.5 * 0.7853981633974483);  // half the smaller joint's 45 degrees
  o.axis_subdivisions = 0;
  EXPECT_THROW(mesh_tree(t, o), ValueError);
  o.axis_subdivisions = 2;
  o.junctions = JunctionMode::kContinuous;
  EXPECT_THROW(mesh_tree(t, o), ValueError);
}

TEST(TreeMesher, BirthTimeFilterKeepsOlderNodes) {
  const TreeGraph tree = small_tree();
  MeshOptions o;
  o.leaves = true;
  o.max_birth_time = 2.5;  // trunk (born 0, 1, 2) and its leaf (1.5) only
  const TriangleMesh mesh = mesh_tree(tree, o);
  EXPECT_EQ(mesh.vertex_count(), tube_vertices(3, 16) + 4);
  EXPECT_EQ(mesh.triangle_count(), tube_triangles(3, 16) + 2);
  EXPECT_FLOAT_EQ(mesh.attribute("age")[0], 2.5f);
  o.max_birth_time = -1.0;
  EXPECT_TRUE(mesh_tree(tree, o).empty());
}

TEST(TreeMesher, StraightChainHasNoTwist) {
  TreeGraph t;
  NodeId p = kNoNode;
  for (int i = 0; i < 4; ++i) {
    p = testing::add(t, p, Eigen::Vector3d(0, 0, i), Eigen::Vector3d(0, 0, i + 1), 0.1, i, 0);
  }
  MeshOptions o;
  o.caps = false;
  const TriangleMesh mesh = mesh_tree(t, o);
  const std::size_t ring = 17;  // 16 sides + seam
  ASSERT_EQ(mesh.vertex_count(), 5 * ring);
  for (std::size_t j = 1; j < 5; ++j) {
    for (std::size_t k = 0; k < ring; ++k) {
      const Eigen::Vector3f d = mesh.positions[j * ring + k] - mesh.positions[(j - 1) * ring + k];
      EXPECT_NEAR(d.x(), 0.0f, 1e-6f);
      EXPECT_NEAR(d.y(), 0.0f, 1e-6f);
      EXPECT_NEAR(d.z(), 1.0f, 1e-6f);
    }
  }
  // Ring points lie at the radius from the axis.
  for (const auto& q : mesh.positions) EXPECT_NEAR(q.head<2>().norm(), 0.1f, 1e-6f);
}

TEST(TreeMesher, CameraDistanceCoarsens) {
  const TreeGraph tree = small_tree();
  MeshOptions o;
  o.camera_m = Eigen::Vector3d(0, -1000, 0);
  const TriangleMesh far = mesh_tree(tree, o);
  EXPECT_EQ(far.triangle_count(), tube_triangles(3, 3) + 2 * tube_triangles(2, 3));
  testing::expect_valid_mesh(far);
}

TEST(TreeMesher, BentLeaves) {
  const TreeGraph tree = small_tree();
  MeshOptions o;
  o.leaves = true;
  o.leaf_bend = 0.3;
  o.leaf_bend_segments = 4;
  const TriangleMesh mesh = mesh_tree(tree, o);
  EXPECT_EQ(mesh.triangle_count(Material::kLeaf), 3u * 8u);
  testing::expect_valid_mesh(mesh);
  // The tips droop: the lowest leaf vertex of a bent blade is below the flat one.
  o.leaf_bend = 0.0;
  const TriangleMesh flat = mesh_tree(tree, o);
  EXPECT_LT(mesh.bbox_min().z(), flat.bbox_min().z() + 1e-6f);
}

TEST(TreeMesher, ZeroRadiusAndZeroLengthNodesStayValid) {
  TreeGraph t;
  const NodeId a = testing::add(t, kNoNode, {0, 0, 0}, {0, 0, 1}, 0.0, 0, 0);
  const NodeId b = testing::add(t, a, {0, 0, 1}, {0, 0, 1}, 0.02, 1, 0);  // zero length
  testing::add(t, b, {0, 0, 1}, {0, 1, 2}, 0.02, 2, 0);
  const TriangleMesh mesh = mesh_tree(t, {});
  // One tube of two non-empty segments, 3 sides from the minimum radius.
  EXPECT_EQ(mesh.triangle_count(), tube_triangles(2, 3));
  testing::expect_valid_mesh(mesh);
  testing::expect_closed_bark(mesh);
}

TEST(TreeMesher, EmptyTreeAndBadOptions) {
  EXPECT_TRUE(mesh_tree(TreeGraph{}, {}).empty());
  MeshOptions o;
  o.min_sides = 2;
  EXPECT_THROW(mesh_tree(small_tree(), o), ValueError);
  o = {};
  o.edge_length_m = 0.0;
  EXPECT_THROW(count_mesh(small_tree(), o), ValueError);
}

}  // namespace
}  // namespace fspm::graphics
