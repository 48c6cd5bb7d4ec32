#pragma once
// The plants of a scene file (docs/formats.md): many plants from a few files, each placed by a
// position, a rotation and a uniform scale (Jaeger 4.2's 200-tree scene from two graphs). Read
// by the one scene reader (fspm/scene_reader.hpp); files are resolved against the scene file's
// directory, and each distinct (file, age) is loaded and meshed once however many plants use it.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "fspm/mtg_tree.hpp"
#include "fspm/scene_description.hpp"

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
  std::string path;    // resolved
  double age = -1.0;   // plant age for compressed graphs (< 0: as simulated)
  MtgTreeOptions mtg;  // how an MTG plant file is read: the command's options, the plant's units
};

struct SceneFile {
  std::vector<SceneSource> sources;  // distinct (path, age), in order of first use
  std::vector<SceneInstance> instances;
};

// The placed plants of a scene, sharing one source per distinct (file, age).
SceneFile scene_plants(const std::vector<ScenePlant>& plants);

// True when `path` ends in .json (case-insensitive): the CLI takes it as a scene.
bool is_scene_path(const std::string& path);

// Throws IoError when unreadable, ParseError (with the line and column) for bad JSON and
// ValueError (with the line and JSON path) for anything malformed: a plant without "file",
// non-numeric or non-finite values, a scale <= 0, an unknown key.
SceneFile read_scene_file(const std::string& path);
SceneFile parse_scene(const std::string& text, const std::string& scene_path);

}  // namespace fspm::graphics
