#pragma once
// One scene for every command (docs/formats.md, "Scene files"): the sky, the ground, obstacles
// (spheres and leaf clusters, boxes, walls, triangle meshes) and placed plants, z up. This is the
// scene as written in the file, values checked but defaults left unset where the reading module
// computes them (a cluster's translucency follows Pirk eq. 4.4 in the environment module). The
// environment turns it into occluders and a sky, graphics into placed plant meshes.
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "fspm/length_unit.hpp"

namespace fspm {

// Largest number of sky directions of the light integral (scene files, the library's check).
inline constexpr int kMaxSkyDirections = 1 << 20;

// The crown mesh fspm crown writes in its output directory; a scene's "crown" and the graphics
// commands take the directory for it.
inline constexpr const char* kCrownMeshName = "crown.glb";

// Where the brightest sky direction comes from (one of them at most).
enum class SkySource { kDefault, kBrightest, kSun, kNoonSun };

struct SceneSky {
  SkySource source = SkySource::kDefault;
  Eigen::Vector3d brightest = Eigen::Vector3d::UnitZ();  // kBrightest, as written (non-zero)
  double sun_elevation_deg = 90.0;                       // kSun
  double sun_azimuth_deg = 0.0;                          // kSun
  double latitude_deg = 0.0;                             // kNoonSun
  double day_of_year = 172.0;                            // kNoonSun
  std::optional<int> directions;
  std::optional<double> significance;
  std::optional<bool> analytic;
};

// Translucency gamma in [0, 1] (0 opaque, 1 transparent) and whether the obstacle stops growth;
// unset: the type's default (docs/formats.md).
struct ObstacleSurface {
  std::optional<double> translucency;
  std::optional<bool> solid;
};

struct SphereObstacle {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius_m = 1.0;
  bool cluster = false;          // written as type "cluster" (a leaf cluster)
  std::optional<double> gamma0;  // base translucency of Pirk eq. 4.4
};

// A box of centre and size, optionally rotated by angle_deg about axis.
struct BoxObstacle {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Vector3d size_m = Eigen::Vector3d::Ones();
  std::optional<Eigen::Vector3d> axis;  // set together with angle_deg
  double angle_deg = 0.0;
};

// A vertical wall from (x0, y0) to (x1, y1), standing on base_m.
struct WallObstacle {
  Eigen::Vector2d from = Eigen::Vector2d::Zero();
  Eigen::Vector2d to = Eigen::Vector2d::UnitX();
  double height_m = 1.0;
  double thickness_m = 0.2;
  double base_m = 0.0;
};

struct MeshObstacle {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;  // indices into vertices, checked
};

struct SceneObstacle {
  std::variant<SphereObstacle, BoxObstacle, WallObstacle, MeshObstacle> shape;
  ObstacleSurface surface;
};

// The plane z = height_m; everything below it is ground.
struct SceneGround {
  double height_m = 0.0;
  ObstacleSurface surface;
};

// A plant file placed by position, rotations about x, then y, then z, and a uniform scale.
struct ScenePlant {
  std::string file;  // resolved against the scene file's directory
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotation_deg = Eigen::Vector3d::Zero();
  double scale = 1.0;
  std::optional<double> age;  // plant age of a compressed graph; unset: as simulated
  // Units of an MTG plant file ("length_unit", "diameter_unit"); unset: the command's options.
  std::optional<LengthUnit> length_unit, diameter_unit;
};

// A terrain from a heightfield image (Argudo 2014, 6.1): pixel (i, j), row 0 at the top (north),
// stands at x = i metres_per_pixel, y = (rows - 1 - j) metres_per_pixel and
// z = height_scale_m * value, the value of its first channel (in [0, 1] for integer images, as
// stored for floating-point ones).
struct SceneTerrain {
  std::string heightfield;  // resolved against the scene file's directory
  double metres_per_pixel = 1.0;
  double height_scale_m = 1.0;
  int stride = 1;  // the mesh takes every stride-th pixel (plants stand on the full heightfield)
};

// One plant file of a population class, drawn with `probability` among the class's files.
struct PopulationPlant {
  std::string file;  // resolved
  double probability = 1.0;
  std::optional<double> age;
};

// The sites whose class-map grey level (0-255) is `value` hold a plant with probability
// `density`, one of `plants` (Argudo 2014, 6.2: species as plants with a probability).
struct PopulationClass {
  int value = 0;
  double density = 1.0;
  std::vector<PopulationPlant> plants;
};

// Plants spread over the terrain at a minimum distance (Poisson-disk dart throwing), each on the
// terrain, turned about z at random and scaled by a factor in [1 - scale_jitter, 1 + scale_jitter].
struct ScenePopulation {
  std::string map;  // class map, resolved, stretched over the terrain; empty: one class
  std::vector<PopulationClass> classes;
  double min_distance_m = 1.0;
  std::optional<double> count;  // at most this many plants; unset: as many as fit
  std::uint64_t seed = 1;
  double scale_jitter = 0.0;
};

struct SceneDescription {
  std::string comment;  // free text, kept by fspm scene upgrade
  SceneSky sky;
  std::optional<double> gamma0;  // default base translucency of leaf clusters
  std::optional<SceneGround> ground;
  std::vector<SceneObstacle> obstacles;
  std::vector<ScenePlant> plants;
  std::optional<SceneTerrain> terrain;
  std::optional<ScenePopulation> population;  // needs the terrain
};

}  // namespace fspm
