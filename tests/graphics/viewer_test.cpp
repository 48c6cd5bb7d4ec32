#include "graphics/viewer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "fspm/error.hpp"
#include "graphics/image.hpp"
#include "graphics/render.hpp"
#include "graphics/tree_mesher.hpp"
#include "tests/graphics/test_trees.hpp"

namespace fspm::graphics {
namespace {

namespace fs = std::filesystem;

TEST(Viewer, RejectsUnknownAttributeAndNoSteps) {
  ViewerOptions o;
  EXPECT_THROW(run_viewer({}, {}, o), ValueError);
  o.color_by = "nope";
  EXPECT_THROW(run_viewer({mesh_tree(testing::small_tree(), {})}, {0.0}, o), ValueError);
}

TEST(Viewer, ScreenshotAfterFramesShowsTreeAndShadow) {
  if (!viewer_available() || !render_available()) GTEST_SKIP() << "built without viewer/VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  const fs::path dir = fs::temp_directory_path() / ("fspm_viewer_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  ViewerOptions o;
  o.width = 320;
  o.height = 240;
  o.frames = 3;
  o.screenshot = (dir / "shot.png").string();
  MeshOptions mo;
  mo.leaves = true;
  const TreeGraph tree = testing::small_tree();
  std::vector<TriangleMesh> steps;
  mo.max_birth_time = 2.5;
  steps.push_back(mesh_tree(tree, mo));
  mo.max_birth_time = 10;
  steps.push_back(mesh_tree(tree, mo));
  const ViewerStats stats = run_viewer(steps, {2.5, 10}, o);
  EXPECT_EQ(stats.frames, 3);
  EXPECT_EQ(stats.triangles, steps.back().triangle_count());  // starts on the last step
  EXPECT_GT(stats.mean_frame_ms, 0.0);
  const Image shot = read_image(o.screenshot);
  ASSERT_EQ(shot.width, 320);
  ASSERT_EQ(shot.height, 240);
  // Sky at the top-left corner; bark pixels (red > green > blue); ground pixels both lit
  // (0.55, 0.62, 0.45 shaded) and in shadow (same hue, darker).
  const auto* sky = shot.pixel(0, 0);
  EXPECT_GT(sky[2], sky[0]);
  std::size_t bark = 0, lit_ground = 0, dark_ground = 0;
  for (int y = 0; y < shot.height; ++y) {
    for (int x = 0; x < shot.width; ++x) {
      const auto* p = shot.pixel(x, y);
      if (p[0] > p[1] + 10 && p[1] > p[2] + 5) ++bark;
      const bool greenish_grey = p[1] > p[0] && p[1] > p[2] && p[1] - p[2] < 60;
      if (greenish_grey && p[1] > 130) ++lit_ground;
      if (greenish_grey && p[1] < 100 && p[1] > 20) ++dark_ground;
    }
  }
  EXPECT_GT(bark, 100u);
  EXPECT_GT(lit_ground, 1000u);
  EXPECT_GT(dark_ground, 20u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fspm::graphics
