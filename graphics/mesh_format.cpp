#include <algorithm>
#include <cctype>
#include <filesystem>

#include "fspm/error.hpp"
#include "graphics/mesh_writers.hpp"

namespace fspm::graphics {

MeshFormat mesh_format_for(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".obj") return MeshFormat::kObj;
  if (ext == ".ply") return MeshFormat::kPly;
  if (ext == ".vtp") return MeshFormat::kVtp;
  if (ext == ".pvd") return MeshFormat::kPvd;
  if (ext == ".glb") return MeshFormat::kGlb;
  throw ValueError(
      "unknown mesh file extension '" + ext + "' (expected .obj, .ply, .vtp, .pvd or .glb)", path);
}

void write_mesh(const TriangleMesh& mesh, const std::string& path) {
  switch (mesh_format_for(path)) {
    case MeshFormat::kObj:
      write_obj(mesh, path);
      return;
    case MeshFormat::kPly:
      write_ply(mesh, path);
      return;
    case MeshFormat::kVtp:
      write_vtp(mesh, path);
      return;
    case MeshFormat::kGlb:
      write_glb(mesh, path);
      return;
    case MeshFormat::kPvd:
      break;
  }
  throw ValueError("a .pvd growth sequence is written from a tree, not from one mesh", path);
}

void write_mesh(const InstancedMesh& scene, const std::string& path) {
  const MeshFormat format = mesh_format_for(path);
  if (format == MeshFormat::kGlb) {
    write_glb(scene, path);
  } else if (format == MeshFormat::kPvd) {
    throw ValueError("a .pvd growth sequence is written from a tree, not from a scene", path);
  } else if (scene.instances.size() == 1 && scene.instances[0].matrix().isIdentity()) {
    write_mesh(scene.meshes[scene.instances[0].mesh], path);
  } else {
    write_mesh(scene.flatten(), path);
  }
}

}  // namespace fspm::graphics
