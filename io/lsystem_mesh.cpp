#include "io/lsystem_mesh.hpp"

#include <string>

#include "fspm/error.hpp"
#include "fspm/saturating.hpp"

namespace fspm::io {

graphics::InstancedMesh mesh_lsystem(const lsystem::LsystemDrawing& drawing,
                                     const graphics::MeshOptions& options) {
  if (drawing.occurrences > graphics::kMaxInstances) {
    throw ValueError("the drawing places " + count_text(drawing.occurrences) +
                     " substructures, more than " + std::to_string(graphics::kMaxInstances) +
                     " instances: draw substructures smaller than a length as one internode "
                     "(--detail)");
  }
  return graphics::mesh_instanced(drawing.tree, options);
}

}  // namespace fspm::io
