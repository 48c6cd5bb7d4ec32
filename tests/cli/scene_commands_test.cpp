// One scene for every command: renders and meshes of a scene file draw its obstacles, light reads
// it, and fspm scene upgrade rewrites the earlier layouts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "graphics/image.hpp"
#include "tests/cli/run_command.hpp"
#include "tests/cli/small_tree.hpp"
#include "tests/graphics/image_checks.hpp"

namespace fspm {
namespace {

namespace fs = std::filesystem;
using graphics::testing::stone_pixels;
using testing::read_text;
using testing::run_fspm;
using testing::scratch_dir;
using testing::write_small_tree;
using testing::write_text;

// The small tree (2 m tall at the origin) with, when `wall`, a wall 1.2 m high across the front
// camera's view, 0.6 m before the trunk.
std::string write_tree_scene(const fs::path& dir, bool wall) {
  write_small_tree(dir);
  const std::string path = (dir / (wall ? "walled.json" : "open.json")).string();
  write_text(path, std::string(R"({"fspm_scene": 2, "ground": {"z": 0}, "obstacles": [)") +
                       (wall ? R"({"type": "wall", "from": [-0.6, -0.6], "to": [0.6, -0.6],
                                  "height": 1.2, "thickness": 0.1})"
                             : "") +
                       R"(], "plants": [{"file": "t.tree"}]})");
  return path;
}

bool no_renderer(const testing::CommandResult& r) {
  return r.exit_code != 0 && (r.err.find("without VTK") != std::string::npos ||
                              r.err.find("no X display") != std::string::npos);
}

TEST(SceneCli, RenderOfAScenePlantBesideAWallShowsTheWall) {
  const auto dir = scratch_dir("scene_render");
  const std::string common = " --view front --size 200x160 --no-ground";
  auto r = run_fspm("render " + write_tree_scene(dir, false) + " -o " +
                    (dir / "open.png").string() + common);
  if (no_renderer(r)) GTEST_SKIP() << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_fspm("render " + write_tree_scene(dir, true) + " -o " + (dir / "walled.png").string() +
               common);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The wall covers the lower part of the framed tree: an eighth of the picture or more in stone.
  EXPECT_LT(stone_pixels(graphics::read_image((dir / "open.png").string())), 100u);
  EXPECT_GT(stone_pixels(graphics::read_image((dir / "walled.png").string())), 200u * 160u / 8);
}

// The height of a mesh: the z extent of its OBJ vertices.
double obj_height(const std::string& obj) {
  std::istringstream in(obj);
  std::string line;
  double lo = 1e300, hi = -1e300;
  while (std::getline(in, line)) {
    if (line.rfind("v ", 0) != 0) continue;
    std::istringstream v(line.substr(2));
    double x = 0, y = 0, z = 0;
    v >> x >> y >> z;
    lo = std::min(lo, z);
    hi = std::max(hi, z);
  }
  return hi - lo;
}

// A measured plant (MTG) in a scene carries its units: the same plant read in centimetres and
// millimetres is a hundredth of its size read in metres, and `scene upgrade` keeps the units.
TEST(SceneCli, MtgPlantOfASceneIsReadInItsUnits) {
  const auto dir = scratch_dir("scene_mtg_units");
  const std::string mtg = std::string(FSPM_SOURCE_DIR) + "/examples/mtg/boutdenoylum2.mtg";
  write_text(dir / "cm.json", R"({"fspm_scene": 2, "plants": [{"file": ")" + mtg +
                                  R"(", "length_unit": "cm", "diameter_unit": "mm"}]})");
  write_text(dir / "m.json", R"({"fspm_scene": 2, "plants": [{"file": ")" + mtg + R"("}]})");
  auto r = run_fspm("-q mesh " + (dir / "cm.json").string() + " -o " + (dir / "cm.obj").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("--length-unit"), std::string::npos) << r.err;
  r = run_fspm("mesh " + (dir / "m.json").string() + " -o " + (dir / "m.obj").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("--length-unit cm"), std::string::npos) << r.err;
  const double cm = obj_height(read_text(dir / "cm.obj"));
  const double m = obj_height(read_text(dir / "m.obj"));
  EXPECT_GT(cm, 1.0);
  EXPECT_LT(cm, 10.0);
  // Radii scale by 1/1000 and lengths by 1/100, so the heights agree to the trunk's thickness.
  EXPECT_NEAR(cm, m / 100.0, 0.2);
  r = run_fspm("scene upgrade " + (dir / "cm.json").string() + " -o " + (dir / "up.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto up = nlohmann::json::parse(read_text(dir / "up.json"));
  EXPECT_EQ(up["plants"][0]["length_unit"], "cm");
  EXPECT_EQ(up["plants"][0]["diameter_unit"], "mm");
}

TEST(SceneCli, RenderOfAGrowthSceneWithoutPlantsDrawsItsObstacles) {
  const auto dir = scratch_dir("scene_render_walls");
  const std::string scene = (dir / "wall.json").string();
  write_text(scene, R"({"sky": {"brightest": [0, 0, 1]}, "occluders": [{"type": "ground", "z": 0},
      {"type": "wall", "from": [2.5, -20], "to": [2.5, 20], "height": 6, "thickness": 0.2}]})");
  auto r = run_fspm("render " + scene + " -o " + (dir / "w.png").string() +
                    " --view iso --size 200x160");
  if (no_renderer(r)) GTEST_SKIP() << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(stone_pixels(graphics::read_image((dir / "w.png").string())), 200u * 160u / 10);
}

