#include "io/input_registry.hpp"

#include <array>

#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "fspm/scene_reader.hpp"
#include "fspm/tree_file.hpp"
#include "graphics/vtk_readback.hpp"
#include "io/input_kind.hpp"
#include "io/placed_mesh.hpp"
#include "lsystem/lsystem_drawing.hpp"
#include "scans/clusters_file.hpp"
#include "scans/ply_reader.hpp"
#include "scans/point_set_file.hpp"

namespace fspm::io {
namespace {

InputData read_tree(const std::string& path) { return read_tree_file(path, {}); }

InputData read_ctree(const std::string& path) { return read_ctree_file(path); }

InputData read_plant(const std::string& path) { return greenlab::read_plant_params(path); }

InputData read_scene(const std::string& path) { return read_scene_description(path); }

// Explicitly, as fspm mesh draws an L-system without --compressed: one prototype, the whole tree.
InputData read_lsystem(const std::string& path) {
  lsystem::LsystemSource source;
  source.file = path;
  lsystem::LsystemDrawing drawing = lsystem::draw_lsystem(source, false, 0.0, 0);
  return std::move(drawing.tree.prototypes.front().geometry);
}

void require_vtk(const std::string& path) {
  if (!graphics::vtk_available()) {
    throw ValueError("fspm was built without VTK (FSPM_WITH_VTK=OFF): cannot read .vtp meshes",
                     path);
  }
}

InputData read_pvd(const std::string& path) {
  require_vtk(path);
  std::vector<MeshStep> steps;
  for (const auto& step : graphics::read_pvd_file(path)) {
    steps.push_back({step.time, graphics::read_vtp_mesh(step.path)});
  }
  return steps;
}

InputData read_vtp(const std::string& path) {
  require_vtk(path);
  return graphics::read_vtp_mesh(path);
}

InputData read_mesh(const std::string& path) { return read_placed_mesh(path); }

// A PLY with faces is a mesh; one without (a scan) is a point set.
InputData read_ply(const std::string& path) {
  scans::GroupedMesh mesh = scans::read_ply_mesh(path);
  if (!mesh.faces.empty()) return grouped_mesh_triangles(mesh);
  return scans::read_point_set(path);
}

InputData read_points(const std::string& path) { return scans::read_point_set(path); }

InputData read_clusters(const std::string& path) { return scans::read_clusters_file(path); }

constexpr std::array<InputReader, 18> kReaders{{
    {FileKind::kTreeText, "a tree", read_tree},
    {FileKind::kTreeBinary, "a tree", read_tree},
    {FileKind::kNewick, "a tree", read_tree},
    {FileKind::kMtg, "a tree", read_tree},
    {FileKind::kCtree, "a compressed plant", read_ctree},
    {FileKind::kPlant, "a GreenLab plant description", read_plant},
    {FileKind::kScene, "a scene", read_scene},
    {FileKind::kLsystem, "the tree the turtle draws", read_lsystem},
    {FileKind::kPvd, "a growth sequence of meshes", read_pvd},
    {FileKind::kVtp, "a mesh", read_vtp},
    {FileKind::kObj, "a mesh", read_mesh},
    {FileKind::kPly, "a mesh or a point set", read_ply},
    {FileKind::kGltf, "a mesh", read_mesh},
    {FileKind::kGlb, "a mesh", read_mesh},
    {FileKind::kXyz, "a point set", read_points},
    {FileKind::kPcd, "a point set", read_points},
    {FileKind::kLas, "a point set", read_points},
    {FileKind::kClusters, "a cluster-based tree", read_clusters},
}};

std::string known_extensions() {
  std::string text;
  for (const auto& info : file_kinds()) {
    for (std::string_view e : info.extensions) {
      if (e.empty()) continue;
      if (!text.empty()) text += ", ";
      text += e;
    }
  }
  return text;
}

}  // namespace

std::span<const InputReader> input_readers() { return kReaders; }

const InputReader* find_input_reader(FileKind kind) {
  for (const auto& reader : kReaders) {
    if (reader.kind == kind) return &reader;
  }
  return nullptr;
}

InputData read_input(const std::string& path) {
  const std::string file = resolve_crown_folder(path);
  const InputReader* reader = find_input_reader(file_kind(file));
  if (reader == nullptr) {
    (void)open_input_file(file);  // a missing or unreadable file is said to be so first
    throw ValueError("not a file kind fspm reads (by its extension or its first bytes): expected " +
                         known_extensions(),
                     file);
  }
  return reader->read(file);
}

}  // namespace fspm::io
