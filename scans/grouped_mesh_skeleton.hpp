#pragma once
// The skeleton of a tree model exported with one mesh group per branch (Reynolds et al. 2011,
// sec. 3.1, Xfrog's square cross-section primitive): every face of a group is one cross-section
// of the branch, faces that share an edge and lie in one plane are one (a polygon split into
// triangles, as glTF stores it); the bones join the midpoints of consecutive cross-sections in
// file order. A
// group's level is its name without the trailing sequence number ("Branch2_17" and "Branch2_3"
// share the level "Branch2_"); levels are ranked by their first appearance in the file, the
// trunk's first. A branch of level L > 0 hangs at the point of level L - 1 nearest to its first
// midpoint. Radii are the inscribed radius of each cross-section polygon. Groups are OBJ groups or
// glTF nodes (scans/mesh_file.hpp).
#include "fspm/tree_graph.hpp"
#include "scans/obj_reader.hpp"

namespace fspm::scans {

// The level name of a group: its name without trailing digits.
std::string group_level_name(const std::string& group_name);

// Tubes first: when a piece of any group (faces connected through shared vertex positions) is a
// tube of vertex rings (scans/tube_rings.hpp), as modelling programs export branches, every tube
// piece is a branch and the skeleton joins them by geometry (scans/tube_skeleton.hpp); pieces that
// are no tube (leaf cards, flat polygons) are left out and counted in `not_tubes`. Otherwise
// the faces are cross-sections as above.
// Throws ValueError (naming `path`) when the mesh has no face, the first level has no group or
// more than one, or a group has no face.
TreeGraph grouped_mesh_skeleton(const GroupedMesh& mesh, const std::string& path,
                                std::size_t* not_tubes = nullptr);

}  // namespace fspm::scans
