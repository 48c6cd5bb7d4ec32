#include "fspm/file_kind.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <fstream>

namespace fspm {
namespace {

// Extensions and magics: Turk's PLY header ("ply" on the first line), the glTF 2.0 binary header
// ("glTF", GLB File Format Specification), the LAS public header block ("LASF", ASPRS LAS 1.4
// table 3), the PCD header (Point Cloud Library, "# .PCD" comment line), and fspm's own formats
// (docs/formats.md).
constexpr std::array<FileKindInfo, 18> kFileKinds{{
    {FileKind::kTreeText, "text tree", {".tree"}, "fspm-tree"},
    {FileKind::kTreeBinary, "binary tree", {".treeb"}, "FSPMTREB"},
    {FileKind::kNewick, "Newick tree", {".nwk"}, ""},
    {FileKind::kMtg, "MTG", {".mtg"}, "CODE:"},
    {FileKind::kCtree, "compressed tree graph", {".ctree"}, "FSPMCTRE"},
    {FileKind::kPlant, "GreenLab plant", {".toml"}, ""},
    {FileKind::kScene, "scene", {".json"}, ""},
    {FileKind::kLsystem, "L-system", {".l"}, ""},
    {FileKind::kPvd, "ParaView growth sequence", {".pvd"}, ""},
    {FileKind::kVtp, "VTK PolyData mesh", {".vtp"}, ""},
    {FileKind::kObj, "OBJ mesh", {".obj"}, ""},
    {FileKind::kPly, "PLY", {".ply"}, "ply"},
    {FileKind::kGltf, "glTF", {".gltf"}, ""},
    {FileKind::kGlb, "binary glTF", {".glb"}, "glTF"},
    {FileKind::kXyz, "XYZ point set", {".xyz", ".txt", ".csv"}, ""},
    {FileKind::kPcd, "PCD point set", {".pcd"}, "# .PCD"},
    {FileKind::kLas, "LAS point set", {".las", ".laz"}, "LASF"},
    {FileKind::kClusters, "cluster-based tree", {".clusters"}, "FSPMCLU"},
}};

// How much of a file the magic and the XML root element are looked for in.
constexpr std::size_t kSniffBytes = 512;

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// The magic followed by the end of its line where a line must follow it (PLY's "ply"), or by
// anything.
bool starts_with_magic(std::string_view data, std::string_view magic, FileKind kind) {
  // A PCD header may leave out its comment line and start with its first entry.
  if (kind == FileKind::kPcd && data.starts_with("VERSION ")) return true;
  if (magic.empty() || data.substr(0, magic.size()) != magic) return false;
  if (kind != FileKind::kPly) return true;
  const std::string_view rest = data.substr(magic.size());
  return rest.starts_with("\n") || rest.starts_with("\r\n");
}

}  // namespace

std::span<const FileKindInfo> file_kinds() { return kFileKinds; }

const FileKindInfo& file_kind_info(FileKind kind) {
  static constexpr FileKindInfo kUnknownInfo{FileKind::kUnknown, "unknown", {}, ""};
  for (const auto& info : kFileKinds) {
    if (info.kind == kind) return info;
  }
  return kUnknownInfo;
}

FileKind file_kind_for_extension(std::string_view extension) {
  const std::string ext = lower(extension);
  if (ext.empty()) return FileKind::kUnknown;
  for (const auto& info : kFileKinds) {
    for (std::string_view e : info.extensions) {
      if (!e.empty() && e == ext) return info.kind;
    }
  }
  return FileKind::kUnknown;
}

std::string_view table_extension(std::string_view path) {
  const std::string ext = lower(std::filesystem::path(path).extension().string());
  if (ext.empty()) return {};
  for (const auto& info : kFileKinds) {
    for (std::string_view e : info.extensions) {
      if (!e.empty() && e == ext) return e;
    }
  }
  return {};
}

FileKind file_kind_by_extension(std::string_view path) {
  return file_kind_for_extension(std::filesystem::path(path).extension().string());
}

FileKind file_kind_by_content(std::string_view data) {
  for (const auto& info : kFileKinds) {
    if (starts_with_magic(data, info.magic, info.kind)) return info.kind;
  }
  // VTK XML files: the root element's type tells a collection from a mesh.
  if (data.starts_with("<?xml") || data.starts_with("<VTKFile")) {
    if (data.find("type=\"Collection\"") != std::string_view::npos) return FileKind::kPvd;
    if (data.find("type=\"PolyData\"") != std::string_view::npos) return FileKind::kVtp;
  }
  return FileKind::kUnknown;
}

FileKind file_kind(const std::string& path) {
  const FileKind by_extension = file_kind_by_extension(path);
  if (by_extension != FileKind::kUnknown) return by_extension;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return FileKind::kUnknown;
  std::ifstream in(path, std::ios::binary);
  std::string head(kSniffBytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return file_kind_by_content(head);
}

bool is_tree_kind(FileKind kind) {
  return kind == FileKind::kTreeText || kind == FileKind::kTreeBinary ||
         kind == FileKind::kNewick || kind == FileKind::kMtg;
}

std::string_view tree_format_of_kind(FileKind kind) {
  switch (kind) {
    case FileKind::kTreeText:
      return "tree";
    case FileKind::kTreeBinary:
      return "treeb";
    case FileKind::kNewick:
      return "nwk";
    case FileKind::kMtg:
      return "mtg";
    default:
      return "";
  }
}

bool is_grouped_mesh_kind(FileKind kind) {
  return kind == FileKind::kObj || kind == FileKind::kGltf || kind == FileKind::kGlb;
}

bool is_polygon_mesh_kind(FileKind kind) {
  return kind == FileKind::kPly || is_grouped_mesh_kind(kind);
}

bool is_point_set_kind(FileKind kind) {
  return kind == FileKind::kPly || kind == FileKind::kXyz || kind == FileKind::kPcd ||
         kind == FileKind::kLas || is_grouped_mesh_kind(kind);
}

std::optional<MeshFormat> written_mesh_format(FileKind kind) {
  switch (kind) {
    case FileKind::kObj:
      return MeshFormat::kObj;
    case FileKind::kPly:
      return MeshFormat::kPly;
    case FileKind::kVtp:
      return MeshFormat::kVtp;
    case FileKind::kPvd:
      return MeshFormat::kPvd;
    case FileKind::kGlb:
      return MeshFormat::kGlb;
    default:
      return std::nullopt;
  }
}

}  // namespace fspm
