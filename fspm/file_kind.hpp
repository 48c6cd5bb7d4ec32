#pragma once
// The kinds of file fspm reads and writes, decided in one place: by the extension (any case) and,
// when the extension names no kind, by the first bytes of the file (the magic of each binary
// format, the first line of the text formats that have one). Every reader and command asks this
// table; the readers themselves are chosen by kind in io/input_registry.hpp.
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "fspm/mesh_format.hpp"

namespace fspm {

enum class FileKind {
  kUnknown,
  kTreeText,    // .tree (fspm/text_tree_format.hpp)
  kTreeBinary,  // .treeb (fspm/binary_tree_format.hpp)
  kNewick,      // .nwk
  kMtg,         // .mtg
  kCtree,       // .ctree compressed tree graph
  kPlant,       // .toml GreenLab plant description
  kScene,       // .json scene description (docs/formats.md)
  kLsystem,     // .l L-system (with the .v beside it)
  kPvd,         // ParaView collection: a growth sequence of .vtp meshes
  kVtp,         // VTK XML PolyData mesh
  kObj,         // Wavefront OBJ mesh
  kPly,         // PLY: a point set, or a mesh when it has faces
  kGltf,        // glTF 2.0, JSON
  kGlb,         // glTF 2.0, binary
  kXyz,         // .xyz, .txt, .csv point set: one point a line
  kPcd,         // Point Cloud Library point set
  kLas,         // ASPRS LAS point set (.laz is refused by its reader)
  kClusters,    // .clusters cluster-based tree (scans/clusters_file.hpp)
};

struct FileKindInfo {
  FileKind kind;
  std::string_view name;  // what error messages and docs call it
  // Lower-case extensions with their dot, the first one the kind's own; up to four.
  std::string_view extensions[4];
  // The bytes a file of this kind starts with (empty: none that tells it apart).
  std::string_view magic;
};

// One row per kind except kUnknown.
std::span<const FileKindInfo> file_kinds();
const FileKindInfo& file_kind_info(FileKind kind);

// The kind named by the extension of `path` (any case), or kUnknown. `extension` (".obj") alone:
// file_kind_for_extension.
FileKind file_kind_by_extension(std::string_view path);
FileKind file_kind_for_extension(std::string_view extension);
// The extension of `path` as the table spells it (lower case, with its dot) when it names a kind,
// else empty: tells apart the extensions of one kind (.laz from .las, .xyz from .csv).
std::string_view table_extension(std::string_view path);
// The kind told by the first bytes of `data`, or kUnknown.
FileKind file_kind_by_content(std::string_view data);
// The kind of a file: its extension's, or, when the extension names none, its first bytes'
// (kUnknown for a file that cannot be opened or that no magic matches).
FileKind file_kind(const std::string& path);

// Kinds read by read_tree_file (.tree, .treeb, .nwk, .mtg), and the format name it takes for each.
bool is_tree_kind(FileKind kind);
std::string_view tree_format_of_kind(FileKind kind);
// Kinds read as polygon meshes (scans/mesh_file.hpp): .obj, .ply, .gltf, .glb.
bool is_polygon_mesh_kind(FileKind kind);
// Polygon meshes with groups, also the meshes a scene places as crowns: .obj, .gltf, .glb.
bool is_grouped_mesh_kind(FileKind kind);
// Kinds read as point sets (scans/point_set_file.hpp): .ply, .xyz, .pcd, .las and the vertices of
// the grouped meshes.
bool is_point_set_kind(FileKind kind);
// The mesh format fspm writes for a kind, if it writes that kind.
std::optional<MeshFormat> written_mesh_format(FileKind kind);

}  // namespace fspm
