#pragma once
// Invariants every tree mesh must satisfy, shared by the mesher and writer tests.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <bit>
#include <cstring>
#include <map>
#include <tuple>

#include "graphics/triangle_mesh.hpp"

namespace fspm::graphics::testing {

// Indices in range, columns sized, unit normals, no degenerate triangles, no triangle whose
// winding disagrees with its vertex normals.
inline void expect_valid_mesh(const TriangleMesh& mesh) {
  const std::size_t nv = mesh.vertex_count();
  ASSERT_EQ(mesh.normals.size(), nv);
  ASSERT_EQ(mesh.uvs.size(), nv);
  ASSERT_EQ(mesh.materials.size(), mesh.triangle_count());
  for (const auto& a : mesh.attributes) ASSERT_EQ(a.values.size(), nv) << a.name;
  for (std::size_t i = 0; i < nv; ++i) {
    ASSERT_NEAR(mesh.normals[i].norm(), 1.0f, 1e-5f) << "vertex " << i;
  }
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (auto i : tri) ASSERT_LT(i, nv);
    const Eigen::Vector3f a = mesh.positions[tri[0]], b = mesh.positions[tri[1]],
                          c = mesh.positions[tri[2]];
    const Eigen::Vector3f n = (b - a).cross(c - a);
    ASSERT_GT(n.norm(), 1e-10f) << "degenerate triangle " << t;
    const Eigen::Vector3f mean = mesh.normals[tri[0]] + mesh.normals[tri[1]] + mesh.normals[tri[2]];
    ASSERT_GT(n.normalized().dot(mean.normalized()), 0.0f) << "inverted triangle " << t;
  }
}

// Bark surfaces are closed and consistently oriented: after welding vertices at identical
// positions (and identical "branch" attribute when the tree has one, since sibling branches may
// touch), every directed edge occurs exactly once and its reverse exactly once.
inline void expect_closed_bark(const TriangleMesh& mesh) {
  using Key = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, float>;
  const bool branches = mesh.has_attribute("branch");
  std::map<Key, std::uint32_t> weld;
  std::vector<std::uint32_t> id(mesh.vertex_count());
  for (std::size_t i = 0; i < mesh.vertex_count(); ++i) {
    const auto& p = mesh.positions[i];
    const Key k{std::bit_cast<std::uint32_t>(p.x()), std::bit_cast<std::uint32_t>(p.y()),
                std::bit_cast<std::uint32_t>(p.z()), branches ? mesh.attribute("branch")[i] : 0.0f};
    id[i] = weld.emplace(k, static_cast<std::uint32_t>(weld.size())).first->second;
  }
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (mesh.materials[t] != Material::kBark) continue;
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) ++edges[{id[tri[k]], id[tri[(k + 1) % 3]]}];
  }
  for (const auto& [e, n] : edges) {
    ASSERT_EQ(n, 1) << "directed edge used " << n << " times";
    auto rev = edges.find({e.second, e.first});
    ASSERT_TRUE(rev != edges.end()) << "open edge " << e.first << "-" << e.second;
  }
}

}  // namespace fspm::graphics::testing
