// The one scene reader: the current layout, the two earlier ones, the upgrade writer, errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "fspm/error.hpp"
#include "fspm/json_location.hpp"
#include "fspm/scene_reader.hpp"
#include "fspm/scene_writer.hpp"

namespace fspm {
namespace {

namespace fs = std::filesystem;

const char* const kCurrent = R"({
  "fspm_scene": 2,
  "comment": "a site",
  "sky": {"sun": {"elevation_deg": 40, "azimuth_deg": 180}, "directions": 64},
  "gamma0": 0.4,
  "ground": {"z": -0.5},
  "obstacles": [
    {"type": "wall", "from": [2, -3], "to": [2, 3], "height": 4, "translucency": 0.3},
    {"type": "box", "min": [0, 0, 0], "max": [1, 2, 4], "solid": false},
    {"type": "cluster", "center": [0, 0, 5], "radius": 0.5},
    {"type": "mesh", "vertices": [[0,0,3],[1,0,3],[0,1,3]], "triangles": [[0,1,2]]}
  ],
  "plants": [
    {"file": "trees/oak.tree", "position": [1, 2, 0], "rotation_deg": 30, "age": 7},
    {"file": "/abs/birch.ctree", "rotation_deg": [10, 0, 0], "scale": 2}
  ]
})";

TEST(SceneReader, ReadsTheCurrentLayout) {
  const SceneDescription s = parse_scene_description(kCurrent, "/data/site/scene.json");
  EXPECT_EQ(s.comment, "a site");
  EXPECT_EQ(s.sky.source, SkySource::kSun);
  EXPECT_EQ(s.sky.sun_elevation_deg, 40.0);
  EXPECT_EQ(s.sky.sun_azimuth_deg, 180.0);
  EXPECT_EQ(s.sky.directions, 64);
  EXPECT_FALSE(s.sky.significance.has_value());
  EXPECT_EQ(s.gamma0, 0.4);
  ASSERT_TRUE(s.ground.has_value());
  EXPECT_EQ(s.ground->height_m, -0.5);
  ASSERT_EQ(s.obstacles.size(), 4u);
  const auto& wall = std::get<WallObstacle>(s.obstacles[0].shape);
  EXPECT_EQ(wall.from, Eigen::Vector2d(2, -3));
  EXPECT_EQ(wall.height_m, 4.0);
  EXPECT_EQ(wall.thickness_m, 0.2);  // the documented default
  EXPECT_EQ(s.obstacles[0].surface.translucency, 0.3);
  const auto& box = std::get<BoxObstacle>(s.obstacles[1].shape);
  EXPECT_EQ(box.center, Eigen::Vector3d(0.5, 1, 2));  // min/max as centre and size
  EXPECT_EQ(box.size_m, Eigen::Vector3d(1, 2, 4));
  EXPECT_EQ(s.obstacles[1].surface.solid, false);
  EXPECT_TRUE(std::get<SphereObstacle>(s.obstacles[2].shape).cluster);
  EXPECT_FALSE(s.obstacles[2].surface.translucency.has_value());  // Pirk eq. 4.4 later
  EXPECT_EQ(std::get<MeshObstacle>(s.obstacles[3].shape).triangles[0], Eigen::Vector3i(0, 1, 2));
  ASSERT_EQ(s.plants.size(), 2u);
  EXPECT_EQ(s.plants[0].file, "/data/site/trees/oak.tree");
  EXPECT_EQ(s.plants[0].rotation_deg, Eigen::Vector3d(0, 0, 30));
  EXPECT_EQ(s.plants[0].age, 7.0);
  EXPECT_EQ(s.plants[1].file, "/abs/birch.ctree");
  EXPECT_EQ(s.plants[1].rotation_deg, Eigen::Vector3d(10, 0, 0));
  EXPECT_EQ(s.plants[1].scale, 2.0);
  EXPECT_FALSE(s.plants[1].age.has_value());
}

