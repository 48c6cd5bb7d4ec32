#pragma once
// Mesh files for other tools: OBJ + MTL (Blender, MeshLab), binary PLY (attributes as extra
// vertex properties), VTK XML PolyData .vtp (attributes as point-data arrays, for ParaView),
// ParaView .pvd growth sequences (one .vtp per age) and binary glTF 2.0 .glb. Every file is
// written atomically: a failed write leaves no partial output.
#include <span>
#include <string>
#include <vector>

#include "fspm/mesh_format.hpp"
#include "fspm/tree_graph.hpp"
#include "graphics/instanced_mesh.hpp"
#include "graphics/skeleton_skin.hpp"
#include "graphics/tree_mesher.hpp"
#include "graphics/triangle_mesh.hpp"
#include "graphics/wind_animation.hpp"

namespace fspm::graphics {

// The formats and their extensions live in the core (fspm/mesh_format.hpp).
using fspm::mesh_format_for;
using fspm::MeshFormat;

// Writes `path` and, beside it, the material library with the same stem and extension .mtl.
void write_obj(const TriangleMesh& mesh, const std::string& path);
void write_ply(const TriangleMesh& mesh, const std::string& path);
void write_vtp(const TriangleMesh& mesh, const std::string& path);
void write_glb(const TriangleMesh& mesh, const std::string& path);

// A skinned .glb (glTF 2.0 skins and animations): the scene holds node 0 "tree", parent of the
// root joints, and node 1 "bark", the skinned mesh (JOINTS_0 as unsigned shorts, WEIGHTS_0);
// one node per joint named
// joint_<internode id> translated from its parent joint's head; the skin's inverse bind matrices
// translate by minus the heads. With `wind`, one animation "wind" with a LINEAR rotation
// sampler per joint over shared keyframe times, which Blender imports as an action.
void write_skinned_glb(const TriangleMesh& mesh, const Skin& skin, const WindAnimation* wind,
                       const std::string& path);

// Any single-mesh format by extension (not .pvd).
void write_mesh(const TriangleMesh& mesh, const std::string& path);

// Instanced: .glb keeps the instancing (each shared mesh stored once, one node per instance with
// its matrix, the substructure's branching order in the node's extras.order_offset); OBJ, PLY
// and VTP get the flattened explicit mesh. Not .pvd.
void write_glb(const InstancedMesh& scene, const std::string& path);
void write_mesh(const InstancedMesh& scene, const std::string& path);

struct PvdFrame {
  double age = 0.0;
  std::string vtp_path;
  std::size_t vertices = 0;
  std::size_t triangles = 0;
};

// Growth sequence: for each age, the tree restricted to nodes born at or before it
// (MeshOptions::max_birth_time), written as <stem>_<index>.vtp beside `path`, then the .pvd
// collection listing them with their ages as time steps. Ages must be finite; they are sorted.
std::vector<PvdFrame> write_pvd(const TreeGraph& tree, const MeshOptions& options,
                                std::vector<double> ages, const std::string& path);

// Ages for a growth sequence when none are given: every distinct birth time when there are at
// most `max_frames`, else `max_frames` evenly spaced ages from the first to the last birth.
std::vector<double> default_ages(const TreeGraph& tree, std::size_t max_frames = 20);

}  // namespace fspm::graphics
