// Meshes of L-system drawings (fspm-full): `fspm lsystem interpret ... -o MESH`.
#include "cli/lsystem_mesh.hpp"

#include <string>

#include "cli/lsystem_source.hpp"
#include "fspm/error.hpp"
#include "fspm/saturating.hpp"
#include "graphics/instanced_mesh.hpp"
#include "graphics/mesh_writers.hpp"
#include "graphics/tree_mesher.hpp"

namespace fspm::cli {

graphics::InstancedMesh mesh_lsystem(const LsystemDrawing& drawing,
                                     const graphics::MeshOptions& options) {
  if (drawing.occurrences > graphics::kMaxInstances) {
    throw ValueError("the drawing places " + count_text(drawing.occurrences) +
                     " substructures, more than " + std::to_string(graphics::kMaxInstances) +
                     " instances: draw substructures smaller than a length as one internode "
                     "(--detail)");
  }
  return graphics::mesh_instanced(drawing.tree, options);
}

void write_lsystem_mesh(const LsystemDrawing& drawing, const std::string& path,
                        nlohmann::json& summary) {
  const graphics::InstancedMesh mesh = mesh_lsystem(drawing, {});
  graphics::write_mesh(mesh, path);
  summary["meshes"] = mesh.meshes.size();
  summary["mesh_instances"] = mesh.instances.size();
  summary["vertices"] = mesh.vertex_count();
  summary["triangles"] = mesh.triangle_count();
}

}  // namespace fspm::cli
