// fspm mesh --skin --animate through the executable: counts, and every misuse exits 1 without
// writing.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "tests/cli/run_command.hpp"
#include "tests/cli/small_tree.hpp"

namespace fspm {
namespace {

using testing::run_fspm;
using testing::scratch_dir;
using testing::write_small_tree;

TEST(WindCli, SkinnedGlbWithAnimation) {
  const auto dir = scratch_dir("wind");
  const std::string tree = write_small_tree(dir);
  const std::string out = (dir / "w.glb").string();
  auto r = run_fspm("mesh " + tree + " --skin --animate 2 --fps 5 -o " + out + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["joints"], 2);      // two internodes
  EXPECT_EQ(j["keyframes"], 11);  // 0, 0.2, ..., 2 s
  EXPECT_TRUE(std::filesystem::exists(out));
  r = run_fspm("mesh " + tree + " --skin -o " + (dir / "still.glb").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["keyframes"], 0);
  // With the leaf: two bark bones and a quad of 4 vertices more than the bark alone.
  r = run_fspm("mesh " + tree + " --skin --leaves -o " + (dir / "leafy.glb").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto leafy = nlohmann::json::parse(r.out);
  EXPECT_EQ(leafy["joints"], 2);
  EXPECT_EQ(leafy["vertices"].get<int>(), j["vertices"].get<int>() + 4);
}

TEST(WindCli, MisuseExitsOneWithoutOutput) {
  const auto dir = scratch_dir("wind_bad");
  const std::string tree = write_small_tree(dir);
  const std::string glb = (dir / "x.glb").string();
  for (const std::string& args :
       {"mesh " + tree + " --skin -o " + (dir / "x.obj").string(),
        "mesh " + tree + " --animate 2 -o " + glb, "mesh " + tree + " --skin --ages 1 -o " + glb,
        "mesh " + tree + " --skin --animate 2 --wind-direction 0,0 -o " + glb,
        "mesh " + tree + " --skin --animate -1 -o " + glb}) {
    const auto r = run_fspm(args);
    EXPECT_EQ(r.exit_code, 1) << args;
    EXPECT_FALSE(std::filesystem::exists(glb)) << args;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.obj")) << args;
  }
}

}  // namespace
}  // namespace fspm