TEST(SceneReader, ReadsBothEarlierLayouts) {
  // Growth scene: the ground among the occluders.
  const SceneDescription g = parse_scene_description(R"({"sky": {"brightest": [0, 0, 2]},
      "occluders": [{"type": "ground", "z": 1}, {"type": "sphere", "center": [0, 0, 3],
      "radius": 1, "translucency": 0}]})");
  ASSERT_TRUE(g.ground.has_value());
  EXPECT_EQ(g.ground->height_m, 1.0);
  ASSERT_EQ(g.obstacles.size(), 1u);
  EXPECT_FALSE(std::get<SphereObstacle>(g.obstacles[0].shape).cluster);
  EXPECT_EQ(g.sky.brightest, Eigen::Vector3d(0, 0, 2));
  EXPECT_TRUE(g.plants.empty());
  // Plant scene, version 1.
  const SceneDescription p = parse_scene_description(
      R"({"fspm_scene": 1, "instances": [{"file": "a.tree", "position": [3, 0, 0]}]})",
      "dir/s.json");
  ASSERT_EQ(p.plants.size(), 1u);
  EXPECT_EQ(p.plants[0].file, "dir/a.tree");
  EXPECT_EQ(p.plants[0].position, Eigen::Vector3d(3, 0, 0));
  EXPECT_TRUE(p.obstacles.empty());
  EXPECT_FALSE(p.ground.has_value());
}

void expect_same(const SceneDescription& a, const SceneDescription& b) {
  EXPECT_EQ(a.comment, b.comment);
  EXPECT_EQ(a.sky.source, b.sky.source);
  EXPECT_EQ(a.sky.sun_elevation_deg, b.sky.sun_elevation_deg);
  EXPECT_EQ(a.sky.directions, b.sky.directions);
  EXPECT_EQ(a.gamma0, b.gamma0);
  ASSERT_EQ(a.ground.has_value(), b.ground.has_value());
  if (a.ground) {
    EXPECT_EQ(a.ground->height_m, b.ground->height_m);
  }
  ASSERT_EQ(a.obstacles.size(), b.obstacles.size());
  for (std::size_t i = 0; i < a.obstacles.size(); ++i) {
    EXPECT_EQ(a.obstacles[i].shape.index(), b.obstacles[i].shape.index()) << i;
    EXPECT_EQ(a.obstacles[i].surface.translucency, b.obstacles[i].surface.translucency) << i;
    EXPECT_EQ(a.obstacles[i].surface.solid, b.obstacles[i].surface.solid) << i;
  }
  const auto& wa = std::get<WallObstacle>(a.obstacles[0].shape);
  const auto& wb = std::get<WallObstacle>(b.obstacles[0].shape);
  EXPECT_EQ(wa.to, wb.to);
  EXPECT_EQ(wa.thickness_m, wb.thickness_m);
  EXPECT_EQ(std::get<BoxObstacle>(a.obstacles[1].shape).center,
            std::get<BoxObstacle>(b.obstacles[1].shape).center);
  EXPECT_EQ(std::get<SphereObstacle>(a.obstacles[2].shape).cluster,
            std::get<SphereObstacle>(b.obstacles[2].shape).cluster);
  EXPECT_EQ(std::get<MeshObstacle>(a.obstacles[3].shape).vertices,
            std::get<MeshObstacle>(b.obstacles[3].shape).vertices);
  ASSERT_EQ(a.plants.size(), b.plants.size());
  for (std::size_t i = 0; i < a.plants.size(); ++i) {
    EXPECT_EQ(fs::weakly_canonical(a.plants[i].file), fs::weakly_canonical(b.plants[i].file));
    EXPECT_EQ(a.plants[i].rotation_deg, b.plants[i].rotation_deg);
    EXPECT_EQ(a.plants[i].scale, b.plants[i].scale);
    EXPECT_EQ(a.plants[i].age, b.plants[i].age);
  }
}

TEST(SceneReader, UpgradedSceneReadsBackTheSame) {
  const fs::path dir = fs::temp_directory_path() / "fspm_scene_reader_test";
  fs::create_directories(dir / "out");
  const std::string original_path = (dir / "scene.json").string();
  const SceneDescription original = parse_scene_description(kCurrent, original_path);
  // Written one directory down: the relative plant file must still name the same file.
  const std::string upgraded_path = (dir / "out" / "scene.json").string();
  write_scene_description(original, upgraded_path);
  const SceneDescription upgraded = read_scene_description(upgraded_path);
  expect_same(original, upgraded);
  EXPECT_EQ(fs::path(upgraded.plants[0].file).lexically_normal(),
            (dir / "trees" / "oak.tree").lexically_normal());
  fs::remove_all(dir);
}

