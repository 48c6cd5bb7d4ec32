// Terrain from a heightfield: heights at the samples and bilinear between them, checked against
// values worked out by hand for a tiny image; the grid mesh; reading the image from a file.
#include "graphics/heightfield.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>

#include "fspm/error.hpp"
#include "graphics/image.hpp"
#include "graphics/render.hpp"

namespace fspm::graphics {
namespace {

// 3 columns x 2 rows, row 0 (north) first; fifths, so 8-bit grey levels hold them exactly.
//   north: 0.0 0.2 0.4      at 2 m per pixel and 10 m per unit the samples stand at
//   south: 0.6 0.8 0.4      y = 2: (0, 0) (2, 2) (4, 4); y = 0: (0, 6) (2, 8) (4, 4)  [x, z]
FloatImage tiny_image() {
  FloatImage image;
  image.width = 3;
  image.height = 2;
  image.values = {0.0f, 0.2f, 0.4f, 0.6f, 0.8f, 0.4f};
  return image;
}

void expect_tiny_heights(const Heightfield& h) {
  EXPECT_EQ(h.width_m(), 4.0);
  EXPECT_EQ(h.depth_m(), 2.0);
  // The samples (pixel centres).
  EXPECT_NEAR(h.height_at(0, 2), 0.0, 1e-5);
  EXPECT_NEAR(h.height_at(2, 2), 2.0, 1e-5);
  EXPECT_NEAR(h.height_at(4, 2), 4.0, 1e-5);
  EXPECT_NEAR(h.height_at(0, 0), 6.0, 1e-5);
  EXPECT_NEAR(h.height_at(2, 0), 8.0, 1e-5);
  EXPECT_NEAR(h.height_at(4, 0), 4.0, 1e-5);
  // Cell centres: the mean of the four corners, (0 + 2 + 6 + 8) / 4 and (2 + 4 + 8 + 4) / 4.
  EXPECT_NEAR(h.height_at(1, 1), 4.0, 1e-5);
  EXPECT_NEAR(h.height_at(3, 1), 4.5, 1e-5);
  // (3, 0.5): halfway along x, a quarter of the way up from the south row:
  // north edge (2 + 4) / 2 = 3, south edge (8 + 4) / 2 = 6, 6 + 0.25 (3 - 6) = 5.25.
  EXPECT_NEAR(h.height_at(3, 0.5), 5.25, 1e-5);
  // Along an edge between two samples: linear, 0 + 0.3 (6 - 0) at x = 0, y = 1.4.
  EXPECT_NEAR(h.height_at(0, 1.4), 1.8, 1e-5);
  // Outside the extent: clamped to the border.
  EXPECT_NEAR(h.height_at(-5, 9), 0.0, 1e-5);
  EXPECT_NEAR(h.height_at(50, -3), 4.0, 1e-5);
}

TEST(Heightfield, HeightsAtSamplesAndBilinearBetween) {
  expect_tiny_heights(Heightfield(tiny_image(), 2.0, 10.0));
}

TEST(Heightfield, ReadsTheHeightsFromAnImageFile) {
  if (!render_available()) GTEST_SKIP() << "built without OpenImageIO";
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "fspm_heightfield_test.png";
  Image png;
  png.width = 3;
  png.height = 2;
  png.rgba.assign(3 * 2 * 4, 255);
  const std::uint8_t grey[6] = {0, 51, 102, 153, 204, 102};  // fifths of 255
  for (int k = 0; k < 6; ++k) {
    for (int c = 0; c < 3; ++c) png.rgba[4 * k + c] = grey[k];
  }
  write_image(png, path.string());
  expect_tiny_heights(Heightfield(read_float_image(path.string()), 2.0, 10.0));
  std::filesystem::remove(path);
}

TEST(Heightfield, RejectsTooSmallImagesAndBadScales) {
  FloatImage one;
  one.width = 1;
  one.height = 5;
  one.values.assign(5, 0.0f);
  EXPECT_THROW(Heightfield(one, 1.0, 1.0), ValueError);
  EXPECT_THROW(Heightfield(tiny_image(), 0.0, 1.0), ValueError);
  EXPECT_THROW(read_float_image("/nonexistent/height.png"), Error);
}

TEST(Heightfield, MeshIsTheGridOfSamplesFacingUp) {
  const Heightfield h(tiny_image(), 2.0, 10.0);
  const TriangleMesh mesh = heightfield_mesh(h);
  ASSERT_EQ(mesh.vertex_count(), 6u);
  ASSERT_EQ(mesh.triangle_count(), 4u);  // two per cell
  EXPECT_EQ(mesh.triangle_count(Material::kTerrain), 4u);
  for (const auto& p : mesh.positions) {
    EXPECT_NEAR(p.z(), h.height_at(p.x(), p.y()), 1e-5);
  }
  EXPECT_EQ(mesh.positions[5], Eigen::Vector3f(4, 0, 4));  // last column of the south row
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3f n = (mesh.positions[t[1]] - mesh.positions[t[0]])
                                  .cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
    EXPECT_GT(n.z(), 0.0f);  // counter-clockwise seen from above
  }
  for (const auto& n : mesh.normals) EXPECT_GT(n.z(), 0.0f);
}

TEST(Heightfield, StrideKeepsEveryStrideThSampleAndTheLast) {
  FloatImage image;
  image.width = 5;
  image.height = 5;
  image.values.assign(25, 0.5f);
  const Heightfield h(image, 1.0, 1.0);
  EXPECT_EQ(heightfield_mesh(h, 2).vertex_count(), 9u);  // 0, 2, 4 each way
  EXPECT_EQ(heightfield_mesh(h, 3).vertex_count(), 9u);  // 0, 3, 4
  EXPECT_EQ(heightfield_mesh(h, 10).vertex_count(), 4u);
  EXPECT_THROW(heightfield_mesh(h, 0), ValueError);
}

}  // namespace
}  // namespace fspm::graphics
