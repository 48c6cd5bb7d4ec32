// Meshes of L-system drawings (fspm-full): `fspm lsystem interpret ... -o MESH`.
#include <string>

#include "cli/lsystem_source.hpp"
#include "graphics/instanced_mesh.hpp"
#include "graphics/mesh_writers.hpp"
#include "io/lsystem_mesh.hpp"

namespace fspm::cli {

void write_lsystem_mesh(const LsystemDrawing& drawing, const std::string& path,
                        nlohmann::json& summary) {
  const graphics::InstancedMesh mesh = io::mesh_lsystem(drawing, {});
  graphics::write_mesh(mesh, path);
  summary["meshes"] = mesh.meshes.size();
  summary["mesh_instances"] = mesh.instances.size();
  summary["vertices"] = mesh.vertex_count();
  summary["triangles"] = mesh.triangle_count();
}

}  // namespace fspm::cli
