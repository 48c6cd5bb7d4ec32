// The terrain and population blocks of the one scene reader: values, paths, defaults, errors and
// the round trip through the writer.
#include <gtest/gtest.h>

#include <filesystem>

#include "fspm/error.hpp"
#include "fspm/scene_reader.hpp"
#include "fspm/scene_writer.hpp"

namespace fspm {
namespace {

const char* const kLandscape = R"({
  "terrain": {"heightfield": "hills.png", "metres_per_pixel": 2.5, "height_scale_m": 40,
              "stride": 2},
  "population": {
    "map": "classes.png", "min_distance_m": 3, "count": 10000, "seed": 42, "scale_jitter": 0.2,
    "classes": [
      {"value": 255, "density": 0.9,
       "plants": [{"file": "a.toml", "probability": 0.7}, {"file": "b.ctree", "probability": 0.3,
                   "age": 5}]},
      {"value": 128, "density": 0.2, "plants": [{"file": "a.toml", "probability": 1}]}
    ]
  }
})";

// The error message of parsing `text`, empty when it parses.
std::string error_of(const std::string& text) {
  try {
    parse_scene_description(text, "s.json");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(SceneLandscapeReader, ReadsTerrainAndPopulation) {
  const SceneDescription s = parse_scene_description(kLandscape, "/data/site/scene.json");
  ASSERT_TRUE(s.terrain.has_value());
  EXPECT_EQ(s.terrain->heightfield, "/data/site/hills.png");
  EXPECT_EQ(s.terrain->metres_per_pixel, 2.5);
  EXPECT_EQ(s.terrain->height_scale_m, 40.0);
  EXPECT_EQ(s.terrain->stride, 2);
  ASSERT_TRUE(s.population.has_value());
  const ScenePopulation& p = *s.population;
  EXPECT_EQ(p.map, "/data/site/classes.png");
  EXPECT_EQ(p.min_distance_m, 3.0);
  EXPECT_EQ(p.count, 10000.0);
  EXPECT_EQ(p.seed, 42u);
  EXPECT_EQ(p.scale_jitter, 0.2);
  ASSERT_EQ(p.classes.size(), 2u);
  EXPECT_EQ(p.classes[0].value, 255);
  EXPECT_EQ(p.classes[0].density, 0.9);
  ASSERT_EQ(p.classes[0].plants.size(), 2u);
  EXPECT_EQ(p.classes[0].plants[1].file, "/data/site/b.ctree");
  EXPECT_EQ(p.classes[0].plants[1].probability, 0.3);
  EXPECT_EQ(p.classes[0].plants[1].age, 5.0);
  EXPECT_EQ(p.classes[1].value, 128);
}

TEST(SceneLandscapeReader, DefaultsAreTheDocumentedOnes) {
  const SceneDescription s = parse_scene_description(
      R"({"terrain": {"heightfield": "h.png", "metres_per_pixel": 1},
          "population": {"min_distance_m": 2, "classes": [{"plants": [{"file": "a.toml",
          "probability": 1}]}]}})",
      "s.json");
  EXPECT_EQ(s.terrain->height_scale_m, 1.0);
  EXPECT_EQ(s.terrain->stride, 1);
  EXPECT_TRUE(s.population->map.empty());
  EXPECT_FALSE(s.population->count.has_value());
  EXPECT_EQ(s.population->seed, 1u);
  EXPECT_EQ(s.population->scale_jitter, 0.0);
  EXPECT_EQ(s.population->classes[0].density, 1.0);
}

TEST(SceneLandscapeReader, RejectsUnknownKeysAndBadValues) {
  const std::string terrain = R"("terrain": {"heightfield": "h.png", "metres_per_pixel": 1})";
  const std::string plants = R"("plants": [{"file": "a.toml", "probability": 1}])";
  EXPECT_NE(error_of(R"({"terrain": {"heightfield": "h.png", "metres_per_pixel": 1,
                         "heigth_scale_m": 3}})")
                .find("/terrain/heigth_scale_m"),
            std::string::npos);
  EXPECT_NE(error_of("{" + terrain + R"(, "population": {"min_distance_m": 1, "seeed": 3,
                      "classes": [{)" +
                     plants + "}]}}")
                .find("unknown key"),
            std::string::npos);
  // A population needs a terrain; probabilities must sum to 1; several classes need a map.
  EXPECT_NE(error_of(R"({"population": {"min_distance_m": 1, "classes": [{)" + plants + "}]}}")
                .find("/terrain"),
            std::string::npos);
  EXPECT_NE(error_of("{" + terrain + R"(, "population": {"min_distance_m": 1, "classes": [
                      {"plants": [{"file": "a", "probability": 0.5}]}]}})")
                .find("summing to 1"),
            std::string::npos);
  EXPECT_NE(error_of("{" + terrain + R"(, "population": {"min_distance_m": 1, "classes": [
                      {"value": 1, )" +
                     plants + R"(}, {"value": 2, )" + plants + "}]}}")
                .find("need a map"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"terrain": {"heightfield": "h.png", "metres_per_pixel": 0}})")
                .find("metres_per_pixel"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"terrain": {"heightfield": "h.png", "metres_per_pixel": 1,
                         "stride": 1.5}})")
                .find("stride"),
            std::string::npos);
}

TEST(SceneLandscapeReader, WriterKeepsTerrainAndPopulation) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "fspm_scene_landscape_writer";
  fs::create_directories(dir);
  const SceneDescription original =
      parse_scene_description(kLandscape, (dir / "scene.json").string());
  write_scene_description(original, (dir / "copy.json").string());
  const SceneDescription copy = read_scene_description((dir / "copy.json").string());
  ASSERT_TRUE(copy.terrain && copy.population);
  EXPECT_EQ(fs::path(copy.terrain->heightfield), fs::path(original.terrain->heightfield));
  EXPECT_EQ(copy.terrain->stride, 2);
  EXPECT_EQ(fs::path(copy.population->map), fs::path(original.population->map));
  EXPECT_EQ(copy.population->seed, 42u);
  EXPECT_EQ(copy.population->count, 10000.0);
  ASSERT_EQ(copy.population->classes.size(), 2u);
  EXPECT_EQ(copy.population->classes[0].plants[1].age, 5.0);
  EXPECT_EQ(copy.population->classes[1].density, 0.2);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fspm
