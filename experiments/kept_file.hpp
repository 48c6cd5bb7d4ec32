#pragma once
// The kinds of file an experiment can keep per run (outputs.keep, docs/experiments.md).
#include <optional>
#include <string_view>

namespace fspm::experiments {

enum class KeptFile { kTree, kMesh, kImage };

inline constexpr KeptFile kKeptFiles[] = {KeptFile::kTree, KeptFile::kMesh, KeptFile::kImage};

// "tree", "mesh", "image": the names outputs.keep takes.
constexpr std::string_view kept_file_name(KeptFile kind) {
  switch (kind) {
    case KeptFile::kTree:
      return "tree";
    case KeptFile::kMesh:
      return "mesh";
    case KeptFile::kImage:
      return "image";
  }
  return "tree";
}

}  // namespace fspm::experiments
