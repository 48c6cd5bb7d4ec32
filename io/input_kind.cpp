#include "io/input_kind.hpp"

#include <filesystem>

#include "fspm/file_kind.hpp"
#include "fspm/scene_description.hpp"

namespace fspm::io {

InputKind input_kind(const std::string& path) {
  switch (file_kind(path)) {
    case FileKind::kCtree:
      return InputKind::kCompressed;
    case FileKind::kPlant:
      return InputKind::kPlant;
    case FileKind::kScene:
      return InputKind::kScene;
    case FileKind::kPvd:
      return InputKind::kPvd;
    case FileKind::kLsystem:
      return InputKind::kLsystem;
    case FileKind::kObj:
    case FileKind::kGltf:
    case FileKind::kGlb:
      return InputKind::kMesh;  // a crown from fspm crown
    default:
      return InputKind::kTree;
  }
}

bool is_compressed(InputKind kind) {
  return kind == InputKind::kCompressed || kind == InputKind::kPlant;
}

std::string resolve_crown_folder(const std::string& path) {
  const std::filesystem::path crown = std::filesystem::path(path) / kCrownMeshName;
  const bool folder =
      std::filesystem::is_directory(path) && std::filesystem::is_regular_file(crown);
  return folder ? crown.string() : path;
}

}  // namespace fspm::io
