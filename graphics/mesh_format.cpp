#include "fspm/error.hpp"
#include "graphics/mesh_writers.hpp"

namespace fspm::graphics {

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
