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
  // A tree whose internodes all have zero length (or non-finite geometry, which the mesher
  // leaves out) gives no surface: an empty file would pass for a result.
  if (scene.triangle_count() == 0) {
    throw ValueError(
        "no triangle to write: the input draws no surface (every internode of zero length or "
        "radius, or not finite, and no leaf)",
        path);
  }
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
