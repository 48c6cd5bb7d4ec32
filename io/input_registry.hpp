#pragma once
// Input loading as a library: one reader per file kind (fspm/file_kind.hpp), each giving the data
// the file holds as it is: a tree, a compressed plant, a GreenLab plant description, a scene, a
// triangle mesh, a growth sequence of meshes, a point set or a cluster-based tree. Python's
// fspm.load and any program that takes "a file" call read_input; the graphics commands mesh the
// same kinds (io/input_mesh.hpp).
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "fspm/compressed_tree_graph.hpp"
#include "fspm/file_kind.hpp"
#include "fspm/scene_description.hpp"
#include "fspm/tree_graph.hpp"
#include "graphics/triangle_mesh.hpp"
#include "greenlab/plant_params.hpp"
#include "scans/cluster_model.hpp"
#include "scans/point_set.hpp"

namespace fspm::io {

// One step of a ParaView growth sequence (.pvd): its time and its mesh.
struct MeshStep {
  double time = 0.0;
  graphics::TriangleMesh mesh;
};

using InputData = std::variant<TreeGraph, CompressedTreeGraph, greenlab::PlantParams,
                               SceneDescription, graphics::TriangleMesh, std::vector<MeshStep>,
                               scans::PointSet, scans::ClusterModel>;

struct InputReader {
  FileKind kind;
  // What the reader gives, for messages and docs ("a tree", "a point set", ...).
  const char* gives;
  InputData (*read)(const std::string& path);
};

// The registry: one reader for every kind of fspm/file_kind.hpp.
std::span<const InputReader> input_readers();
// The reader of `kind`, or nullptr (kUnknown).
const InputReader* find_input_reader(FileKind kind);

// The file at `path` (a folder written by fspm crown stands for its crown.glb) read by the reader
// of its kind: an L-system is derived and drawn by the turtle into its tree (the file's steps and
// seed, the .v beside it); a .ply with faces is a mesh, without faces a point set. Throws
// ValueError for a file of no known kind (naming the extensions known), and the readers' errors.
InputData read_input(const std::string& path);

}  // namespace fspm::io
