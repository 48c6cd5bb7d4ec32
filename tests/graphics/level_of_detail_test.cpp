// CPU level of detail: Reynolds' expression 2, Pirk's B-spline refinement (eq. 6.6-6.7) against
// the closed-form basis, frustum culling against a brute-force point test, stochastic pruning.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <set>

#include "fspm/error.hpp"
#include "graphics/bspline_refinement.hpp"
#include "graphics/frustum_culling.hpp"
#include "graphics/stochastic_pruning.hpp"
#include "graphics/tessellation_level.hpp"
#include "graphics/tree_mesher.hpp"
#include "tests/graphics/test_trees.hpp"

namespace fspm::graphics {
namespace {

TEST(TessellationLevel, FollowsReynoldsExpression2) {
  const TessellationLimits l{40.0, 0.5, 12.0};
  // (1 - 10/40) (0.25/0.5) 12 = 4.5
  EXPECT_DOUBLE_EQ(tessellation_level(10.0, 0.25, l), 4.5);
  EXPECT_DOUBLE_EQ(tessellation_level(0.0, 0.5, l), 12.0);
  EXPECT_DOUBLE_EQ(tessellation_level(30.0, 0.1, l), 0.25 * 0.2 * 12.0);
  EXPECT_EQ(tessellation_level(40.0, 0.5, l), 0.0);  // culled from D_max on
  EXPECT_EQ(tessellation_level(80.0, 0.5, l), 0.0);
  EXPECT_DOUBLE_EQ(tessellation_level(0.0, 2.0, l), 12.0);  // area factor clamped to 1
  EXPECT_THROW(tessellation_level(-1.0, 0.1, l), ValueError);
  EXPECT_THROW(tessellation_level(1.0, 0.1, TessellationLimits{0.0, 1.0, 1.0}), ValueError);
}

TEST(TessellationLevel, PerFaceFromCentroidDistanceAndArea) {
  TriangleMesh m;
  // Right triangles with legs 1 (area 0.5) and 2 (area 2), in the plane z = 0.
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {10, 0, 0}, {12, 0, 0}, {10, 2, 0}};
  m.triangles = {{0, 1, 2}, {3, 4, 5}};
  m.materials = {Material::kBark, Material::kBark};
  const Eigen::Vector3f viewer(0, 0, 0);
  const auto levels = face_tessellation_levels(m, viewer, {20.0, 0.0, 8.0});  // A_max = 2
  const double d0 = std::sqrt(2.0) / 3.0;
  const double d1 = Eigen::Vector2d(32.0 / 3.0, 2.0 / 3.0).norm();
  EXPECT_NEAR(levels[0], (1 - d0 / 20.0) * (0.5 / 2.0) * 8.0, 1e-6);
  EXPECT_NEAR(levels[1], (1 - d1 / 20.0) * 1.0 * 8.0, 1e-6);
}

// The uniform cubic B-spline basis written out (Pirk eq. 6.6).
std::array<double, 4> basis(double t) {
  return {std::pow(1 - t, 3) / 6.0, (3 * t * t * t - 6 * t * t + 4) / 6.0,
          (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6.0, t * t * t / 6.0};
}

TEST(BsplineRefinement, MatrixFormEqualsTheBasis) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-2, 2);
  std::array<Eigen::Vector3d, 4> p;
  for (auto& x : p) x = {u(rng), u(rng), u(rng)};
  for (double t : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
    const auto b = basis(t);
    const Eigen::Vector3d expected = b[0] * p[0] + b[1] * p[1] + b[2] * p[2] + b[3] * p[3];
    EXPECT_TRUE(cubic_bspline(p[0], p[1], p[2], p[3], t).isApprox(expected, 1e-12)) << t;
  }
}

// Reynolds 3.3: the highest branch level's bark left out, the leaves kept. small_tree has a trunk
// of order 0 (three internodes, one tube) and two branches of order 1: without them the bark is
// the trunk's tube alone, 2 * 3 * 8 walls and 2 * 8 cap triangles; the trunk is never dropped.
TEST(BranchLevelCulling, HighestBarkOrdersGoTheTrunkAndLeavesStay) {
  MeshOptions o;
  o.min_sides = o.max_sides = 8;
  o.leaves = true;
  const TriangleMesh mesh = mesh_tree(testing::small_tree(), o);
  const TriangleMesh one = without_highest_bark_orders(mesh, 1);
  EXPECT_EQ(one.triangle_count(Material::kBark), 2u * 3u * 8u + 2u * 8u);
  EXPECT_GT(mesh.triangle_count(Material::kBark), one.triangle_count(Material::kBark));
  EXPECT_EQ(one.triangle_count(Material::kLeaf), mesh.triangle_count(Material::kLeaf));
  EXPECT_GT(one.triangle_count(Material::kLeaf), 0u);
  EXPECT_EQ(without_highest_bark_orders(mesh, 5).triangle_count(), one.triangle_count());
  EXPECT_EQ(without_highest_bark_orders(mesh, 0).triangles, mesh.triangles);
  EXPECT_THROW(without_highest_bark_orders(mesh, -1), ValueError);
}

