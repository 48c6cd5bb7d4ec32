// The viewer's wind against the closed form of a lean: with bias 1 the wind model leans every
// joint by its amplitude at all times (wind_animation.hpp), so a one-internode tree is its rest
// mesh turned rigidly about the internode's base, across the wind, by amplitude x strength.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "graphics/skeleton_skin.hpp"
#include "graphics/tree_mesher.hpp"
#include "graphics/viewer_wind.hpp"
#include "tests/graphics/test_trees.hpp"

namespace fspm::graphics {
namespace {

ViewerWind one_internode_in_wind() {
  TreeGraph tree;
  testing::add(tree, kNoNode, {0, 0, 0}, {0, 0, 2}, 0.05, 0, 0);
  ViewerWind w;
  MeshOptions o;
  o.junctions = JunctionMode::kContinuous;  // the mesh that carries bone weights
  w.mesh = mesh_tree(tree, o);
  w.skin = skin_mesh(tree, w.mesh);
  w.wind.bias = 1.0;
  w.wind.amplitude_rad = 0.1;
  w.wind.direction = {1.0, 0.0, 0.0};
  return w;
}

TEST(ViewerWind, LeansTheTreeDownwindByAmplitudeTimesStrength) {
  const ViewerWind w = one_internode_in_wind();
  std::vector<Eigen::Vector3f> positions, normals;
  for (const double strength : {0.0, 1.0, 2.5}) {
    for (const double t_s : {0.0, 0.7, 3.1}) {
      w.pose(t_s, strength, positions, normals);
      ASSERT_EQ(positions.size(), w.mesh.vertex_count());
      // Wind along +x: the axis up x wind is +y, and a positive turn about it takes the top
      // towards +x, downwind.
      const Eigen::AngleAxisf lean(static_cast<float>(0.1 * strength), Eigen::Vector3f::UnitY());
      for (std::size_t v = 0; v < positions.size(); ++v) {
        const Eigen::Vector3f expected = lean * w.mesh.positions[v];
        EXPECT_LT((positions[v] - expected).norm(), 1e-4f)
            << "strength " << strength << ", t " << t_s << ", vertex " << v;
        EXPECT_LT((normals[v] - lean * w.mesh.normals[v]).norm(), 1e-4f);
      }
    }
  }
}

TEST(ViewerWind, SwaysWithTimeWithoutALeanOfItsOwn) {
  ViewerWind w = one_internode_in_wind();
  w.wind.bias = 0.0;  // a pure sway: the top moves back and forth over time
  std::vector<Eigen::Vector3f> a, b, normals;
  w.pose(0.3, 1.0, a, normals);
  w.pose(1.1, 1.0, b, normals);
  float moved = 0.0f;
  for (std::size_t v = 0; v < a.size(); ++v) moved = std::max(moved, (a[v] - b[v]).norm());
  EXPECT_GT(moved, 1e-3f);
  // Never further than the amplitude lets it: a vertex at most 2 m up turns by at most 0.1 rad.
  for (std::size_t v = 0; v < a.size(); ++v) {
    EXPECT_LE((a[v] - w.mesh.positions[v]).norm(), 0.1f * w.mesh.positions[v].norm() + 1e-4f);
  }
}

}  // namespace
}  // namespace fspm::graphics
