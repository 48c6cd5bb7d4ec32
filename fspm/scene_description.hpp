#pragma once
// One scene for every command (docs/formats.md, "Scene files"): the sky, the ground, obstacles
// (spheres and leaf clusters, boxes, walls, triangle meshes) and placed plants, z up. This is the
// scene as written in the file, values checked but defaults left unset where the reading module
// computes them (a cluster's translucency follows Pirk eq. 4.4 in the environment module). The
// environment turns it into occluders and a sky, graphics into placed plant meshes.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace fspm {

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
};

struct SceneDescription {
  std::string comment;  // free text, kept by fspm scene upgrade
  SceneSky sky;
  std::optional<double> gamma0;  // default base translucency of leaf clusters
  std::optional<SceneGround> ground;
  std::vector<SceneObstacle> obstacles;
  std::vector<ScenePlant> plants;
};

}  // namespace fspm
