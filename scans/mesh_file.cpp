#include "scans/mesh_file.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "fspm/error.hpp"
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
  return ext == ".obj" || ext == ".ply";
}

GroupedMesh read_mesh_file(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".obj") return read_obj_mesh(path);
  if (ext == ".ply") return read_ply_mesh(path);
  throw ValueError("unknown mesh extension '" + ext + "', expected .obj or .ply", path);
}

}  // namespace fspm::scans
