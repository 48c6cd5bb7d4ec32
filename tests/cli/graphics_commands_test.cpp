#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "fspm/tree_file.hpp"
#include "tests/cli/run_command.hpp"
#include "tests/cli/small_tree.hpp"

namespace fspm {
namespace {

using testing::run_fspm;
using testing::scratch_dir;

using testing::write_small_tree;

TEST(GraphicsCli, MeshEveryFormatWithCounts) {
  const auto dir = scratch_dir("mesh");
  const std::string tree = write_small_tree(dir);
  // One tube of 2 segments with 16 sides (ceil(2 pi 0.05 / 0.01) clamped): 3 rings of 17
  // vertices and two caps of 17; 64 wall and 32 cap triangles. The leaf adds 4 and 2.
  for (const char* ext : {"obj", "ply", "vtp", "glb"}) {
    const std::string out = (dir / (std::string("t.") + ext)).string();
    auto r = run_fspm("mesh " + tree + " -o " + out + " --leaves --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["vertices"], 85 + 4) << ext;
    EXPECT_EQ(j["triangles"], 96 + 2) << ext;
    EXPECT_GE(j["seconds"].get<double>(), 0.0);
    EXPECT_TRUE(std::filesystem::exists(out));
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "t.mtl"));
  auto r = run_fspm("mesh " + tree + " -o " + (dir / "t.glb").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["triangles"], 96);
}

TEST(GraphicsCli, GrowthSequence) {
  const auto dir = scratch_dir("pvd");
  const std::string tree = write_small_tree(dir);
  auto r = run_fspm("mesh " + tree + " -o " + (dir / "g.pvd").string() +
                    " --leaves --ages 0,1,2 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["frames"].size(), 3u);
  // Age 0: one segment of 16 sides (2 rings + 2 caps of 17; 32 + 32 triangles).
  EXPECT_EQ(j["frames"][0]["triangles"], 64);
  EXPECT_EQ(j["frames"][1]["triangles"], 96);
  EXPECT_EQ(j["frames"][2]["triangles"], 98);
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(std::filesystem::exists(dir / ("g_000" + std::to_string(i) + ".vtp")));
  }
  r = run_fspm("mesh " + tree + " -o " + (dir / "g.glb").string() + " --ages 1");
  EXPECT_EQ(r.exit_code, 1);
}

TEST(GraphicsCli, BadInputsExitOneWithoutOutput) {
  const auto dir = scratch_dir("mesh_bad");
  const std::string tree = write_small_tree(dir);
  auto r = run_fspm("mesh " + (dir / "missing.tree").string() + " -o " + (dir / "x.glb").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("missing.tree"), std::string::npos) << r.err;
  r = run_fspm("mesh " + tree + " -o " + (dir / "x.stl").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(".stl"), std::string::npos) << r.err;
  r = run_fspm("mesh " + tree + " -o " + (dir / "no" / "x.glb").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_FALSE(std::filesystem::exists(dir / "no"));
  EXPECT_FALSE(std::filesystem::exists(dir / "x.glb"));
}

TEST(GraphicsCli, RenderPngAndUnknownAttribute) {
  const auto dir = scratch_dir("render");
  const std::string tree = write_small_tree(dir);
  auto r = run_fspm("render " + tree + " -o " + (dir / "x.png").string() +
                    " --color-by no_such_attribute");
  EXPECT_EQ(r.exit_code, 1);
  if (r.err.find("without VTK") != std::string::npos) GTEST_SKIP() << "built without VTK";
  EXPECT_NE(r.err.find("no_such_attribute"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("light"), std::string::npos) << r.err;  // names what is known
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));

  r = run_fspm("render " + tree + " -o " + (dir / "x.png").string() +
               " --color-by light --view side --size 160x120 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["width"], 160);
  EXPECT_EQ(j["height"], 120);
  std::ifstream png(dir / "x.png", std::ios::binary);
  char magic[8] = {};
  png.read(magic, 8);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");

  r = run_fspm("render " + tree + " -o " + (dir / "x.png").string() + " --view back");
  EXPECT_EQ(r.exit_code, 1);
  r = run_fspm("render " + tree + " -o " + (dir / "x.png").string() + " --size 12");
  EXPECT_EQ(r.exit_code, 1);
}

// Leaf clusters of a grown tree (leaf nodes of length 0) become foliage with --leaves: 32 quads
// (64 triangles) per cluster as leaves, a sphere of 8 x 12 cells (168 triangles) as volumes.
TEST(GraphicsCli, GrownTreeFoliageAndLeaflessWarning) {
  const auto dir = scratch_dir("foliage");
  const std::string tree = (dir / "g.tree").string();
  ASSERT_EQ(run_fspm("grow --preset A --years 6 -o " + tree).exit_code, 0);
  const auto info = run_fspm("tree info " + tree + " --json");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const std::size_t clusters = nlohmann::json::parse(info.out)["leaves"].get<std::size_t>();
  ASSERT_GT(clusters, 0u);
  auto triangles = [&](const std::string& flags) {
    const auto r =
        run_fspm("mesh " + tree + " -o " + (dir / "g.ply").string() + " --json " + flags);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return nlohmann::json::parse(r.out)["triangles"].get<std::size_t>();
  };
  const std::size_t bark = triangles("");
  EXPECT_EQ(triangles("--leaves"), bark + 64 * clusters);
  EXPECT_EQ(triangles("--leaves --foliage volumes"), bark + 168 * clusters);
  auto r = run_fspm("mesh " + tree + " -o " + (dir / "g.ply").string() + " --leaves --foliage fog");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("volumes"), std::string::npos) << r.err;

  // A tree without leaves: --leaves says so in one line instead of drawing nothing quietly.
  testing::write_text(dir / "bare.l", "Axiom: FF\n");
  ASSERT_EQ(run_fspm("lsystem interpret " + (dir / "bare.l").string() + " -o " +
                     (dir / "bare.tree").string())
                .exit_code,
            0);
  r = run_fspm("mesh " + (dir / "bare.tree").string() + " -o " + (dir / "b.ply").string() +
               " --leaves");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("no leaves to draw"), std::string::npos) << r.err;
  r = run_fspm("mesh " + tree + " -o " + (dir / "g.ply").string() + " --leaves");
  EXPECT_EQ(r.err.find("no leaves to draw"), std::string::npos) << r.err;
}

// L-system leaves, polygons and predefined surfaces alike, are counted and meshed.
TEST(GraphicsCli, LsystemLeavesAreCountedAndDrawn) {
  const auto dir = scratch_dir("lsystem_leaves");
  testing::write_text(dir / "leafy.l", "Axiom: F[~l(0.3)]F[{.f(0.2)+(90)f(0.2)+(90)f(0.2).}]F\n");
  const std::string tree = (dir / "leafy.tree").string();
  auto r = run_fspm("lsystem interpret " + (dir / "leafy.l").string() + " -o " + tree + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["leaves"], 2);
  EXPECT_EQ(j["polygons"], 1);
  r = run_fspm("tree info " + tree + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["leaves"], 2);
  // Each leaf is one flat quad: 2 triangles.
  r = run_fspm("mesh " + tree + " -o " + (dir / "l.ply").string() + " --json");
  const std::size_t bare = nlohmann::json::parse(r.out)["triangles"].get<std::size_t>();
  r = run_fspm("mesh " + tree + " -o " + (dir / "l.ply").string() + " --json --leaves");
  EXPECT_EQ(nlohmann::json::parse(r.out)["triangles"].get<std::size_t>(), bare + 4);
}

TEST(GraphicsCli, ViewerScreenshot) {
  const auto dir = scratch_dir("view");
  const std::string tree = write_small_tree(dir);
  auto r = run_fspm("view " + tree + " --leaves --ages 0,2 --screenshot " +
                    (dir / "v.png").string() + " --frames 2 --size 160x120 --json");
  if (r.err.find("without the viewer") != std::string::npos ||
      r.err.find("without OpenImageIO") != std::string::npos) {
    GTEST_SKIP() << r.err;
  }
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["frames"], 2);
  EXPECT_EQ(j["triangles"], 98);  // the last growth step: tube and leaf
  EXPECT_TRUE(std::filesystem::exists(dir / "v.png"));
  r = run_fspm("view " + tree + " --color-by nope --screenshot " + (dir / "w.png").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_FALSE(std::filesystem::exists(dir / "w.png"));
}

// --frames without --screenshot: the window opens (on a virtual X server here), draws that many
// frames and closes by itself; a timeout stops a viewer that would wait for the user.
TEST(GraphicsCli, ViewerClosesAfterItsFrames) {
  const auto dir = scratch_dir("view_frames");
  const std::string tree = write_small_tree(dir);
  const auto r = run_fspm("view " + tree + " --frames 3 --size 160x120 --no-panel --json",
                          "timeout 300 xvfb-run -a ");
  if (r.err.find("without the viewer") != std::string::npos) GTEST_SKIP() << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["frames"], 3);
}

