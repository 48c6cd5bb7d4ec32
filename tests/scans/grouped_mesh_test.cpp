// Skeleton of a grouped OBJ mesh (Reynolds et al. 2011, 3.1) on hand-built square cross-sections.
#include <gtest/gtest.h>

#include <sstream>

#include "fspm/error.hpp"
#include "scans/grouped_mesh_skeleton.hpp"

namespace fspm::scans {
namespace {

// A square cross-section of side w centred at c, normal to z, as OBJ lines.
void square(std::ostringstream& obj, int& next_vertex, const Eigen::Vector3d& c, double w) {
  const double h = w / 2;
  for (const auto& [dx, dy] : {std::pair{-h, -h}, {h, -h}, {h, h}, {-h, h}}) {
    obj << "v " << c.x() + dx << ' ' << c.y() + dy << ' ' << c.z() << '\n';
  }
  obj << "f " << next_vertex << ' ' << next_vertex + 1 << ' ' << next_vertex + 2 << ' '
      << next_vertex + 3 << '\n';
  next_vertex += 4;
}

TEST(GroupedMeshSkeleton, TrunkAndTwoBranchesByLevelName) {
  std::ostringstream obj;
  int v = 1;
  obj << "g Trunk1\n";
  for (int k = 0; k <= 4; ++k) square(obj, v, {0, 0, k * 1.0}, 0.4);
  obj << "g Branch1\n";  // starts near the trunk's point at z = 2
  for (int k = 1; k <= 3; ++k) square(obj, v, {0.5 * k, 0, 2.0 + 0.3 * k}, 0.1);
  obj << "g Branch2\n";  // near z = 3
  for (int k = 1; k <= 2; ++k) square(obj, v, {0, -0.5 * k, 2.9 + 0.5 * k}, 0.1);
  const TreeGraph t = grouped_mesh_skeleton(parse_obj_mesh(obj.str(), "m.obj"), "m.obj");
  ASSERT_EQ(t.size(), 4u + 3u + 2u);
  EXPECT_EQ(group_level_name("Branch17"), "Branch");
  // Trunk: four bones between five midpoints, radius half the side (inscribed).
  EXPECT_TRUE(t.end(3).isApprox(Eigen::Vector3d(0, 0, 4)));
  EXPECT_NEAR(t.radius(0), 0.2, 1e-12);
  // Branch1 hangs at the trunk node ending at z = 2 (id 1), Branch2 at z = 3 (id 2).
  EXPECT_EQ(t.parent(4), 1u);
  EXPECT_TRUE(t.start(4).isApprox(Eigen::Vector3d(0, 0, 2)));
  EXPECT_EQ(t.parent(7), 2u);
  EXPECT_EQ(t.order(7), 1);
  EXPECT_NEAR(t.radius(8), 0.05, 1e-12);
}

TEST(GroupedMeshSkeleton, RefusesTwoTrunks) {
  std::ostringstream obj;
  int v = 1;
  obj << "g Trunk1\n";
  square(obj, v, {0, 0, 0}, 0.4);
  square(obj, v, {0, 0, 1}, 0.4);
  obj << "g Trunk2\n";
  square(obj, v, {1, 0, 0}, 0.4);
  square(obj, v, {1, 0, 1}, 0.4);
  EXPECT_THROW(grouped_mesh_skeleton(parse_obj_mesh(obj.str(), "m.obj"), "m.obj"), ValueError);
}

}  // namespace
}  // namespace fspm::scans
