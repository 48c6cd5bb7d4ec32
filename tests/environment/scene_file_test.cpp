#include "environment/scene_file.hpp"

#include <gtest/gtest.h>

#include "environment/points_file.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_scene_json(text, "scene.json");
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(SceneFile, ParsesASphereAndABox) {
  const Scene s =
      parse_scene_json(R"({ "sky": { "model": "cos2", "brightest": [0, 0, 1], "directions": 256 },
    "occluders": [
      { "type": "sphere", "center": [0, 0, 5], "radius": 1.0, "translucency": 0.0 },
      { "type": "box", "min": [2, -5, 0], "max": [2.5, 5, 6], "translucency": 0.0 } ] })");
  ASSERT_EQ(s.spheres.size(), 1u);
  ASSERT_EQ(s.boxes.size(), 1u);
  EXPECT_EQ(s.sky.directions, 256);
  EXPECT_TRUE(s.boxes[0].contains({2.2, 0, 3}));
  EXPECT_FALSE(s.boxes[0].contains({1.9, 0, 3}));
}

TEST(SceneFile, ClusterTranslucencyDefaultsToPirkEq44) {
  const Scene s = parse_scene_json(R"({"occluders": [
      {"type": "cluster", "center": [0, 0, 5], "radius": 2},
      {"type": "cluster", "center": [0, 0, 5], "radius": 2, "gamma0": 0.8},
      {"type": "wall", "from": [0, 0], "to": [4, 0], "height": 3},
      {"type": "ground", "z": -1},
      {"type": "box", "center": [0, 0, 1], "size": [2, 2, 2], "axis": [0, 0, 1], "angle_deg": 45},
      {"type": "mesh", "vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,2]]}]})");
  EXPECT_DOUBLE_EQ(s.spheres[0].translucency, 0.25);
  EXPECT_DOUBLE_EQ(s.spheres[1].translucency, 0.64);
  EXPECT_TRUE(s.boxes[0].contains({2, 0, 1}));
  EXPECT_TRUE(s.boxes[1].contains({1.3, 0, 1}));  // rotated 45 deg: corner reaches x = sqrt 2
  ASSERT_TRUE(s.ground.has_value());
  EXPECT_TRUE(s.inside_solid({0, 5, -2}));
  EXPECT_EQ(s.meshes.size(), 1u);
}

TEST(SceneFile, SunFromLatitudeAndFromElevation) {
  const Scene a = parse_scene_json(R"({"sky": {"latitude_deg": 50, "day_of_year": 172}})");
  EXPECT_LT(a.sky.brightest.y(), 0.0);
  const Scene b = parse_scene_json(R"({"sky": {"sun": {"elevation_deg": 0, "azimuth_deg": 90}}})");
  EXPECT_NEAR(b.sky.brightest.x(), 1.0, 1e-12);
}

TEST(SceneFile, BadInputNamesFilePathAndExpectation) {
  std::string m =
      error_of(R"({"occluders": [{"type": "sphere", "center": [0,0,0], "radius": -1}]})");
  EXPECT_NE(m.find("scene.json"), std::string::npos) << m;
  EXPECT_NE(m.find("/occluders/0/radius"), std::string::npos) << m;
  EXPECT_NE(m.find("non-negative radius"), std::string::npos) << m;

  m = error_of(R"({"occluders": [{"type": "box", "min": [0,0,0], "max": [1,1,1]},
      {"type": "sphere", "center": [0,0,0], "radius": 1, "translucency": 1.5}]})");
  EXPECT_NE(m.find("/occluders/1/translucency"), std::string::npos) << m;
  EXPECT_NE(m.find("[0, 1]"), std::string::npos) << m;

  m = error_of(
      "{\"occluders\": [\n {\"type\": \"sphere\", \"center\": [0,0,NaN], \"radius\": 1}]}");
  EXPECT_NE(m.find("scene.json:2:"), std::string::npos) << m;

  m = error_of(R"({"occluders": [{"type": "cone"}]})");
  EXPECT_NE(m.find("/occluders/0/type"), std::string::npos) << m;
  EXPECT_NE(m.find("sphere"), std::string::npos) << m;

  m = error_of(R"({"sky": {"directions": 0}})");
  EXPECT_NE(m.find("/sky/directions"), std::string::npos) << m;

  m = error_of(R"({"occluders": [{"type": "sphere", "centre": [0,0,0], "radius": 1}]})");
  EXPECT_NE(m.find("/occluders/0/centre"), std::string::npos) << m;
}

TEST(PointsFile, ParsesAndRejectsBadRows) {
  const auto pts = parse_points_csv("x,y,z\n1,2,3\n\n4.5, -1e2 ,0\n", "p.csv");
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_EQ(pts[1], Eigen::Vector3d(4.5, -100, 0));
  try {
    parse_points_csv("x,y,z\n1,2,3\n1,abc,3\n", "p.csv");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "p.csv");
    EXPECT_EQ(e.line(), 3);
    EXPECT_NE(std::string(e.what()).find("column y"), std::string::npos);
  }
  EXPECT_THROW(parse_points_csv("x,y\n1,2\n", "p.csv"), ParseError);
  EXPECT_THROW(parse_points_csv("x,y,z\n1,2\n", "p.csv"), ParseError);
  EXPECT_THROW(parse_points_csv("x,y,z\n1,2,nan\n", "p.csv"), ParseError);
}

}  // namespace
}  // namespace fspm::environment