std::size_t faces_after(const std::string& obj, const std::string& material) {
  const auto at = obj.find("usemtl " + material + "\n");
  if (at == std::string::npos) return 0;
  std::size_t n = 0;
  const auto end = obj.find("usemtl", at + 1);
  for (auto f = obj.find("\nf ", at); f < end && f != std::string::npos;
       f = obj.find("\nf ", f + 1)) {
    ++n;
  }
  return n;
}

TEST(SceneCli, MeshOfASceneHasItsOpaqueAndTranslucentObstaclesWhole) {
  const auto dir = scratch_dir("scene_mesh");
  write_small_tree(dir);
  const std::string scene = (dir / "s.json").string();
  write_text(scene, R"({"fspm_scene": 2, "obstacles": [
      {"type": "wall", "from": [30, -20], "to": [30, 20], "height": 6},
      {"type": "box", "center": [0, 3, 1], "size": [1, 1, 2], "translucency": 0.5}],
      "plants": [{"file": "t.tree"}]})");
  auto r = run_fspm("mesh " + scene + " -o " + (dir / "s.obj").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["obstacle_triangles"], 24);
  const std::string obj = read_text(dir / "s.obj");
  EXPECT_EQ(faces_after(obj, "obstacle"), 12u);  // the far wall too: mesh files keep everything
  EXPECT_EQ(faces_after(obj, "translucent_obstacle_0.5"), 12u);  // named by its translucency
}

// Each translucent obstacle gets a glTF material of alpha 1 - gamma: two walls letting 30 % and
// 60 % of the light through are blended at 0.7 and 0.4, an opaque one stays in stone.
TEST(SceneCli, GlbGivesEachTranslucentObstacleItsOwnAlpha) {
  const auto dir = scratch_dir("scene_glb_alpha");
  write_small_tree(dir);
  const std::string scene = (dir / "s.json").string();
  const double gamma_a = 0.3, gamma_b = 0.6;
  write_text(scene, R"({"fspm_scene": 2, "obstacles": [
      {"type": "wall", "from": [3, -2], "to": [3, 2], "height": 2, "translucency": 0.3},
      {"type": "wall", "from": [-3, -2], "to": [-3, 2], "height": 2, "translucency": 0.6},
      {"type": "wall", "from": [-2, 3], "to": [2, 3], "height": 2}],
      "plants": [{"file": "t.tree"}]})");
  const auto r = run_fspm("mesh " + scene + " -o " + (dir / "s.glb").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string glb = read_text(dir / "s.glb");
  ASSERT_GT(glb.size(), 20u);
  std::uint32_t json_bytes = 0;
  std::memcpy(&json_bytes, glb.data() + 12, 4);
  const auto doc = nlohmann::json::parse(glb.substr(20, json_bytes));
  // The alphas of the materials the obstacle primitives use, with their index counts.
  std::map<double, std::size_t> alpha_indices;
  for (const auto& mesh : doc["meshes"]) {
    if (mesh["name"] != "obstacles") continue;
    for (const auto& prim : mesh["primitives"]) {
      ASSERT_TRUE(prim.contains("material"));
      const auto& material = doc["materials"][prim["material"].get<std::size_t>()];
      const double alpha = material["pbrMetallicRoughness"]["baseColorFactor"][3].get<double>();
      if (alpha < 1.0) {
        EXPECT_EQ(material["alphaMode"], "BLEND");
      }
      alpha_indices[std::round(alpha * 1000.0) / 1000.0] +=
          doc["accessors"][prim["indices"].get<std::size_t>()]["count"].get<std::size_t>();
    }
  }
  const std::map<double, std::size_t> expected = {
      {std::round((1.0 - gamma_b) * 1000.0) / 1000.0, 36},  // 12 triangles a wall
      {std::round((1.0 - gamma_a) * 1000.0) / 1000.0, 36},
      {1.0, 36}};
  EXPECT_EQ(alpha_indices, expected);
  // The .obj's material library: one material per translucency, dissolve d = 1 - gamma.
  ASSERT_EQ(run_fspm("mesh " + scene + " -o " + (dir / "s.obj").string()).exit_code, 0);
  const std::string mtl = read_text(dir / "s.mtl");
  for (const double gamma : {gamma_a, gamma_b}) {
    std::ostringstream name;
    name << "newmtl translucent_obstacle_" << gamma << "\n";
    const auto at = mtl.find(name.str());
    ASSERT_NE(at, std::string::npos) << name.str();
    const auto d = mtl.find("\nd ", at);
    ASSERT_NE(d, std::string::npos);
    EXPECT_NEAR(std::stod(mtl.substr(d + 3, 8)), 1.0 - gamma, 1e-6);
  }
}

