#pragma once
// The mesh file formats fspm writes, named by their extensions. Kept in the core so that
// experiment files, which know no graphics, hold a format as a type (graphics/mesh_writers.hpp
// writes them).
#include <optional>
#include <string>
#include <string_view>

namespace fspm {

// OBJ + MTL, binary PLY, VTK XML PolyData, ParaView growth sequence, binary glTF 2.0.
enum class MeshFormat { kObj, kPly, kVtp, kPvd, kGlb };

inline constexpr MeshFormat kMeshFormats[] = {MeshFormat::kObj, MeshFormat::kPly, MeshFormat::kVtp,
                                              MeshFormat::kPvd, MeshFormat::kGlb};

// "obj", "ply", "vtp", "pvd", "glb": the extension without its dot.
std::string_view mesh_format_name(MeshFormat format);
// Inverse of mesh_format_name, ignoring case; nothing for an unknown name.
std::optional<MeshFormat> find_mesh_format(std::string_view name);
// From the extension of `path`; throws ValueError naming the known extensions otherwise.
MeshFormat mesh_format_for(const std::string& path);

}  // namespace fspm