// The viewer's level-of-detail and tessellation options: what they report, and the combinations
// that mean nothing refused with exit 1 before any window opens.
TEST(GraphicsCli, ViewerImpostorsAndTessellation) {
  const auto dir = scratch_dir("view_impostors");
  const std::string tree = std::string(FSPM_SOURCE_DIR) + "/examples/trees/open_a12.treeb";
  auto r = run_fspm("view " + tree + " --tessellate 4 --tessellate-on-cpu --max-sides 4 " +
                    "--screenshot " + (dir / "t.png").string() + " --size 160x120 --json");
  if (r.err.find("without the viewer") != std::string::npos ||
      r.err.find("without OpenImageIO") != std::string::npos) {
    GTEST_SKIP() << r.err;
  }
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["tessellation"], "cpu");
  // (1 - d / D_max) L_max rounded up at the starting distance, D_max four times it: 3 of 4.
  EXPECT_EQ(j["cpu_tessellation_level"], 3);
  r = run_fspm("view " + tree + " --lod --lod-distance 0.001 --screenshot " +
               (dir / "i.png").string() + " --size 160x120 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["impostors"], 1);
  EXPECT_EQ(j["triangles"], 2);
  for (const char* args : {"--no-impostors", "--lod --tessellate 4", "--lod --full-detail",
                           "--lod --max-sides 4", "--wind --tessellate 2"}) {
    r = run_fspm("view " + tree + " " + args + " --screenshot " + (dir / "x.png").string());
    EXPECT_EQ(r.exit_code, 1) << args;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png")) << args;
  }
}

