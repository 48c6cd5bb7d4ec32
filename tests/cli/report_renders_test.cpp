// fspm report's renders with the scene: a tree adapted beside a wall is drawn with the wall, one
// adapted far from it alone (and its caption says why), both at one scale with a scale bar.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "graphics/image.hpp"
#include "tests/cli/run_command.hpp"
#include "tests/graphics/image_checks.hpp"

namespace fspm::testing {
namespace {

namespace fs = std::filesystem;

TEST(ReportRenders, TheWallIsDrawnBesideTheTreeThatWasAdaptedToIt) {
  const fs::path dir = scratch_dir("report_renders");
  const std::string examples = std::string(FSPM_SOURCE_DIR) + "/examples";
  // The example tree 7.5 m from the wall's face (run 0: far) and 1 m from it (run 1: near).
  write_text(dir / "e.toml",
             "[experiment]\nname = \"w\"\n[model]\nkind = \"adapt\"\nfile = \"" + examples +
                 "/trees/open_a12.treeb\"\nscene = \"" + examples +
                 "/environment/wall_scene.json\"\n[sweep]\ntree_x_m = [-5.0, 1.5]\n"
                 "[outputs]\nmetrics = [\"nodes\", \"pruned_nodes\"]\nimage_size = \"200x150\"\n");
  const std::string out = (dir / "out").string();
  ASSERT_EQ(run_fspm("run " + (dir / "e.toml").string() + " -j 2 -o " + out).exit_code, 0);
  const CommandResult report = run_fspm("report " + out);
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const std::string md = read_text(dir / "out" / "report.md");
  if (md.find("not rendered") != std::string::npos || !fs::exists(dir / "out" / "figures")) {
    GTEST_SKIP() << "no renders (no VTK or no display): " << md;
  }
  EXPECT_NE(md.find("All pictures at one scale"), std::string::npos) << md;
  EXPECT_NE(md.find("the black bar is 1 m"), std::string::npos) << md;
  // Only the far tree's caption says the wall was too far away to draw.
  const auto far = md.find("the scene's obstacles are too far from the tree to be drawn");
  ASSERT_NE(far, std::string::npos) << md;
  EXPECT_EQ(md.find("the scene's obstacles are too far", far + 1), std::string::npos) << md;
  EXPECT_LT(md.find("*Run 0 "), far);
  EXPECT_GT(md.find("*Run 1 "), far);
  const graphics::Image far_image =
      graphics::read_image((dir / "out/figures/run-0000000.png").string());
  const graphics::Image near_image =
      graphics::read_image((dir / "out/figures/run-0000001.png").string());
  ASSERT_EQ(near_image.width, 200);
  ASSERT_EQ(near_image.height, 150);
  // The wall, 6 m high in a picture about 6.4 m high, is a grey column of many pixels.
  EXPECT_LT(graphics::testing::stone_pixels(far_image), 30u);
  EXPECT_GT(graphics::testing::stone_pixels(near_image), 200u);
  // The light profile of both trees (their clusters carry a translucency), listed by run.
  EXPECT_NE(md.find("## Light in the crown"), std::string::npos) << md;
  EXPECT_NE(md.find("- run 0: tree_x_m = -5"), std::string::npos) << md;
  EXPECT_NE(md.find("- run 1: tree_x_m = 1.5"), std::string::npos) << md;
  const graphics::Image profile =
      graphics::read_image((dir / "out/figures/light-profile.png").string());
  EXPECT_EQ(profile.width, 640);
  EXPECT_EQ(profile.height, 480);
}

}  // namespace
}  // namespace fspm::testing