TEST(BsplineRefinement, ChainIsContinuousAndKeepsLines) {
  const std::vector<Eigen::Vector3d> chain = {
      {0, 0, 0}, {0, 0, 1}, {0.3, 0, 2}, {0.8, 0.2, 2.6}, {1.5, 0.2, 3.0}};
  const auto fine = refine_chain(chain, 4);
  ASSERT_EQ(fine.size(), 4u * 4u + 1u);
  // Ends: with the reflected phantom points, S_0(0) = (2 P0 - P1 + 4 P0 + P1) / 6 = P0, and
  // S_3(1) = P4: the chain still starts and ends where it did.
  EXPECT_TRUE(fine.front().isApprox(chain[0]));
  EXPECT_TRUE(fine.back().isApprox(chain[4]));
  // Joints: S_i(0) = (P_{i-1} + 4 P_i + P_{i+1}) / 6, where consecutive segments meet.
  for (int i = 1; i < 4; ++i) {
    EXPECT_TRUE(fine[4 * i].isApprox((chain[i - 1] + 4 * chain[i] + chain[i + 1]) / 6.0)) << i;
  }
  // Evenly spaced collinear points stay on their line, evenly spaced.
  const std::vector<Eigen::Vector3d> line = {{0, 0, 0}, {1, 1, 0}, {2, 2, 0}, {3, 3, 0}};
  const auto refined = refine_chain(line, 3);
  for (std::size_t k = 1; k + 1 < refined.size(); ++k) {
    EXPECT_NEAR(refined[k].x(), refined[k].y(), 1e-12);
  }
  EXPECT_THROW(refine_chain(line, 0), ValueError);
}

// OpenGL-style perspective and look-at, written out.
Eigen::Matrix4d perspective(double fovy, double aspect, double n, double f) {
  const double t = 1.0 / std::tan(fovy / 2);
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = t / aspect;
  m(1, 1) = t;
  m(2, 2) = (f + n) / (n - f);
  m(2, 3) = 2 * f * n / (n - f);
  m(3, 2) = -1;
  return m;
}
Eigen::Matrix4d look_at(const Eigen::Vector3d& eye, const Eigen::Vector3d& at,
                        const Eigen::Vector3d& up) {
  const Eigen::Vector3d f = (at - eye).normalized(), s = f.cross(up).normalized(), u = s.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.row(0) << s.transpose(), -s.dot(eye);
  m.row(1) << u.transpose(), -u.dot(eye);
  m.row(2) << -f.transpose(), f.dot(eye);
  return m;
}

bool in_clip_volume(const Eigen::Matrix4d& vp, const Eigen::Vector3d& p) {
  const Eigen::Vector4d c = vp * p.homogeneous();
  return c.w() > 0 && std::abs(c.x()) <= c.w() && std::abs(c.y()) <= c.w() &&
         std::abs(c.z()) <= c.w();
}

TEST(FrustumCulling, NeverCullsWhatIsInViewAndCullsMost) {
  TriangleMesh cube;  // unit cube from (0,0,0): its corners and centre stand for the instance
  for (int i = 0; i < 8; ++i)
    cube.positions.push_back(Eigen::Vector3f(i & 1, (i >> 1) & 1, i >> 2));
  cube.triangles = {{0, 1, 3}};
  cube.materials = {Material::kBark};
  InstancedMesh scene;
  scene.meshes.push_back(cube);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> pos(-80, 80), s(0.3, 3.0), ang(0, 6.283);
  for (int i = 0; i < 2000; ++i) {
    MeshInstance inst;
    inst.linear =
        (s(rng) * Eigen::AngleAxisd(ang(rng), Eigen::Vector3d::UnitZ()).toRotationMatrix())
            .cast<float>();
    inst.translation = Eigen::Vector3f(pos(rng), pos(rng), 0);
    scene.instances.push_back(inst);
  }
  const Eigen::Matrix4d vp =
      perspective(1.0, 1.5, 0.1, 60.0) * look_at({0, -5, 2}, {3, 10, 1}, Eigen::Vector3d::UnitZ());
  const auto visible = visible_instances(scene, vp);
  const std::set<std::size_t> kept(visible.begin(), visible.end());
  std::size_t brute = 0;
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const auto& inst = scene.instances[i];
    // Brute force: points of the placed cube on a 6 x 6 x 6 grid.
    bool seen = false;
    for (int a = 0; a < 6 && !seen; ++a) {
      for (int b = 0; b < 6 && !seen; ++b) {
        for (int c = 0; c < 6 && !seen; ++c) {
          const Eigen::Vector3d p =
              (inst.linear * Eigen::Vector3f(a / 5.0f, b / 5.0f, c / 5.0f) + inst.translation)
                  .cast<double>();
          seen = in_clip_volume(vp, p);
        }
      }
    }
    brute += seen;
    if (seen) {
      EXPECT_TRUE(kept.count(i)) << "instance " << i << " is in view but was culled";
    }
  }
  EXPECT_GT(brute, 20u);
  EXPECT_GE(kept.size(), brute);
  EXPECT_LT(kept.size(), brute + brute / 2 + 10);  // spheres are loose only near the frustum
  EXPECT_LT(kept.size(), scene.instances.size() / 4);
}

