// The skeleton of branch meshes by contraction (Pirk 5.2.1, Au et al. 2008) on meshes built here
// whose skeleton is known: a closed cylinder (its axis) and three closed cylinders meeting in a
// Y (three branches of known lengths).
#include "stages/mesh_skeleton.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

#include "fspm/error.hpp"

namespace fspm::stages {
namespace {

constexpr double kPi = std::numbers::pi;

struct Polygons {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::vector<std::uint32_t>> faces;
};

// A closed tube from a to b: `rings` rings of `sides` vertices plus a repeated seam vertex (as
// exporters write it for texture coordinates), quads between rings, and a fan cap at each end
// around a centre vertex whose rim repeats the ring (as for its own normals).
void add_cylinder(Polygons& m, const Eigen::Vector3d& a, const Eigen::Vector3d& b, double r,
                  int rings, int sides) {
  const Eigen::Vector3d axis = (b - a).normalized();
  const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u);
  const auto ring_point = [&](int k, int s) {
    const double phi = 2.0 * kPi * s / sides;
    return Eigen::Vector3d(a + (b - a) * k / (rings - 1.0) +
                           r * (std::cos(phi) * u + std::sin(phi) * v));
  };
  const auto base = static_cast<std::uint32_t>(m.vertices.size());
  for (int k = 0; k < rings; ++k) {
    for (int s = 0; s <= sides; ++s) m.vertices.push_back(ring_point(k, s));
  }
  const auto at = [&](int k, int s) {
    return base + static_cast<std::uint32_t>(k * (sides + 1) + s);
  };
  for (int k = 0; k + 1 < rings; ++k) {
    for (int s = 0; s < sides; ++s)
      m.faces.push_back({at(k, s), at(k, s + 1), at(k + 1, s + 1), at(k + 1, s)});
  }
  for (const int k : {0, rings - 1}) {
    const auto centre = static_cast<std::uint32_t>(m.vertices.size());
    m.vertices.push_back(k == 0 ? a : b);
    for (int s = 0; s <= sides; ++s) m.vertices.push_back(ring_point(k, s));
    for (int s = 0; s < sides; ++s) {
      const std::uint32_t p = centre + 1 + s, q = centre + 2 + s;
      m.faces.push_back(k == 0 ? std::vector<std::uint32_t>{centre, q, p}
                               : std::vector<std::uint32_t>{centre, p, q});
    }
  }
}

double total_length(const TreeGraph& t) {
  double sum = 0.0;
  for (NodeId i = 0; i < t.size(); ++i) sum += t.length(i);
  return sum;
}

// Branches: runs of internodes between the root, branch points and tips, by their lengths.
std::vector<double> branch_lengths(const TreeGraph& t) {
  std::vector<double> out;
  for (NodeId i = 0; i < t.size(); ++i) {
    const NodeId p = t.parent(i);
    if (p != kNoNode && t.child_count(p) == 1) continue;  // not the first of a branch
    double len = 0.0;
    NodeId n = i;
    while (true) {
      len += t.length(n);
      if (t.child_count(n) != 1) break;
      n = t.first_child(n);
    }
    out.push_back(len);
  }
  return out;
}

TEST(MeshSkeleton, ClosedCylinderGivesItsAxis) {
  Polygons m;
  const double length = 1.0, radius = 0.05;
  add_cylinder(m, {0.2, -0.1, 0.0}, {0.2, -0.1, length}, radius, 41, 16);
  const BranchMesh mesh = weld_branch_mesh(m.vertices, m.faces);
  ASSERT_EQ(mesh.vertices.size(), 41u * 16u + 2u);  // seams and cap rims welded
  const MeshSkeleton s = mesh_skeleton(mesh);
  const TreeGraph& t = s.tree;
  ASSERT_GE(t.size(), 5u);
  for (NodeId i = 0; i < t.size(); ++i) {
    EXPECT_LE(t.child_count(i), 1u) << "node " << i;
    EXPECT_NEAR(t.end(i).x(), 0.2, 0.1 * radius);
    EXPECT_NEAR(t.end(i).y(), -0.1, 0.1 * radius);
  }
  EXPECT_NEAR(t.start(0).z(), 0.0, 0.03 * length);  // rooted at the lowest end
  EXPECT_NEAR(total_length(t), length, 0.03 * length);
  double weighted = 0.0;
  for (NodeId i = 0; i < t.size(); ++i) weighted += t.radius(i) * t.length(i);
  EXPECT_NEAR(weighted / total_length(t), radius, 0.1 * radius);
  EXPECT_LT(s.area_ratio, 1e-2);
}

// Three separate closed tubes (as `fspm mesh` writes a tree by default): a trunk of 1 m and two
// laterals of 0.6 m leaving its top at 45 degrees. The skeleton has one branch point and three
// branches of those lengths.
TEST(MeshSkeleton, ThreeTubesInAYGiveThreeBranches) {
  Polygons m;
  const Eigen::Vector3d top(0, 0, 1);
  const double lateral = 0.6, s = lateral / std::sqrt(2.0);
  add_cylinder(m, {0, 0, 0}, top, 0.05, 41, 16);
  add_cylinder(m, top, top + Eigen::Vector3d(s, 0, s), 0.03, 25, 12);
  add_cylinder(m, top, top + Eigen::Vector3d(-s, 0, s), 0.03, 25, 12);
  const MeshSkeleton sk = mesh_skeleton(weld_branch_mesh(m.vertices, m.faces));
  const TreeGraph& t = sk.tree;
  std::size_t tips = 0, forks = 0;
  for (NodeId i = 0; i < t.size(); ++i) {
    tips += t.is_tip(i);
    forks += t.child_count(i) > 1;
  }
  EXPECT_EQ(tips, 2u);
  EXPECT_EQ(forks, 1u);
  const std::vector<double> b = branch_lengths(t);
  ASSERT_EQ(b.size(), 3u);
  EXPECT_NEAR(b[0], 1.0, 0.05);  // the trunk first: breadth first from the root
  EXPECT_NEAR(b[1], lateral, 0.05 * lateral);
  EXPECT_NEAR(b[2], lateral, 0.05 * lateral);
  EXPECT_NEAR(total_length(t), 1.0 + 2 * lateral, 0.03 * (1.0 + 2 * lateral));
}

TEST(MeshSkeleton, RejectsBadInput) {
  EXPECT_THROW(weld_branch_mesh({{0, 0, 0}, {1, 0, 0}}, {{0, 1, 2}}), ValueError);
  EXPECT_THROW(weld_branch_mesh({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}}, {{0, 1, 2}}), ValueError);
  MeshSkeletonParams p;
  p.contraction.contraction_scale = 0.5;
  Polygons m;
  add_cylinder(m, {0, 0, 0}, {0, 0, 1}, 0.1, 5, 6);
  EXPECT_THROW(mesh_skeleton(weld_branch_mesh(m.vertices, m.faces), p), ValueError);
}

}  // namespace
}  // namespace fspm::stages
