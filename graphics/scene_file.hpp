#pragma once
// Scene files: many plants from a few files, each placed by a position, a rotation and a uniform
// scale (Jaeger 4.2's 200-tree scene from two graphs). JSON, described in docs/formats.md:
//   {"fspm_scene": 1,
//    "instances": [{"file": "oak.ctree", "position": [0, 0, 0], "rotation_deg": 30,
//                   "scale": 1.0, "age": 12}, ...]}
// Files are resolved against the scene file's directory; each distinct (file, age) is loaded and
// meshed once however many instances use it.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace fspm::graphics {

struct SceneInstance {
  std::size_t source = 0;  // into SceneFile::sources
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  // Rotations about x, then y, then z (degrees); a single number in the file is about z.
  Eigen::Vector3d rotation_deg = Eigen::Vector3d::Zero();
  double scale = 1.0;

  // Rotation times scale, x_world = linear() * x_plant + position.
  Eigen::Matrix3d linear() const;
};

struct SceneSource {
  std::string path;   // resolved
  double age = -1.0;  // plant age for compressed graphs (< 0: as simulated)
};

struct SceneFile {
  std::vector<SceneSource> sources;  // distinct (path, age), in order of first use
  std::vector<SceneInstance> instances;
};

// True when `path` ends in .json (case-insensitive): the CLI takes it as a scene.
bool is_scene_path(const std::string& path);

// Throws IoError when unreadable, ParseError (with the line and column of bad JSON, or the
// instance index) for anything malformed: missing "instances" or "file", non-numeric or
// non-finite values, a scale <= 0, an unknown key.
SceneFile read_scene_file(const std::string& path);
SceneFile parse_scene(const std::string& text, const std::string& scene_path);

}  // namespace fspm::graphics
