// fspm tree convert of a tube mesh written by a tree modeller (examples/trees/ez_tree_branches.obj,
// ez-tree's branches: one tube of rings per branch, no caps), checked against the branch origins
// the generator itself recorded (tests/data/ez_tree_branch_origins.txt).
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "fspm/tree_file.hpp"
#include "tests/cli/run_command.hpp"

namespace fspm {
namespace {

using testing::run_fspm;
using testing::scratch_dir;

struct BranchOrigin {
  Eigen::Vector3d at;
  int level = 0;
  double radius = 0.0;
};

std::vector<BranchOrigin> branch_origins() {
  std::ifstream in(std::string(FSPM_SOURCE_DIR) + "/tests/data/ez_tree_branch_origins.txt");
  std::vector<BranchOrigin> out;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    BranchOrigin b;
    s >> b.at.x() >> b.at.y() >> b.at.z() >> b.level >> b.radius;
    out.push_back(b);
  }
  return out;
}

// Every branch the generator made starts at a node of the skeleton (within 1 cm in the model's
// units, where the trunk is 3 across); every first-level branch starts a branch of higher order
// than its parent within 0.15 (a tenth of the trunk's radius); the base radius is the trunk's
// within 10 %.
TEST(ModellerMesh, EzTreeBranchesConvertToTheirOrigins) {
  const auto dir = scratch_dir("ez_tree");
  const std::string tree = (dir / "ez.tree").string();
  const auto r = run_fspm("tree convert " + std::string(FSPM_SOURCE_DIR) +
                          "/examples/trees/ez_tree_branches.obj " + tree);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const TreeGraph t = read_tree_file(tree);
  const std::vector<BranchOrigin> truth = branch_origins();
  ASSERT_EQ(truth.size(), 457u);
  std::vector<Eigen::Vector3d> ends, forks;
  for (NodeId n = 0; n < t.size(); ++n) {
    ends.push_back(t.start(n));
    ends.push_back(t.end(n));
    const NodeId p = t.parent(n);
    if (p != kNoNode && t.order(n) > t.order(p)) forks.push_back(t.start(n));
  }
  auto nearest = [](const std::vector<Eigen::Vector3d>& set, const Eigen::Vector3d& x) {
    double best = INFINITY;
    for (const Eigen::Vector3d& y : set) best = std::min(best, (y - x).norm());
    return best;
  };
  for (const BranchOrigin& b : truth) {
    EXPECT_LT(nearest(ends, b.at), 0.01) << b.at.transpose();
    if (b.level == 1) {
      EXPECT_LT(nearest(forks, b.at), 0.15) << b.at.transpose();
    }
  }
  ASSERT_GT(t.size(), 0u);
  EXPECT_NEAR(t.radius(0), truth[0].radius, 0.1 * truth[0].radius);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fspm