// The error of parsing `text` as file "s.json".
Error error_of(const std::string& text) {
  try {
    parse_scene_description(text, "s.json");
  } catch (const Error& e) {
    return e;
  }
  return Error("no error");
}

TEST(SceneReader, ErrorsNameFileLinePathAndExpectation) {
  // Line 3 holds the misspelt key.
  Error e = error_of(
      "{\"obstacles\": [\n  {\"type\": \"wall\", \"from\": [0, 0], \"to\": [1, 0],\n"
      "   \"heigth\": 2}]}");
  EXPECT_EQ(e.file(), "s.json");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.column(), 4);
  EXPECT_NE(e.message().find("/obstacles/0/heigth"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("unknown key"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("did you mean 'height'"), std::string::npos) << e.what();
  // A missing key: the line of the object that lacks it.
  e = error_of("{\n\"plants\": [\n\n  {\"position\": [0, 0, 0]}]}");
  EXPECT_EQ(e.line(), 4);
  EXPECT_NE(e.message().find("/plants/0/file"), std::string::npos) << e.what();
  // A ground among the current layout's obstacles, mixing layouts, a later version.
  EXPECT_NE(error_of(R"({"obstacles": [{"type": "ground"}]})").message().find("sphere"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"obstacles": [], "occluders": []})").message().find("only one of"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"fspm_scene": 3})").message().find("version"), std::string::npos);
  EXPECT_NE(error_of(R"({"trees": []})").message().find("plants"), std::string::npos);
  EXPECT_EQ(error_of(R"({"plants": [{"file": "a", "scale": 0}]})").line(), 1);
  EXPECT_THROW(parse_scene_description("{\n\"sky\": {,}}", "s.json"), ParseError);
}

// A value that is not an object where one belongs (a fuzzing finding: {"ground":1} ended the
// process in the key check): refused, naming the path.
TEST(SceneReader, ANumberWhereAnObjectBelongsIsRefused) {
  for (const char* text : {R"({"ground": 1})", R"({"sky": [1]})", R"({"sky": {"sun": 2}})",
                           R"({"obstacles": [3]})", R"({"plants": ["a"]})", "[1]", "7"}) {
    SCOPED_TRACE(text);
    const Error e = error_of(text);
    EXPECT_NE(e.message().find("expected "), std::string::npos) << e.what();
    EXPECT_NE(e.message().find(" object"), std::string::npos) << e.what();
  }
}

TEST(SceneReader, ExampleScenesReadWithTheirPlantFiles) {
  const std::string examples = std::string(FSPM_SOURCE_DIR) + "/examples/";
  const SceneDescription site = read_scene_description(examples + "environment/site_scene.json");
  EXPECT_EQ(site.obstacles.size(), 2u);
  ASSERT_EQ(site.plants.size(), 1u);
  EXPECT_TRUE(fs::exists(site.plants[0].file)) << site.plants[0].file;
  const SceneDescription forest = read_scene_description(examples + "graphics/forest_scene.json");
  EXPECT_EQ(forest.plants.size(), 200u);
  for (const char* file :
       {"environment/wall_scene.json", "environment/sphere_and_box_scene.json"}) {
    EXPECT_FALSE(read_scene_description(examples + file).obstacles.empty()) << file;
  }
}

TEST(JsonLocation, FindsKeysAndElementsByHand) {
  const std::string text = "{\"a\": [1,\n  {\"b\": \"x,]\", \"c\": 2}],\n \"d\": {}}";
  EXPECT_EQ(json_pointer_position(text, "/a").line, 1);
  EXPECT_EQ(json_pointer_position(text, "/a").column, 2);  // the key "a"
  const TextPosition c = json_pointer_position(text, "/a/1/c");
  EXPECT_EQ(c.line, 2);
  EXPECT_EQ(c.column, 16);  // past a string holding , and ]
  EXPECT_EQ(json_pointer_position(text, "/d").line, 3);
  // Missing: the deepest place that exists (the element /a/1).
  const TextPosition missing = json_pointer_position(text, "/a/1/z");
  EXPECT_EQ(missing.line, 2);
  EXPECT_EQ(missing.column, 3);
}

}  // namespace
}  // namespace fspm
