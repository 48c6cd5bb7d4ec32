// Area-weighted vertex normals against closed forms: a cube's corners point along the diagonal,
// a flat grid's normals are its plane's, and two faces of different areas weigh by area.
#include "fspm/vertex_normals.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace fspm {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

void expect_near(const Eigen::Vector3f& got, const Eigen::Vector3f& want) {
  EXPECT_LT((got - want).norm(), 1e-6f) << got.transpose() << " against " << want.transpose();
}

// The cube [-1, 1]^3 with each face split into four triangles around its centre, so every corner
// meets two equal triangles of each of its three faces: its normal is (+-1, +-1, +-1) / sqrt(3),
// and a face centre's is the face's axis.
TEST(VertexNormals, CubeCornersPointAlongTheDiagonal) {
  std::vector<Eigen::Vector3f> p;
  for (int k = 0; k < 8; ++k) {
    p.emplace_back(k & 1 ? 1.0f : -1.0f, k & 2 ? 1.0f : -1.0f, k & 4 ? 1.0f : -1.0f);
  }
  std::vector<Triangle> triangles;
  for (int axis = 0; axis < 3; ++axis) {
    for (const float side : {-1.0f, 1.0f}) {
      Eigen::Vector3f normal = Eigen::Vector3f::Zero();
      normal[axis] = side;
      const auto centre = static_cast<std::uint32_t>(p.size());
      p.push_back(normal);
      // The face's corners in counter-clockwise order seen from outside.
      std::vector<std::uint32_t> ring;
      for (std::uint32_t k = 0; k < 8; ++k) {
        if (p[k][axis] == side) ring.push_back(k);
      }
      const Eigen::Vector3f u = normal.cross(Eigen::Vector3f::Ones()).normalized();
      const Eigen::Vector3f w = normal.cross(u);
      std::sort(ring.begin(), ring.end(), [&](std::uint32_t a, std::uint32_t b) {
        return std::atan2(p[a].dot(w), p[a].dot(u)) < std::atan2(p[b].dot(w), p[b].dot(u));
      });
      for (std::size_t i = 0; i < 4; ++i) triangles.push_back({centre, ring[i], ring[(i + 1) % 4]});
    }
  }
  const auto normals = area_weighted_vertex_normals(p, triangles);
  ASSERT_EQ(normals.size(), 14u);
  for (std::size_t k = 0; k < 8; ++k) expect_near(normals[k], p[k] / std::sqrt(3.0f));
  for (std::size_t k = 8; k < 14; ++k) expect_near(normals[k], p[k]);
}

// A 4 x 3 grid in the plane z = 2, two triangles per cell counter-clockwise from above: +z
// everywhere; the same triangles wound the other way: -z.
TEST(VertexNormals, FlatGridNormalsAreThePlanes) {
  std::vector<Eigen::Vector3f> p;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 4; ++i) p.emplace_back(0.5f * i, 0.25f * j, 2.0f);
  }
  std::vector<Triangle> up, down;
  for (std::uint32_t j = 0; j < 2; ++j) {
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t a = j * 4 + i, b = a + 1, c = a + 4, d = c + 1;
      up.push_back({a, b, d});
      up.push_back({a, d, c});
      down.push_back({a, d, b});
      down.push_back({a, c, d});
    }
  }
  for (const Eigen::Vector3f& n : area_weighted_vertex_normals(p, up)) {
    expect_near(n, Eigen::Vector3f::UnitZ());
  }
  for (const Eigen::Vector3f& n : area_weighted_vertex_normals(p, down)) {
    expect_near(n, -Eigen::Vector3f::UnitZ());
  }
}

// Two faces meeting at the origin: area 2 facing +z and area 1/2 facing +x. Their cross products
// are (0, 0, 4) and (1, 0, 0), so the shared vertex's normal is (1, 0, 4) / sqrt(17).
TEST(VertexNormals, FacesWeighByArea) {
  const std::vector<Eigen::Vector3f> p = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<Triangle> triangles = {{0, 1, 2}, {0, 3, 4}};
  const auto normals = area_weighted_vertex_normals(p, triangles);
  expect_near(normals[0], Eigen::Vector3f(1, 0, 4) / std::sqrt(17.0f));
  expect_near(normals[1], Eigen::Vector3f::UnitZ());
  expect_near(normals[4], Eigen::Vector3f::UnitX());
}

// A vertex of no triangle, or only of a degenerate one, has no direction of its own: +z.
TEST(VertexNormals, VertexWithoutAreaGetsUp) {
  const std::vector<Eigen::Vector3f> p = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {5, 5, 5}};
  const auto normals = area_weighted_vertex_normals(p, std::vector<Triangle>{{0, 1, 2}});
  for (const Eigen::Vector3f& n : normals) expect_near(n, Eigen::Vector3f::UnitZ());
}

}  // namespace
}  // namespace fspm
