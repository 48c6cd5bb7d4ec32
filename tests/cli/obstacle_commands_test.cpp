// fspm mesh | render --obstacles: the walls and boxes of a growth scene beside the tree.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fspm/tree_file.hpp"
#include "graphics/image.hpp"
#include "tests/cli/run_command.hpp"
#include "tests/cli/small_tree.hpp"
#include "tests/graphics/image_checks.hpp"

namespace fspm {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::run_fspm;
using testing::scratch_dir;
using testing::write_text;

using testing::write_small_tree;

// A wall across the view of the front camera (which looks along +y), 0.6 m before the trunk and
// 1.2 m high, with a ground plane that is not drawn.
std::string write_scene(const fs::path& dir) {
  const std::string path = (dir / "wall.json").string();
  write_text(path, R"({"occluders": [
    {"type": "ground", "z": 0},
    {"type": "wall", "from": [-0.6, -0.6], "to": [0.6, -0.6], "height": 1.2, "thickness": 0.1}
  ]})");
  return path;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(ObstacleCli, ObjHasTheWallsTwelveTrianglesUnderUsemtlObstacle) {
  const auto dir = scratch_dir("obstacle_obj");
  const std::string tree = write_small_tree(dir);
  const std::string scene = write_scene(dir);
  auto r = run_fspm("mesh " + tree + " --leaves -o " + (dir / "t.obj").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::size_t tree_triangles = nlohmann::json::parse(r.out)["triangles"];
  r = run_fspm("mesh " + tree + " --leaves --obstacles " + scene + " -o " +
               (dir / "w.obj").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["triangles"], tree_triangles + 12);
  EXPECT_EQ(j["obstacle_triangles"], 12);
  const std::string obj = read_text(dir / "w.obj");
  EXPECT_EQ(count(obj, "\nf "), tree_triangles + 12);
  const auto at = obj.find("usemtl obstacle\n");
  ASSERT_NE(at, std::string::npos);
  EXPECT_EQ(count(obj.substr(at), "\nf "), 12u);
  EXPECT_EQ(count(read_text(dir / "t.obj"), "usemtl obstacle"), 0u);
  for (const char* ext : {"ply", "vtp"}) {
    r = run_fspm("mesh " + tree + " --obstacles " + scene + " -o " +
                 (dir / (std::string("w.") + ext)).string());
    EXPECT_EQ(r.exit_code, 0) << ext << r.err;
  }
  r = run_fspm("mesh " + tree + " --obstacles " + scene + " -o " + (dir / "w.pvd").string());
  EXPECT_EQ(r.exit_code, 1);
  r = run_fspm("mesh " + tree + " --obstacles " + (dir / "none.json").string() + " -o " +
               (dir / "x.obj").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("none.json"), std::string::npos) << r.err;
}

TEST(ObstacleCli, GlbHasThreeMaterialsAndTheWallAsOneMorePlacedMesh) {
  const auto dir = scratch_dir("obstacle_glb");
  const std::string tree = write_small_tree(dir);
  auto r = run_fspm("mesh " + tree + " --leaves --obstacles " + write_scene(dir) + " -o " +
                    (dir / "w.glb").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["meshes"], 2);
  EXPECT_EQ(nlohmann::json::parse(r.out)["instances"], 2);
  const std::string data = read_text(dir / "w.glb");
  ASSERT_GT(data.size(), 20u);
  std::uint32_t json_len = 0;
  std::memcpy(&json_len, data.data() + 12, 4);
  const auto doc = nlohmann::json::parse(data.substr(20, json_len));
  // bark, leaf, obstacle, crown, terrain, translucent obstacle
  ASSERT_EQ(doc["materials"].size(), 6u);
  EXPECT_EQ(doc["materials"][2]["name"], "obstacle");
  std::size_t obstacle_indices = 0;
  for (const auto& mesh : doc["meshes"]) {
    for (const auto& p : mesh["primitives"]) {
      if (p["material"] != 2) continue;
      obstacle_indices +=
          doc["accessors"][p["indices"].get<std::size_t>()]["count"].get<std::size_t>();
    }
  }
  EXPECT_EQ(obstacle_indices, 36u);
}

// Pixels that differ between two images of the same size by more than a little.
std::size_t changed_pixels(const graphics::Image& a, const graphics::Image& b) {
  std::size_t n = 0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      const auto *p = a.pixel(x, y), *q = b.pixel(x, y);
      if (std::abs(p[0] - q[0]) + std::abs(p[1] - q[1]) + std::abs(p[2] - q[2]) > 30) ++n;
    }
  }
  return n;
}

using graphics::testing::stone_pixels;

TEST(ObstacleCli, RenderWithAWallBeforeTheCameraShowsTheWall) {
  const auto dir = scratch_dir("obstacle_render");
  const std::string tree = write_small_tree(dir);
  const std::string scene = write_scene(dir);
  const std::string common = " --view front --size 200x160 --no-ground --json";
  auto r = run_fspm("render " + tree + " -o " + (dir / "a.png").string() + common);
  // Without a display fspm reruns itself under xvfb-run and says so: skip only when it failed.
  if (r.exit_code != 0 && (r.err.find("without VTK") != std::string::npos ||
                           r.err.find("no X display") != std::string::npos)) {
    GTEST_SKIP() << r.err;
  }
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_fspm("render " + tree + " --obstacles " + scene + " -o " + (dir / "b.png").string() +
               common);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["obstacle_triangles"], 12);
  // The camera frames the tree and the wall: the images differ, and where they do the wall's
  // grey stone appears (an eighth of the picture or more; the bare tree has almost none).
  const graphics::Image without = graphics::read_image((dir / "a.png").string());
  const graphics::Image with = graphics::read_image((dir / "b.png").string());
  ASSERT_EQ(with.width, without.width);
  EXPECT_GT(changed_pixels(with, without), 200u * 160u / 8);
  EXPECT_LT(stone_pixels(without), 100u);
  EXPECT_GT(stone_pixels(with), 200u * 160u / 8);
  // Colouring by an attribute still works; the wall keeps its stone colour.
  r = run_fspm("render " + tree + " --obstacles " + scene + " --color-by light -o " +
               (dir / "c.png").string() + common);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(stone_pixels(graphics::read_image((dir / "c.png").string())), 200u * 160u / 8);
}

}  // namespace
}  // namespace fspm