TEST(SceneCli, UpgradeRewritesEarlierLayoutsWithTheSameLight) {
  const auto dir = scratch_dir("scene_upgrade");
  const std::string old_scene = (dir / "old.json").string();
  const std::string old_text = R"({"gamma0": 0.3, "occluders": [{"type": "ground"},
      {"type": "cluster", "center": [0, 0, 3], "radius": 1},
      {"type": "box", "min": [1, -2, 0], "max": [1.5, 2, 4]}]})";
  write_text(old_scene, old_text);
  write_text(dir / "points.csv", "x,y,z\n0,0,0\n2,0,1\n-1,1,0.5\n");
  const std::string upgraded = (dir / "new.json").string();
  auto r = run_fspm("scene upgrade " + old_scene + " -o " + upgraded + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["obstacles"], 2);
  EXPECT_EQ(nlohmann::json::parse(r.out)["layout"], "occluders");
  const auto doc = nlohmann::json::parse(read_text(upgraded));
  EXPECT_EQ(doc["fspm_scene"], 2);
  EXPECT_FALSE(doc.contains("occluders"));
  EXPECT_EQ(doc["ground"]["z"], 0.0);
  const std::string points = " --points " + (dir / "points.csv").string();
  const auto before = run_fspm("light --scene " + old_scene + points);
  const auto after = run_fspm("light --scene " + upgraded + points);
  ASSERT_EQ(before.exit_code, 0) << before.err;
  ASSERT_EQ(after.exit_code, 0) << after.err;
  EXPECT_EQ(after.out, before.out);
  EXPECT_NE(before.out.find("\n2,0,1,"), std::string::npos);  // the light was computed
  // Never over the input, which stays as it was.
  r = run_fspm("scene upgrade " + old_scene + " -o " + old_scene);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(read_text(old_scene), old_text);
}

// Every scene file shipped with fspm (examples/) is in the one current layout: an
// example in an earlier layout fails here with its name. `scene upgrade` reads each, so each is
// also a valid scene.
TEST(SceneCli, EveryShippedSceneIsInTheCurrentLayout) {
  const auto dir = scratch_dir("scene_examples");
  int scenes = 0;
  const fs::path examples = fs::path(FSPM_SOURCE_DIR) / "examples";
  for (const auto& e : fs::recursive_directory_iterator(examples)) {
    if (e.path().extension() != ".json" ||
        e.path().string().find("/downstream/") != std::string::npos) {
      continue;
    }
    const auto r = run_fspm("scene upgrade " + e.path().string() + " -o " +
                            (dir / "up.json").string() + " --json");
    ASSERT_EQ(r.exit_code, 0) << e.path() << ": " << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["layout"], "current")
        << e.path() << " is in an earlier layout: rewrite it with fspm scene upgrade";
    ++scenes;
  }
  EXPECT_GE(scenes, 6);  // wall, sphere and box, site, forest, landscape, the experiment's wall
}

}  // namespace
}  // namespace fspm
