// The viewer's controls panel (Dear ImGui) and its test hook, under Xvfb.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "graphics/image.hpp"
#include "graphics/render.hpp"
#include "graphics/tree_mesher.hpp"
#include "graphics/viewer.hpp"
#include "tests/graphics/test_trees.hpp"

namespace fspm::graphics {
namespace {

namespace fs = std::filesystem;

class ViewerPanelTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!viewer_available() || !render_available()) GTEST_SKIP() << "built without viewer/VTK";
    if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
    dir_ = fs::temp_directory_path() / ("fspm_viewer_panel_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }
  fs::path dir_;
};

// Seen from 3 degrees above the horizontal the horizon is at (1 - tan 3 / tan 20) H / 2 = 205.4
// rows from the top of a 480-row image (viewer_test.cpp, LowViewShowsGroundUpToTheHorizon), so
// the panel's corner, pixels 8-308 across and 8 down to at most 200, is cleared sky without the
// panel: RGB (0.80, 0.87, 0.96) x 255 = (204, 222, 245), as it was before the viewer had a panel.
// With it, most of that corner is the panel's dark background; everything else is unchanged.
TEST_F(ViewerPanelTest, PanelDrawsInItsCornerAndNowhereElse) {
  TriangleMesh post;  // bounds [-1.5, 1.5]^3 from unused corner vertices
  for (int k = 0; k < 8; ++k) {
    post.positions.emplace_back(k & 1 ? 1.5f : -1.5f, k & 2 ? 1.5f : -1.5f, k & 4 ? 1.5f : -1.5f);
    post.normals.emplace_back(0, 0, 1);
    post.uvs.emplace_back(0, 0);
  }
  ViewerOptions o;
  o.width = 640;
  o.height = 480;
  o.shadows = false;
  o.pitch_deg = 3.0;
  o.screenshot = (dir_ / "without.png").string();
  (void)run_viewer({post}, {0.0}, o);
  const Image without = read_image(o.screenshot);
  if (!viewer_panel_available()) GTEST_SKIP() << "built without Dear ImGui";
  o.panel = true;
  o.screenshot = (dir_ / "with.png").string();
  (void)run_viewer({post}, {0.0}, o);
  const Image with = read_image(o.screenshot);
  std::size_t sky = 0, panel = 0, corner = 0, changed_outside = 0;
  for (int y = 0; y < o.height; ++y) {
    for (int x = 0; x < o.width; ++x) {
      const auto* a = without.pixel(x, y);
      const auto* b = with.pixel(x, y);
      const bool same = a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
      if (x >= 8 && x < 308 && y >= 8 && y < 200) {
        ++corner;
        if (a[0] == 204 && a[1] == 222 && a[2] == 245) ++sky;
        if (b[0] + b[1] + b[2] < 3 * 120) ++panel;  // dark: the panel's background and frame
      } else if (x >= 320 || y >= 220) {
        changed_outside += same ? 0 : 1;
      }
    }
  }
  EXPECT_EQ(sky, corner);          // without the panel: the sky, as before
  EXPECT_GT(panel, corner / 2);    // with it: the panel covers most of the corner
  EXPECT_EQ(changed_outside, 0u);  // and nothing else changes
}

// Two growth steps of the small tree (ages 2.5 and 10); the viewer starts on the last. The test
// hook moves the step control to 0 before the first frame, as the panel's step slider does: the
// frame drawn is the younger tree (its triangle count), and the picture is that of a viewer showing
// only the younger tree.
TEST_F(ViewerPanelTest, StepControlChangesTheAgeShown) {
  const TreeGraph tree = testing::small_tree();
  MeshOptions mo;
  mo.leaves = true;
  mo.max_birth_time = 2.5;
  const TriangleMesh young = mesh_tree(tree, mo);
  mo.max_birth_time = 10;
  const TriangleMesh old = mesh_tree(tree, mo);
  ASSERT_NE(young.triangle_count(), old.triangle_count());
  ViewerOptions o;
  o.width = 240;
  o.height = 180;
  o.frames = 2;
  o.panel = viewer_panel_available();
  o.screenshot = (dir_ / "old.png").string();
  const ViewerStats as_is = run_viewer({young, old}, {2.5, 10}, o);
  EXPECT_EQ(as_is.triangles, old.triangle_count());
  EXPECT_EQ(as_is.controls.step, 1);
  int calls = 0;
  o.before_frame = [&](int frame, ViewerControls& c) {
    EXPECT_EQ(frame, calls++);
    if (frame == 0) c.step = 0;
  };
  o.screenshot = (dir_ / "moved.png").string();
  const ViewerStats moved = run_viewer({young, old}, {2.5, 10}, o);
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(moved.controls.step, 0);
  EXPECT_EQ(moved.triangles, young.triangle_count());
  // The same bounds (both steps), so the same camera: the young tree's picture.
  o.panel = false;
  o.before_frame = [](int, ViewerControls& c) { c.step = 0; };
  o.screenshot = (dir_ / "moved_bare.png").string();
  (void)run_viewer({young, old}, {2.5, 10}, o);
  o.before_frame = nullptr;
  o.screenshot = (dir_ / "old_bare.png").string();
  (void)run_viewer({young, old}, {2.5, 10}, o);
  const Image a = read_image((dir_ / "moved_bare.png").string());
  const Image b = read_image((dir_ / "old_bare.png").string());
  std::size_t differ = 0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) differ += a.pixel(x, y)[0] != b.pixel(x, y)[0] ? 1 : 0;
  }
  EXPECT_GT(differ, 50u);  // the branches born at 3 and 4 and their leaves are gone
}

// Choosing a colour attribute while the viewer runs gives the picture of a viewer started with
// it (the meshes are uploaded again with the attribute's colours over its range).
TEST_F(ViewerPanelTest, ColourControlRecoloursAsAtStart) {
  const TriangleMesh mesh = mesh_tree(testing::small_tree(), {});
  ASSERT_TRUE(mesh.has_attribute("light"));
  ViewerOptions o;
  o.width = 200;
  o.height = 160;
  o.frames = 2;
  o.color_by = "light";
  o.screenshot = (dir_ / "start.png").string();
  (void)run_viewer({mesh}, {0.0}, o);
  o.color_by.clear();
  o.screenshot = (dir_ / "plain.png").string();
  (void)run_viewer({mesh}, {0.0}, o);
  o.before_frame = [](int frame, ViewerControls& c) {
    if (frame == 1) c.color_by = "light";
  };
  o.screenshot = (dir_ / "switched.png").string();
  const ViewerStats stats = run_viewer({mesh}, {0.0}, o);
  EXPECT_EQ(stats.controls.color_by, "light");
  const Image start = read_image((dir_ / "start.png").string());
  const Image plain = read_image((dir_ / "plain.png").string());
  const Image switched = read_image((dir_ / "switched.png").string());
  std::size_t same_as_start = 0, differ_from_plain = 0;
  for (int y = 0; y < start.height; ++y) {
    for (int x = 0; x < start.width; ++x) {
      bool same = true, plain_same = true;
      for (int k = 0; k < 3; ++k) {
        same &= start.pixel(x, y)[k] == switched.pixel(x, y)[k];
        plain_same &= plain.pixel(x, y)[k] == switched.pixel(x, y)[k];
      }
      same_as_start += same ? 1 : 0;
      differ_from_plain += plain_same ? 0 : 1;
    }
  }
  EXPECT_EQ(same_as_start, std::size_t(200 * 160));
  EXPECT_GT(differ_from_plain, 50u);
}

}  // namespace
}  // namespace fspm::graphics
