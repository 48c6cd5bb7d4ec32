// Plants spread over a terrain: minimum distance by brute force over all pairs, inside the
// terrain, plant frequencies within a binomial bound of their probabilities, classes from the
// map, the same seed giving the same plants, and every plant standing on the terrain (a planar
// terrain, whose height at any point is the plane's formula).
#include "graphics/population.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "fspm/error.hpp"
#include "graphics/poisson_disk.hpp"

namespace fspm::graphics {
namespace {

constexpr double kMetresPerPixel = 1.5;
constexpr double kHeightScale = 20.0;
constexpr int kColumns = 41, kRows = 31;

// Grey value (i + 2 j) / 100 at column i, row j from the top: heights on a plane.
Heightfield planar_terrain() {
  FloatImage image;
  image.width = kColumns;
  image.height = kRows;
  for (int j = 0; j < kRows; ++j) {
    for (int i = 0; i < kColumns; ++i) image.values.push_back((i + 2.0f * j) / 100.0f);
  }
  return Heightfield(image, kMetresPerPixel, kHeightScale);
}

// The plane through the samples: i = x / s, j = rows - 1 - y / s.
double plane_height(double x, double y) {
  return kHeightScale * (x / kMetresPerPixel + 2.0 * (kRows - 1 - y / kMetresPerPixel)) / 100.0;
}

ScenePopulation one_class(std::vector<std::pair<std::string, double>> plants) {
  ScenePopulation p;
  p.min_distance_m = 2.0;
  p.seed = 7;
  PopulationClass c;
  for (const auto& [file, probability] : plants) c.plants.push_back({file, probability, {}});
  p.classes.push_back(c);
  return p;
}

std::vector<ScenePlant> place(const ScenePopulation& p, const Heightfield& terrain,
                              const FloatImage* map = nullptr) {
  std::mt19937_64 rng(p.seed);
  return place_population(p, terrain, map, rng);
}

TEST(Population, NoTwoPlantsCloserThanTheMinimumDistanceAllInside) {
  const Heightfield terrain = planar_terrain();
  const std::vector<ScenePlant> plants = place(one_class({{"a", 1.0}}), terrain);
  // 60 m x 45 m at 2 m: random sequential adsorption jams at 0.547 of the area covered by disks
  // of radius 1 m, about 470 sites; the darts come close to it.
  ASSERT_GT(plants.size(), 300u);
  double closest = 1e9;
  for (std::size_t a = 0; a < plants.size(); ++a) {
    for (std::size_t b = a + 1; b < plants.size(); ++b) {
      closest = std::min(closest, (plants[a].position - plants[b].position).head<2>().norm());
    }
  }
  EXPECT_GE(closest, 2.0);
  for (const ScenePlant& p : plants) {
    EXPECT_GE(p.position.x(), 0.0);
    EXPECT_LE(p.position.x(), terrain.width_m());
    EXPECT_GE(p.position.y(), 0.0);
    EXPECT_LE(p.position.y(), terrain.depth_m());
  }
}

TEST(Population, PlantsStandOnTheTerrain) {
  ScenePopulation p = one_class({{"a", 1.0}});
  p.scale_jitter = 0.3;
  for (const ScenePlant& plant : place(p, planar_terrain())) {
    EXPECT_NEAR(plant.position.z(), plane_height(plant.position.x(), plant.position.y()), 1e-5);
    EXPECT_GE(plant.scale, 0.7);
    EXPECT_LE(plant.scale, 1.3);
    EXPECT_GE(plant.rotation_deg.z(), 0.0);
    EXPECT_LT(plant.rotation_deg.z(), 360.0);
    EXPECT_EQ(plant.rotation_deg.head<2>(), Eigen::Vector2d::Zero());  // upright
  }
}

TEST(Population, PlantFrequenciesFollowTheirProbabilities) {
  ScenePopulation p = one_class({{"a", 0.5}, {"b", 0.3}, {"c", 0.2}});
  p.min_distance_m = 0.5;  // about 10 000 plants
  const std::vector<ScenePlant> plants = place(p, planar_terrain());
  const double n = static_cast<double>(plants.size());
  ASSERT_GT(n, 5000.0);
  std::map<std::string, double> count;
  for (const ScenePlant& plant : plants) count[plant.file] += 1.0;
  for (const auto& [file, probability] : {std::pair{"a", 0.5}, {"b", 0.3}, {"c", 0.2}}) {
    // Binomial(n, p): within 4.5 standard deviations (a false alarm about once in 150 000).
    EXPECT_NEAR(count[file], n * probability, 4.5 * std::sqrt(n * probability * (1 - probability)))
        << file;
  }
}

TEST(Population, ClassMapChoosesWherePlantsGrowAndWhich) {
  // 2 x 2 map over the terrain: north-west grey 255, north-east 128, south row 0 (no class).
  FloatImage map;
  map.width = 2;
  map.height = 2;
  map.values = {1.0f, 128.0f / 255.0f, 0.0f, 0.0f};
  ScenePopulation p = one_class({{"pine", 1.0}});
  p.map = "map.png";
  p.classes[0].value = 255;
  PopulationClass birch;
  birch.value = 128;
  birch.plants.push_back({"birch", 1.0, {}});
  p.classes.push_back(birch);
  const Heightfield terrain = planar_terrain();
  const std::vector<ScenePlant> plants = place(p, terrain, &map);
  ASSERT_GT(plants.size(), 100u);
  std::size_t pines = 0;
  for (const ScenePlant& plant : plants) {
    const bool north = plant.position.y() >= terrain.depth_m() / 2;
    const bool west = plant.position.x() < terrain.width_m() / 2;
    EXPECT_TRUE(north) << plant.position.transpose();
    EXPECT_EQ(plant.file, west ? "pine" : "birch");
    pines += plant.file == "pine";
  }
  EXPECT_GT(pines, 0u);
  EXPECT_LT(pines, plants.size());
  EXPECT_EQ(class_value_at(map, terrain, 1.0, terrain.depth_m() - 1.0), 255);
  EXPECT_EQ(class_value_at(map, terrain, terrain.width_m() - 1.0, terrain.depth_m()), 128);
  EXPECT_EQ(class_value_at(map, terrain, 1.0, 1.0), 0);
}

TEST(Population, SameSeedSamePlantsAndCountIsAnUpperBound) {
  const Heightfield terrain = planar_terrain();
  ScenePopulation p = one_class({{"a", 0.6}, {"b", 0.4}});
  p.scale_jitter = 0.2;
  const std::vector<ScenePlant> first = place(p, terrain), second = place(p, terrain);
  ASSERT_EQ(first.size(), second.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].position, second[i].position);
    EXPECT_EQ(first[i].file, second[i].file);
    EXPECT_EQ(first[i].rotation_deg, second[i].rotation_deg);
    EXPECT_EQ(first[i].scale, second[i].scale);
  }
  p.seed = 8;
  EXPECT_NE(place(p, terrain).front().position, first.front().position);
  p.count = 50;
  EXPECT_EQ(place(p, terrain).size(), 50u);
}

TEST(Population, RejectsSeveralClassesWithoutAMap) {
  ScenePopulation p = one_class({{"a", 1.0}});
  p.classes.push_back(p.classes.front());
  p.classes.back().value = 3;
  EXPECT_THROW(place(p, planar_terrain()), ValueError);
  std::mt19937_64 rng(1);
  PoissonDiskOptions o;
  o.min_distance_m = 0.0;
  EXPECT_THROW(poisson_disk_points(o, rng), ValueError);
}

}  // namespace
}  // namespace fspm::graphics
