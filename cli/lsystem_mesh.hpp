#pragma once
// Meshes of L-system drawings (fspm-full).
#include "cli/lsystem_source.hpp"
#include "graphics/instanced_mesh.hpp"
#include "graphics/tree_mesher.hpp"

namespace fspm::cli {

// The drawing's prototypes meshed once each and placed (graphics::mesh_instanced). Throws
// ValueError, before meshing, when it places more than graphics::kMaxInstances substructures.
graphics::InstancedMesh mesh_lsystem(const LsystemDrawing& drawing,
                                     const graphics::MeshOptions& options);

}  // namespace fspm::cli
