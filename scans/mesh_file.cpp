#include "scans/mesh_file.hpp"

#include <filesystem>

#include "fspm/error.hpp"
#include "fspm/file_kind.hpp"
#include "scans/gltf_reader.hpp"
#include "scans/ply_reader.hpp"

namespace fspm::scans {

bool is_mesh_file(std::string_view path) {
  return is_polygon_mesh_kind(file_kind_by_extension(path));
}

bool is_grouped_mesh_file(std::string_view path) {
  return is_grouped_mesh_kind(file_kind_by_extension(path));
}

namespace {

GroupedMesh read_any_mesh(const std::string& path, FileKind kind, const std::string& ext) {
  if (kind == FileKind::kObj) return read_obj_mesh(path);
  if (kind == FileKind::kPly) return read_ply_mesh(path);
  if (kind == FileKind::kGltf || kind == FileKind::kGlb) return read_gltf_mesh(path);
  throw ValueError("unknown mesh extension '" + ext + "', expected .obj, .ply, .gltf or .glb",
                   path);
}

}  // namespace

GroupedMesh read_mesh_file(const std::string& path, std::string_view format) {
  const std::string ext =
      format.empty() ? std::filesystem::path(path).extension().string() : "." + std::string(format);
  const FileKind kind = format.empty() ? file_kind(path) : file_kind_for_extension(ext);
  GroupedMesh m = read_any_mesh(path, kind, ext);
  if (m.faces.empty()) {
    throw ParseError(
        "no triangle in the mesh (" + std::to_string(m.vertices.size()) + " vertices, no face)",
        path);
  }
  return m;
}

}  // namespace fspm::scans
