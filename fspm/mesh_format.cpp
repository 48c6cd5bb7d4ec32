#include "fspm/mesh_format.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "fspm/error.hpp"
#include "fspm/file_kind.hpp"

namespace fspm {

std::string_view mesh_format_name(MeshFormat format) {
  switch (format) {
    case MeshFormat::kObj:
      return "obj";
    case MeshFormat::kPly:
      return "ply";
    case MeshFormat::kVtp:
      return "vtp";
    case MeshFormat::kPvd:
      return "pvd";
    case MeshFormat::kGlb:
      return "glb";
  }
  return "obj";
}

std::optional<MeshFormat> find_mesh_format(std::string_view name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (MeshFormat f : kMeshFormats) {
    if (mesh_format_name(f) == lower) return f;
  }
  return std::nullopt;
}

MeshFormat mesh_format_for(const std::string& path) {
  if (const std::optional<MeshFormat> f = written_mesh_format(file_kind_by_extension(path))) {
    return *f;
  }
  const std::string ext = std::filesystem::path(path).extension().string();
  throw ValueError(
      "unknown mesh file extension '" + ext + "' (expected .obj, .ply, .vtp, .pvd or .glb)", path);
}

}  // namespace fspm
