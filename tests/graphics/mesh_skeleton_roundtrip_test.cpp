// The skeleton of meshes written by fspm's own tree mesher (Pirk 5.2.1 mesh contraction): the
// mesh of a known three-branch tree, written as PLY and OBJ and read back, gives back that tree's
// branches (their number, lengths and radii).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "graphics/mesh_writers.hpp"
#include "graphics/tree_mesher.hpp"
#include "scans/mesh_file.hpp"
#include "stages/mesh_skeleton.hpp"

namespace fspm::graphics {
namespace {

namespace fs = std::filesystem;

// A trunk of 1.2 m (radius 6 cm) forking into two laterals of 0.7 m (radius 3.5 cm) at 40
// degrees from the vertical, each branch cut into internodes of 5 cm as grown trees are.
TreeGraph fork_tree(double* trunk_m, double* lateral_m) {
  *trunk_m = 1.2;
  *lateral_m = 0.7;
  TreeGraph t;
  NodeId last = kNoNode;
  const auto chain = [&t](NodeId parent, Eigen::Vector3d from, const Eigen::Vector3d& dir,
                          double length, double radius) {
    const int n = static_cast<int>(std::lround(length / 0.05));
    for (int k = 0; k < n; ++k) {
      NodeData d;
      d.start = from;
      d.end = from + dir * (length / n);
      d.radius = radius;
      parent = t.add_node(parent, d);
      from = d.end;
    }
    return parent;
  };
  last = chain(kNoNode, {0, 0, 0}, Eigen::Vector3d::UnitZ(), *trunk_m, 0.06);
  const double a = 40.0 * 3.14159265358979 / 180.0;
  chain(last, t.end(last), {std::sin(a), 0, std::cos(a)}, *lateral_m, 0.035);
  chain(last, t.end(last), {-std::sin(a), 0, std::cos(a)}, *lateral_m, 0.035);
  return t;
}

struct Branch {
  double length = 0.0, radius_length = 0.0;  // radius integrated over length
};

std::vector<Branch> branches(const TreeGraph& t) {
  std::vector<Branch> out;
  for (NodeId i = 0; i < t.size(); ++i) {
    const NodeId p = t.parent(i);
    if (p != kNoNode && t.child_count(p) == 1) continue;
    Branch b;
    for (NodeId n = i;; n = t.first_child(n)) {
      b.length += t.length(n);
      b.radius_length += t.radius(n) * t.length(n);
      if (t.child_count(n) != 1) break;
    }
    out.push_back(b);
  }
  return out;
}

void expect_fork(const TreeGraph& skeleton, double trunk_m, double lateral_m) {
  const std::vector<Branch> b = branches(skeleton);
  ASSERT_EQ(b.size(), 3u);
  EXPECT_NEAR(b[0].length, trunk_m, 0.05 * trunk_m);
  EXPECT_NEAR(b[0].radius_length / b[0].length, 0.06, 0.1 * 0.06);
  for (int k = 1; k <= 2; ++k) {
    EXPECT_NEAR(b[k].length, lateral_m, 0.05 * lateral_m);
    EXPECT_NEAR(b[k].radius_length / b[k].length, 0.035, 0.1 * 0.035);
  }
}

class MeshSkeletonRoundTrip : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fspm_mesh_skeleton_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// Separate closed tubes (the default of `fspm mesh`), written and read back in each format.
TEST_P(MeshSkeletonRoundTrip, SeparateTubesGiveTheTreeBack) {
  double trunk = 0, lateral = 0;
  const TreeGraph tree = fork_tree(&trunk, &lateral);
  const std::string path = (dir_ / ("fork." + GetParam())).string();
  write_mesh(mesh_tree(tree), path);
  const scans::GroupedMesh m = scans::read_mesh_file(path);
  const stages::MeshSkeleton s =
      stages::mesh_skeleton(stages::weld_branch_mesh(m.vertices, m.faces));
  expect_fork(s.tree, trunk, lateral);
  EXPECT_NEAR(s.tree.start(0).z(), 0.0, 0.02);
}

INSTANTIATE_TEST_SUITE_P(Formats, MeshSkeletonRoundTrip, ::testing::Values("ply", "obj"));

// One closed surface with knuckles at the fork (Reynolds 3.2).
TEST(MeshSkeleton, ContinuousMeshGivesTheTreeBack) {
  double trunk = 0, lateral = 0;
  const TreeGraph tree = fork_tree(&trunk, &lateral);
  MeshOptions o;
  o.junctions = JunctionMode::kContinuous;
  const TriangleMesh mesh = mesh_tree_continuous(tree, o);
  std::vector<Eigen::Vector3d> v;
  for (const Eigen::Vector3f& p : mesh.positions) v.push_back(p.cast<double>());
  std::vector<std::vector<std::uint32_t>> f;
  for (const auto& t : mesh.triangles) f.push_back({t[0], t[1], t[2]});
  const stages::MeshSkeleton s = stages::mesh_skeleton(stages::weld_branch_mesh(v, f));
  expect_fork(s.tree, trunk, lateral);
}

}  // namespace
}  // namespace fspm::graphics