// fspm mesh --axis-subdivisions S: every internode's wall is cut into S pieces along a B-spline
// (Pirk eq. 6.7), caps and leaves unchanged, so the triangles grow linearly in S:
// T(3) - T(1) = 2 (T(2) - T(1)). Continuous junctions refuse it.
TEST(GraphicsCli, MeshAxisSubdivisionsMultiplyTheWalls) {
  const auto dir = scratch_dir("mesh_axis");
  const std::string tree = std::string(FSPM_SOURCE_DIR) + "/examples/trees/open_a12.treeb";
  std::vector<long> triangles;
  for (int s = 1; s <= 3; ++s) {
    const auto r = run_fspm("mesh " + tree + " --leaves --axis-subdivisions " + std::to_string(s) +
                            " -o " + (dir / "t.ply").string() + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    triangles.push_back(nlohmann::json::parse(r.out)["triangles"].get<long>());
  }
  EXPECT_GT(triangles[1], triangles[0]);
  EXPECT_EQ(triangles[2] - triangles[0], 2 * (triangles[1] - triangles[0]));
  for (const char* args : {"--axis-subdivisions 2 --junctions continuous", "--axis-subdivisions 0",
                           "--axis-subdivisions 17"}) {
    const auto r = run_fspm("mesh " + tree + " " + args + " -o " + (dir / "x.ply").string());
    EXPECT_EQ(r.exit_code, 1) << args;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.ply")) << args;
  }
}

// fspm view --shadow-cascades N draws N cascades and the whole scene's map once for a still
// camera; --look-at and --distance move the camera; out-of-range values are refused before any
// window opens.
TEST(GraphicsCli, ViewerShadowCascadesAndCameraPlacement) {
  const auto dir = scratch_dir("view_cascades");
  const std::string tree = std::string(FSPM_SOURCE_DIR) + "/examples/trees/open_a12.treeb";
  auto r = run_fspm("view " + tree + " --shadow-cascades 3 --frames 3 --screenshot " +
                    (dir / "c.png").string() + " --size 160x120 --json");
  if (r.err.find("without the viewer") != std::string::npos ||
      r.err.find("without OpenImageIO") != std::string::npos) {
    GTEST_SKIP() << r.err;
  }
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["shadow_maps_drawn"], 4);
  r = run_fspm("view " + tree + " --screenshot " + (dir / "a.png").string() + " --size 160x120");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Looking at a point 100 m away along +x, 5 m from it: the tree is out of the view.
  r = run_fspm("view " + tree + " --look-at 100,0,0 --distance 5 --screenshot " +
               (dir / "b.png").string() + " --size 160x120");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto bytes = [](const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_NE(bytes(dir / "a.png"), bytes(dir / "b.png"));
  for (const char* args : {"--shadow-cascades 5", "--look-at 1,2", "--distance 0"}) {
    r = run_fspm("view " + tree + " " + args + " --screenshot " + (dir / "x.png").string());
    EXPECT_EQ(r.exit_code, 1) << args;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png")) << args;
  }
}

// fspm view --stages N: N developmental stages (Pirk 5), the last one the given tree itself
// (Pirk: t = 1 gives back the input), so its triangles are those fspm mesh makes of the file.
TEST(GraphicsCli, ViewerStepsThroughDevelopmentalStages) {
  const auto dir = scratch_dir("view_stages");
  const std::string tree = std::string(FSPM_SOURCE_DIR) + "/examples/trees/open_a12.treeb";
  auto r = run_fspm("mesh " + tree + " -o " + (dir / "whole.ply").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto whole = nlohmann::json::parse(r.out)["triangles"].get<std::size_t>();
  // --full-detail: at 160 x 120 pixels the coarse meshes would take over.
  r = run_fspm("view " + tree + " --stages 5 --screenshot " + (dir / "s.png").string() +
               " --size 160x120 --full-detail --json");
  if (r.err.find("without the viewer") != std::string::npos ||
      r.err.find("without OpenImageIO") != std::string::npos) {
    GTEST_SKIP() << r.err;
  }
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["steps"], 5);
  EXPECT_EQ(j["triangles"].get<std::size_t>(), whole);  // the last stage, shown last
  // Stages of what is not a tree file, or with ages, are refused before any window.
  r = run_fspm("view " + std::string(FSPM_SOURCE_DIR) +
               "/examples/greenlab/rauh.toml --stages 3 --screenshot " + (dir / "x.png").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--stages takes tree files"), std::string::npos) << r.err;
  r = run_fspm("view " + tree + " --stages 3 --ages 1 --screenshot " + (dir / "y.png").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png") || std::filesystem::exists(dir / "y.png"));
}

// fspm view --wind plays the sway: two screenshots half a second apart differ, where the same
// two of the tree standing still are identical (the control: nothing else changes between frames).
TEST(GraphicsCli, ViewerPlaysTheWind) {
  const auto dir = scratch_dir("view_wind");
  const std::string tree = std::string(FSPM_SOURCE_DIR) + "/examples/trees/open_a12.treeb";
  const auto shot = [&](const std::string& extra, int frames, const std::string& name) {
    return run_fspm("view " + tree + extra + " --no-panel --size 160x120 --frames " +
                    std::to_string(frames) + " --screenshot " + (dir / name).string());
  };
  auto r = shot(" --wind", 1, "w1.png");
  if (r.err.find("without the viewer") != std::string::npos ||
      r.err.find("without OpenImageIO") != std::string::npos) {
    GTEST_SKIP() << r.err;
  }
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(shot(" --wind", 12, "w12.png").exit_code, 0);
  ASSERT_EQ(shot("", 1, "s1.png").exit_code, 0);
  ASSERT_EQ(shot("", 12, "s12.png").exit_code, 0);
  EXPECT_EQ(testing::read_text(dir / "s1.png"), testing::read_text(dir / "s12.png"));
  EXPECT_NE(testing::read_text(dir / "w1.png"), testing::read_text(dir / "w12.png"));
  // Wind options without --wind, or wind on more than one tree, are refused.
  r = run_fspm("view " + tree + " --wind-amplitude 20 --screenshot " + (dir / "x.png").string());
  EXPECT_EQ(r.exit_code, 1);
  r = run_fspm("view " + tree + " " + tree + " --wind --screenshot " + (dir / "y.png").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--wind sways one tree file"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace fspm