// `n` square leaves of side 0.1 (two triangles each) on a grid, and one bark triangle.
TriangleMesh leafy_mesh(int n) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
  m.triangles = {{0, 1, 2}};
  m.materials = {Material::kBark};
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3f o(static_cast<float>(i % 10), static_cast<float>(i / 10), 2.0f);
    const auto v = static_cast<std::uint32_t>(m.positions.size());
    for (const Eigen::Vector3f& d : {Eigen::Vector3f(0, 0, 0), Eigen::Vector3f(0.1f, 0, 0),
                                     Eigen::Vector3f(0.1f, 0.1f, 0), Eigen::Vector3f(0, 0.1f, 0)}) {
      m.positions.push_back(o + d);
    }
    m.triangles.push_back({v, v + 1, v + 2});
    m.triangles.push_back({v, v + 2, v + 3});
    m.materials.insert(m.materials.end(), 2, Material::kLeaf);
  }
  m.normals.assign(m.positions.size(), Eigen::Vector3f::UnitZ());
  m.uvs.assign(m.positions.size(), Eigen::Vector2f::Zero());
  return m;
}

double leaf_area(const TriangleMesh& m) {
  double a = 0;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    if (m.materials[t] != Material::kLeaf) continue;
    const auto& tri = m.triangles[t];
    a += 0.5 * (m.positions[tri[1]] - m.positions[tri[0]])
                   .cross(m.positions[tri[2]] - m.positions[tri[0]])
                   .norm();
  }
  return a;
}

std::set<std::pair<int, int>> leaf_cells(const TriangleMesh& m) {  // grid cell of each leaf
  std::set<std::pair<int, int>> out;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    if (m.materials[t] != Material::kLeaf) continue;
    const Eigen::Vector3f c = (m.positions[m.triangles[t][0]] + m.positions[m.triangles[t][1]] +
                               m.positions[m.triangles[t][2]]) /
                              3.0f;
    // Leaves are enlarged about their centres (i + 0.05, j + 0.05): round back to the cell.
    out.insert({static_cast<int>(std::lround(c.x() - 0.05f)),
                static_cast<int>(std::lround(c.y() - 0.05f))});
  }
  return out;
}

TEST(StochasticPruning, PrefixKeepsLeafAreaAndNests) {
  const TriangleMesh mesh = leafy_mesh(50);
  std::mt19937_64 rng(5);
  const LeafBuffer buffer = make_leaf_buffer(mesh, rng);
  ASSERT_EQ(buffer.leaf_count(), 50u);
  EXPECT_EQ(buffer.bark.triangle_count(), 1u);
  EXPECT_EQ(pruned_leaf_count(50, 0.3), 15u);
  EXPECT_EQ(pruned_leaf_count(50, 0.001), 1u);
  EXPECT_EQ(pruned_leaf_count(50, 0.0), 0u);
  EXPECT_THROW(pruned_leaf_count(50, 1.5), ValueError);
  EXPECT_DOUBLE_EQ(pruning_fraction(20.0, 10.0), 0.25);
  EXPECT_DOUBLE_EQ(pruning_fraction(5.0, 10.0), 1.0);
  const double total = leaf_area(mesh);  // 50 * 0.01
  std::set<std::pair<int, int>> previous;
  for (std::size_t n : {5u, 15u, 40u, 50u}) {
    const TriangleMesh pruned = pruned_mesh(buffer, n);
    EXPECT_EQ(pruned.triangle_count(), 1 + 2 * n);
    EXPECT_NEAR(leaf_area(pruned), total, 1e-4 * total) << n << " leaves";
    const auto cells = leaf_cells(pruned);
    EXPECT_EQ(cells.size(), n);
    for (const auto& c : previous) EXPECT_TRUE(cells.count(c)) << "prefixes nest";
    previous = cells;
  }
  // Same seed, same leaves; another seed, another choice.
  std::mt19937_64 same(5), other(6);
  EXPECT_EQ(leaf_cells(pruned_mesh(make_leaf_buffer(mesh, same), 10)),
            leaf_cells(pruned_mesh(buffer, 10)));
  EXPECT_NE(leaf_cells(pruned_mesh(make_leaf_buffer(mesh, other), 10)),
            leaf_cells(pruned_mesh(buffer, 10)));
}

}  // namespace
}  // namespace fspm::graphics
