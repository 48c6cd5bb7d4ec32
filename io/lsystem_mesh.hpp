#pragma once
// Meshes of L-system drawings (lsystem/lsystem_drawing.hpp).
#include "graphics/instanced_mesh.hpp"
#include "graphics/tree_mesher.hpp"
#include "lsystem/lsystem_drawing.hpp"

namespace fspm::io {

// The drawing's prototypes meshed once each and placed (graphics::mesh_instanced). Throws
// ValueError, before meshing, when it places more than graphics::kMaxInstances substructures.
graphics::InstancedMesh mesh_lsystem(const lsystem::LsystemDrawing& drawing,
                                     const graphics::MeshOptions& options);

}  // namespace fspm::io
