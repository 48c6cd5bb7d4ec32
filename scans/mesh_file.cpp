#include "scans/mesh_file.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "fspm/error.hpp"
#include "scans/gltf_reader.hpp"
#include "scans/ply_reader.hpp"

namespace fspm::scans {
namespace {

std::string lower_extension(std::string_view path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

bool is_mesh_file(std::string_view path) {
  const std::string ext = lower_extension(path);
  return ext == ".ply" || is_grouped_mesh_file(path);
}

bool is_grouped_mesh_file(std::string_view path) {
  const std::string ext = lower_extension(path);
  return ext == ".obj" || ext == ".gltf" || ext == ".glb";
}

namespace {

GroupedMesh read_any_mesh(const std::string& path, const std::string& ext) {
  if (ext == ".obj") return read_obj_mesh(path);
  if (ext == ".ply") return read_ply_mesh(path);
  if (ext == ".gltf" || ext == ".glb") return read_gltf_mesh(path);
  throw ValueError("unknown mesh extension '" + ext + "', expected .obj, .ply, .gltf or .glb",
                   path);
}

}  // namespace

GroupedMesh read_mesh_file(const std::string& path, std::string_view format) {
  const std::string ext = format.empty() ? lower_extension(path) : "." + std::string(format);
  GroupedMesh m = read_any_mesh(path, ext);
  if (m.faces.empty()) {
    throw ParseError(
        "no triangle in the mesh (" + std::to_string(m.vertices.size()) + " vertices, no face)",
        path);
  }
  return m;
}

}  // namespace fspm::scans
