// Skeletons of tube meshes as modelling programs export branches (rings of vertices, quads or
// triangle pairs between consecutive rings, no caps): tubes are built here around known axes and
// radii, written as OBJ groups, as a PLY without groups and as glTF nodes, and the skeleton read
// back must find every fork and tip within 5 cm and every radius within 10 % of the known ones.
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>

#include "fspm/error.hpp"
#include "scans/grouped_mesh_skeleton.hpp"
#include "scans/mesh_file.hpp"
#include "scans/ply_reader.hpp"
#include "tests/scans/gltf_test_file.hpp"

namespace fspm::scans {
namespace {

// A known branch: axis points (ring positions) and the radius at each.
struct Axis {
  std::vector<Eigen::Vector3d> points;
  std::vector<double> radii;
};

// Points from a to b (both included) every `step` metres or less, radius linear from ra to rb.
Axis straight(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double ra, double rb,
              double step) {
  const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / step)));
  Axis x;
  for (int i = 0; i <= n; ++i) {
    const double s = static_cast<double>(i) / n;
    x.points.push_back(a + s * (b - a));
    x.radii.push_back(ra + s * (rb - ra));
  }
  return x;
}

struct Tube {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::uint32_t, 4>> quads;  // local indices
};

// Rings of `n` vertices normal to the axis (the tangent by central differences), rotated by
// `phase` so that seams do not line up; quads join consecutive rings; no caps.
Tube tube_of(const Axis& a, int n, double phase) {
  Tube t;
  const std::size_t m = a.points.size();
  for (std::size_t i = 0; i < m; ++i) {
    const Eigen::Vector3d tangent =
        (a.points[std::min(i + 1, m - 1)] - a.points[i == 0 ? 0 : i - 1]).normalized();
    const Eigen::Vector3d u = tangent.unitOrthogonal(), v = tangent.cross(u);
    for (int j = 0; j < n; ++j) {
      const double th = phase + 2.0 * std::numbers::pi * j / n;
      t.vertices.push_back(a.points[i] + a.radii[i] * (std::cos(th) * u + std::sin(th) * v));
    }
  }
  for (std::size_t i = 0; i + 1 < m; ++i) {
    for (int j = 0; j < n; ++j) {
      const auto at = [n](std::size_t ring, int k) {
        return static_cast<std::uint32_t>(ring * n + (k % n));
      };
      t.quads.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)});
    }
  }
  return t;
}

std::string obj_of(const std::vector<Axis>& axes) {
  std::ostringstream obj;
  obj.precision(10);
  std::uint32_t first = 1;
  for (std::size_t b = 0; b < axes.size(); ++b) {
    const Tube t = tube_of(axes[b], b == 0 ? 16 : 8, 0.3 * b);
    obj << "g Branch_" << b << '\n';
    for (const Eigen::Vector3d& p : t.vertices) obj << "v " << p.transpose() << '\n';
    for (const auto& q : t.quads) {
      obj << "f " << first + q[0] << ' ' << first + q[1] << ' ' << first + q[2] << ' '
          << first + q[3] << '\n';
    }
    first += static_cast<std::uint32_t>(t.vertices.size());
  }
  return obj.str();
}

// One PLY, no groups: each tube is a connected piece, split into triangles.
std::string ply_of(const std::vector<Axis>& axes) {
  std::vector<Eigen::Vector3d> v;
  std::vector<std::array<std::uint32_t, 3>> f;
  for (std::size_t b = 0; b < axes.size(); ++b) {
    const Tube t = tube_of(axes[b], b == 0 ? 12 : 10, 0.7 * b);
    const auto first = static_cast<std::uint32_t>(v.size());
    v.insert(v.end(), t.vertices.begin(), t.vertices.end());
    for (const auto& q : t.quads) {
      f.push_back({first + q[0], first + q[1], first + q[2]});
      f.push_back({first + q[0], first + q[2], first + q[3]});
    }
  }
  std::ostringstream ply;
  ply.precision(10);
  ply << "ply\nformat ascii 1.0\nelement vertex " << v.size()
      << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << f.size()
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const Eigen::Vector3d& p : v) ply << p.transpose() << '\n';
  for (const auto& t : f) ply << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  return ply.str();
}

