#include "graphics/render.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "fspm/error.hpp"
#include "graphics/tree_mesher.hpp"
#include "tests/graphics/test_trees.hpp"

namespace fspm::graphics {
namespace {

namespace fs = std::filesystem;

TEST(Render, ViewAndSizeParsing) {
  EXPECT_EQ(view_from_name("top"), View::kTop);
  EXPECT_THROW(view_from_name("back"), ValueError);
  int w = 0, h = 0;
  parse_size("640x480", w, h);
  EXPECT_EQ(w, 640);
  EXPECT_EQ(h, 480);
  EXPECT_THROW(parse_size("640", w, h), ValueError);
  EXPECT_THROW(parse_size("0x10", w, h), ValueError);
  EXPECT_THROW(parse_size("10x10x", w, h), ValueError);
}

TEST(Render, UnknownColourAttributeIsValueError) {
  const TriangleMesh mesh = mesh_tree(testing::small_tree(), {});
  RenderOptions o;
  o.color_by = "no_such_attribute";
  EXPECT_THROW(render_mesh(mesh, o), ValueError);
}

TEST(Render, ImageRoundTripThroughOpenImageIO) {
  if (!render_available()) GTEST_SKIP() << "built without VTK/OpenImageIO";
  Image image;
  image.width = 7;
  image.height = 5;
  image.rgba.resize(7 * 5 * 4);
  for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = static_cast<std::uint8_t>(i);
  for (std::size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;
  const fs::path dir = fs::temp_directory_path() / ("fspm_img_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (const char* name : {"a.png", "a.tif"}) {
    const std::string p = (dir / name).string();
    write_image(image, p);
    const Image back = read_image(p);
    EXPECT_EQ(back.width, 7);
    EXPECT_EQ(back.height, 5);
    EXPECT_EQ(back.rgba, image.rgba) << name;
  }
  EXPECT_THROW(write_image(image, (dir / "a.unknownformat").string()), ValueError);
  EXPECT_THROW(write_image(image, (dir / "missing/a.png").string()), IoError);
  EXPECT_FALSE(fs::exists(dir / "missing"));
  fs::remove_all(dir);
}

// Counts pixels whose colour is close to `rgb`.
std::size_t count_near(const Image& image, int r, int g, int b, int tolerance) {
  std::size_t n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      if (std::abs(p[0] - r) <= tolerance && std::abs(p[1] - g) <= tolerance &&
          std::abs(p[2] - b) <= tolerance) {
        ++n;
      }
    }
  }
  return n;
}

TEST(Render, IsoViewShowsBarkLeavesAndBackground) {
  if (!render_available()) GTEST_SKIP() << "built without VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  MeshOptions mo;
  mo.leaves = true;
  const TriangleMesh mesh = mesh_tree(testing::small_tree(), mo);
  RenderOptions o;
  o.width = 200;
  o.height = 160;
  o.view = View::kIso;
  o.ground = false;
  const Image image = render_mesh(mesh, o);
  ASSERT_EQ(image.width, 200);
  ASSERT_EQ(image.height, 160);
  // Top-left corner is the white end of the gradient background.
  const auto* corner = image.pixel(0, 0);
  EXPECT_GT(corner[0], 180);
  // Some pixels are bark brown (red > green > blue) and some leaf green.
  std::size_t bark = 0, leaf = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      if (p[0] > p[1] + 10 && p[1] > p[2] + 5) ++bark;
      if (p[1] > p[0] + 30 && p[1] > p[2] + 30) ++leaf;
    }
  }
  EXPECT_GT(bark, 200u);
  EXPECT_GT(leaf, 5u);
}

TEST(Render, ColourByAgeSpansTheLookupTable) {
  if (!render_available()) GTEST_SKIP() << "built without VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  const TriangleMesh mesh = mesh_tree(testing::small_tree(), {});
  RenderOptions o;
  o.width = 240;
  o.height = 200;
  o.color_by = "age";
  const Image image = render_mesh(mesh, o);
  // Blue (young tips) and red (old trunk) both appear, in the tree and in the scalar bar.
  std::size_t red = 0, blue = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      if (p[0] > 120 && p[0] > 2 * p[1] && p[0] > 2 * p[2]) ++red;
      if (p[2] > 120 && p[2] > 2 * p[0] && p[2] > 2 * p[1]) ++blue;
    }
  }
  EXPECT_GT(red, 20u);
  EXPECT_GT(blue, 20u);
  (void)count_near;
}

}  // namespace
}  // namespace fspm::graphics
