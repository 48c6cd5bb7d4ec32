#pragma once
// Any input of the graphics commands opened as a mesh: a tree meshed once, a compressed plant
// (.ctree, or a GreenLab plant simulated on the fly) meshed per substructure and placed by
// transforms (Jaeger 3.1.2), a scene's plants placed as it says with its obstacles and terrain, a
// crown's mesh as it is, a point set or .clusters file as spheres and hulls (io/scan_render_mesh).
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "fspm/compressed_tree_graph.hpp"
#include "fspm/instanced_lod.hpp"
#include "fspm/mtg_tree.hpp"
#include "fspm/scene_description.hpp"
#include "graphics/instanced_mesh.hpp"
#include "graphics/tree_mesher.hpp"
#include "graphics/triangle_mesh.hpp"
#include "io/input_kind.hpp"

namespace fspm::io {

// A .ctree as written, or a GreenLab plant description simulated (kind kCompressed or kPlant).
CompressedTreeGraph load_compressed(const std::string& path, InputKind kind);

// Jaeger 3.1.2: one prototype per substructure, meshed once, placed by transforms; `age` < 0: as
// simulated. The level of detail reduces the substructures before they are meshed (Jaeger 3.1.1).
graphics::InstancedMesh mesh_compressed(const CompressedTreeGraph& graph, double age,
                                        const graphics::MeshOptions& options,
                                        const LevelOfDetail& lod);

// A tree meshed once, a compressed plant meshed per substructure, or a crown's mesh as it is;
// `age` is the plant age of a compressed graph (< 0: as simulated) or, for a tree, the latest
// birth time kept. Throws ValueError for a scene, a .pvd or an L-system, which are no part.
graphics::InstancedMesh load_part(const std::string& path, InputKind kind,
                                  const std::string& format, double age,
                                  graphics::MeshOptions options, const LevelOfDetail& lod = {},
                                  const MtgTreeOptions& mtg = default_mtg_tree_options());

// A crown's mesh from fspm crown without the crown's triangles (material leaf), which a ray-cast
// crown replaces; its trunk, if any, stays. The vertices stay too (they frame the view alike).
graphics::TriangleMesh without_crown(graphics::TriangleMesh mesh);

// A scene with its population's plants added to its plants; the terrain mesh, if any, in
// `terrain`.
SceneDescription read_landscape_scene(const std::string& path,
                                      std::optional<graphics::TriangleMesh>& terrain);

// The terrain placed once, as it is (after the obstacles, which are cropped to the plants).
void add_terrain(graphics::InstancedMesh& mesh, std::optional<graphics::TriangleMesh>& terrain);

// The plants of a scene file (its population's among them), each distinct plant file meshed once
// and placed as often as the scene says, its obstacles and its terrain: obstacles near the plants
// (`near_plants`, for pictures), or all of them whole. A scene without plants shows its obstacles
// whole. `crowns_ray_cast`: crowns from fspm crown without their crown triangles.
graphics::InstancedMesh load_scene(const std::string& path, const graphics::MeshOptions& options,
                                   bool near_plants, const LevelOfDetail& lod = {},
                                   bool crowns_ray_cast = false);

// A scene (load_scene) or one part (load_part) at the origin, as simulated or written.
graphics::InstancedMesh load_instanced(const std::string& path, const std::string& format,
                                       const graphics::MeshOptions& options, bool near_plants,
                                       const LevelOfDetail& lod = {});

// The mesh `fspm render` draws: a point set or .clusters file (io/scan_render_mesh.hpp), a tree
// recentred as its scan is, or any other input as load_instanced (an explicit `format` names a
// tree format, whatever the extension).
graphics::InstancedMesh load_render_input(const std::string& path, const std::string& format,
                                          const graphics::MeshOptions& options,
                                          const LevelOfDetail& lod = {});

// The bounds of an input drawn as load_render_input draws it (--frame: pictures of the stages of
// one tree that share camera and ground). Throws ValueError when there is nothing to draw.
Eigen::AlignedBox3f frame_of(const std::string& path, const graphics::MeshOptions& options);

// Default growth steps of a compressed plant: whole cycles 1..final age, at most 20.
std::vector<double> plant_ages(const CompressedTreeGraph& g);

}  // namespace fspm::io