std::vector<test::GltfPart> gltf_of(const std::vector<Axis>& axes) {
  std::vector<test::GltfPart> parts;
  for (std::size_t b = 0; b < axes.size(); ++b) {
    const Tube t = tube_of(axes[b], 8, 0.5 * b);
    test::GltfPart p{"branch" + std::to_string(b), "mesh" + std::to_string(b), {}, {}};
    for (const Eigen::Vector3d& q : t.vertices) {
      for (int k = 0; k < 3; ++k) p.positions.push_back(static_cast<float>(q[k]));
    }
    for (const auto& q : t.quads)
      p.indices.insert(p.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
    parts.push_back(std::move(p));
  }
  return parts;
}

// The known radius at point p: linear along the nearest segment of the nearest axis.
double known_radius(const std::vector<Axis>& axes, const Eigen::Vector3d& p) {
  double best = 1e30, r = 0.0;
  for (const Axis& a : axes) {
    for (std::size_t i = 0; i + 1 < a.points.size(); ++i) {
      const Eigen::Vector3d d = a.points[i + 1] - a.points[i];
      const double s = std::clamp((p - a.points[i]).dot(d) / d.squaredNorm(), 0.0, 1.0);
      const double dist = (a.points[i] + s * d - p).norm();
      if (dist < best) best = dist, r = a.radii[i] + s * (a.radii[i + 1] - a.radii[i]);
    }
  }
  return r;
}

// Every known branch (after the trunk) has a tip within 5 cm of its last point, and walking
// down from that tip, the first node of its order starts within 5 cm of its fork (its first
// point); the trunk starts at its first point; every node's radius is within 10 % of the known
// radius at its midpoint; the skeleton has as many tips as the known tree.
void expect_skeleton(const TreeGraph& t, const std::vector<Axis>& axes, std::size_t tips) {
  ASSERT_GT(t.size(), 0u);
  EXPECT_LT((t.start(0) - axes[0].points.front()).norm(), 0.05) << t.start(0).transpose();
  EXPECT_EQ(t.order(0), 0);
  std::vector<NodeId> tip_nodes;
  for (NodeId i = 0; i < t.size(); ++i) {
    if (t.children(i).empty()) tip_nodes.push_back(i);
    const Eigen::Vector3d mid = 0.5 * (t.start(i) + t.end(i));
    const double r = known_radius(axes, mid);
    EXPECT_NEAR(t.radius(i), r, 0.1 * r) << "node " << i << " at " << mid.transpose();
  }
  EXPECT_EQ(tip_nodes.size(), tips);
  for (std::size_t b = 1; b < axes.size(); ++b) {
    NodeId tip = kNoNode;
    for (NodeId i : tip_nodes) {
      if ((t.end(i) - axes[b].points.back()).norm() < 0.05) tip = i;
    }
    ASSERT_NE(tip, kNoNode) << "no tip near branch " << b << "'s " << axes[b].points.back();
    NodeId first = tip;
    while (t.parent(first) != kNoNode && t.order(t.parent(first)) == t.order(tip)) {
      first = t.parent(first);
    }
    EXPECT_LT((t.start(first) - axes[b].points.front()).norm(), 0.05)
        << "branch " << b << " forks at " << t.start(first).transpose();
  }
}

// A Y: a trunk to 2 m that forks into two branches, one of them bent.
std::vector<Axis> y_tree() {
  const Eigen::Vector3d fork(0.0, 0.0, 2.0);
  Axis bent = straight(fork, {0.5, 0.1, 2.6}, 0.08, 0.06, 0.15);
  const Axis rest = straight({0.5, 0.1, 2.6}, {0.7, 0.5, 3.4}, 0.06, 0.03, 0.15);
  bent.points.insert(bent.points.end(), rest.points.begin() + 1, rest.points.end());
  bent.radii.insert(bent.radii.end(), rest.radii.begin() + 1, rest.radii.end());
  return {straight({0, 0, 0}, fork, 0.15, 0.12, 0.25), bent,
          straight(fork, {-0.6, 0.3, 3.0}, 0.07, 0.04, 0.2)};
}

// A trunk to 4 m with a branch at 1.5 m (between the trunk's rings, 0.6 m apart) and a branch
// on that branch, half-way between two of its rings.
std::vector<Axis> branch_on_branch() {
  const Axis trunk = straight({0, 0, 0}, {0, 0, 4.0}, 0.2, 0.08, 0.6);
  const Axis b1 = straight({0, 0, 1.5}, {1.2, 0, 2.7}, 0.09, 0.04, 0.3);
  const Eigen::Vector3d fork = b1.points[2] + 0.45 * (b1.points[3] - b1.points[2]);
  const Axis b2 = straight(fork, fork + Eigen::Vector3d(0.1, 0.7, 0.5), 0.04, 0.02, 0.2);
  return {trunk, b1, b2};
}

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("fspm_tube_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

TEST(TubeMeshSkeleton, YTreeFromObjGroups) {
  const std::vector<Axis> y = y_tree();
  std::size_t not_tubes = 99;
  const TreeGraph t =
      grouped_mesh_skeleton(parse_obj_mesh(obj_of(y), "y.obj"), "y.obj", &not_tubes);
  EXPECT_EQ(not_tubes, 0u);
  expect_skeleton(t, y, 2);
}

TEST(TubeMeshSkeleton, BranchOnBranchFromObjGroups) {
  const std::vector<Axis> b = branch_on_branch();
  const TreeGraph t = grouped_mesh_skeleton(parse_obj_mesh(obj_of(b), "b.obj"), "b.obj");
  expect_skeleton(t, b, 3);
  // Orders: trunk 0, its branch 1, the branch on it 2.
  int deepest = 0;
  for (NodeId i = 0; i < t.size(); ++i) deepest = std::max<int>(deepest, t.order(i));
  EXPECT_EQ(deepest, 2);
}

TEST(TubeMeshSkeleton, PiecesOfAPlyWithoutGroups) {
  for (const std::vector<Axis>& axes : {y_tree(), branch_on_branch()}) {
    const TreeGraph t = grouped_mesh_skeleton(parse_ply_mesh(ply_of(axes), "t.ply"), "t.ply");
    expect_skeleton(t, axes, axes.size() == 3 && axes[0].points.back().z() > 3.0 ? 3 : 2);
  }
}

TEST(TubeMeshSkeleton, GltfNodes) {
  const std::vector<Axis> b = branch_on_branch();
  const std::string glb = temp_path("tubes.glb");
  test::write_glb(glb, gltf_of(b));
  const TreeGraph t = grouped_mesh_skeleton(read_mesh_file(glb), glb);
  std::filesystem::remove(glb);
  expect_skeleton(t, b, 3);
}

// Groups listed tip first and tubes written from their far end: the skeleton does not depend
// on the file's order or on the rings' direction.
TEST(TubeMeshSkeleton, OrderAndDirectionOfTubesDoNotMatter) {
  std::vector<Axis> b = branch_on_branch();
  std::vector<Axis> shuffled{b[2], b[0], b[1]};
  for (Axis& a : shuffled) {
    std::reverse(a.points.begin(), a.points.end());
    std::reverse(a.radii.begin(), a.radii.end());
  }
  const TreeGraph t = grouped_mesh_skeleton(parse_obj_mesh(obj_of(shuffled), "s.obj"), "s.obj");
  expect_skeleton(t, b, 3);
}

// A branch modelled from the trunk's surface, as SpeedTree and Xfrog start laterals: its first
// ring lies 0.21 m along its axis from where that axis meets the trunk's (at 45 degrees to a trunk
// of radius 0.15 m). The fork is that meeting point, not the trunk point nearest the first ring
// (0.15 m higher).
TEST(TubeMeshSkeleton, BranchFromTheParentsSurfaceForksOnTheAxis) {
  const Eigen::Vector3d fork(0, 0, 1.5), d = Eigen::Vector3d(1, 0, 1).normalized();
  const std::vector<Axis> axes{
      straight({0, 0, 0}, {0, 0, 3.0}, 0.15, 0.1, 0.3),
      straight(fork + 0.15 * std::sqrt(2.0) * d, fork + 1.2 * d, 0.05, 0.03, 0.2)};
  const TreeGraph t = grouped_mesh_skeleton(parse_obj_mesh(obj_of(axes), "s.obj"), "s.obj");
  NodeId first = kNoNode, tip = kNoNode;
  for (NodeId i = 0; i < t.size(); ++i) {
    if (t.order(i) == 1 && t.order(t.parent(i)) == 0) first = i;
    if (t.order(i) == 1 && t.children(i).empty()) tip = i;
  }
  ASSERT_NE(first, kNoNode);
  ASSERT_NE(tip, kNoNode);
  EXPECT_LT((t.start(first) - fork).norm(), 0.05) << t.start(first).transpose();
  EXPECT_LT((t.end(tip) - (fork + 1.2 * d)).norm(), 0.05) << t.end(tip).transpose();
}

TEST(TubeMeshSkeleton, APointSetIsNoMesh) {
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
  try {
    grouped_mesh_skeleton(parse_ply_mesh(ply, "p.ply"), "p.ply");
    FAIL() << "no error";
  } catch (const ValueError& e) {
    EXPECT_NE(std::string(e.what()).find("fspm encode"), std::string::npos) << e.what();
  }
}

// Tubes closed by caps (a polygon, or a fan of triangles around a centre vertex) and a flat leaf
// card beside them: the same skeleton, the card counted as no tube.
TEST(TubeMeshSkeleton, CapsAndLeafCards) {
  const std::vector<Axis> y = y_tree();
  std::string obj = obj_of(y);
  std::size_t vertices = 0;
  for (std::size_t p = obj.find("\nv "); p != std::string::npos; p = obj.find("\nv ", p + 1)) {
    ++vertices;
  }
  std::ostringstream more;
  // The trunk (group Branch_0, 16 vertices a ring, first in the file): a 16-gon at its base and
  // a fan around a centre vertex at its top.
  more << "g Branch_0\nf";
  for (int j = 16; j >= 1; --j) more << ' ' << j;
  const std::size_t top = y[0].points.size() - 1;
  more << "\nv " << y[0].points[top].transpose() << '\n';
  const std::size_t centre = vertices + 1;
  for (int j = 0; j < 16; ++j) {
    more << "f " << centre << ' ' << top * 16 + 1 + j << ' ' << top * 16 + 1 + (j + 1) % 16 << '\n';
  }
  more << "g Leaf\nv 1 1 1\nv 1.1 1 1\nv 1.1 1.05 1.1\nv 1 1.05 1.1\nf -4 -3 -2 -1\n";
  obj += more.str();
  std::size_t not_tubes = 0;
  const TreeGraph t = grouped_mesh_skeleton(parse_obj_mesh(obj, "c.obj"), "c.obj", &not_tubes);
  EXPECT_EQ(not_tubes, 1u);
  expect_skeleton(t, y, 2);
}

}  // namespace
}  // namespace fspm::scans
