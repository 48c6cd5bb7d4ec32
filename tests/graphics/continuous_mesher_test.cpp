#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <bit>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

#include "graphics/tree_mesher.hpp"
#include "tests/graphics/mesh_checks.hpp"
#include "tests/graphics/test_trees.hpp"

namespace fspm::graphics {
namespace {

// Connected components of the bark after welding equal positions.
std::size_t bark_components(const TriangleMesh& mesh) {
  std::map<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>, std::uint32_t> weld;
  std::vector<std::uint32_t> id(mesh.vertex_count());
  for (std::size_t i = 0; i < mesh.vertex_count(); ++i) {
    const auto& p = mesh.positions[i];
    id[i] = weld.emplace(std::make_tuple(std::bit_cast<std::uint32_t>(p.x()),
                                         std::bit_cast<std::uint32_t>(p.y()),
                                         std::bit_cast<std::uint32_t>(p.z())),
                         static_cast<std::uint32_t>(weld.size()))
                .first->second;
  }
  std::vector<std::uint32_t> up(weld.size());
  std::iota(up.begin(), up.end(), 0u);
  auto find = [&](std::uint32_t x) {
    while (up[x] != x) x = up[x] = up[up[x]];
    return x;
  };
  std::vector<char> used(weld.size(), 0);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (mesh.materials[t] != Material::kBark) continue;
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      used[id[tri[k]]] = 1;
      up[find(id[tri[k]])] = find(id[tri[(k + 1) % 3]]);
    }
  }
  std::size_t roots = 0;
  for (std::uint32_t v = 0; v < up.size(); ++v) roots += used[v] && find(v) == v;
  return roots;
}

TEST(ContinuousMesher, OneClosedSurfaceThroughJunctions) {
  const TreeGraph tree = testing::junction_tree();
  MeshOptions o;
  o.junctions = JunctionMode::kContinuous;
  const TriangleMesh mesh = mesh_tree(tree, o);
  testing::expect_valid_mesh(mesh);
  testing::expect_closed_bark(mesh);
  EXPECT_EQ(bark_components(mesh), 1u);
  const auto w0 = mesh.attribute("weight0");
  const auto w1 = mesh.attribute("weight1");
  const auto w2 = mesh.attribute("weight2");
  const auto w3 = mesh.attribute("weight3");
  std::size_t halves = 0;
  for (std::size_t i = 0; i < mesh.vertex_count(); ++i) {
    ASSERT_NEAR(w0[i] + w1[i] + w2[i] + w3[i], 1.0f, 1e-6f);
    halves += w0[i] == 0.5f;
  }
  EXPECT_GT(halves, 0u);  // interior joints are shared by two bones
}

TEST(ContinuousMesher, ReynoldsWidthTapersToTheTip) {
  const TreeGraph tree = testing::junction_tree();
  MeshOptions o;
  o.junctions = JunctionMode::kContinuous;
  o.reynolds_width = true;
  const TriangleMesh mesh = mesh_tree(tree, o);
  testing::expect_valid_mesh(mesh);
  testing::expect_closed_bark(mesh);
  // Expression 1 at the middle of the trunk (t = 0.5): (1 / 2.5 - 0.25) / 0.75 = 0.2 of the root.
  float at_half = 0.0f;
  for (const auto& p : mesh.positions) {
    if (std::abs(p.z() - 2.0f) < 1e-5f && p.head<2>().norm() > at_half)
      at_half = p.head<2>().norm();
  }
  EXPECT_NEAR(at_half, 0.1f * 0.2f, 1e-4f);
}

TEST(ContinuousMesher, BinaryTreeFallsBackToSeparateTubes) {
  // Both children of every fork have a higher order: no axis runs through a fork, so every
  // lateral starts with its own cap and the mesh equals the chain mesher's bark.
  const TreeGraph tree = testing::binary_tree(4, 2);
  MeshOptions o;
  o.junctions = JunctionMode::kContinuous;
  const TriangleMesh mesh = mesh_tree(tree, o);
  testing::expect_valid_mesh(mesh);
  testing::expect_closed_bark(mesh);
  EXPECT_EQ(mesh.triangle_count(), mesh_tree(tree, {}).triangle_count());
}

}  // namespace
}  // namespace fspm::graphics
