#pragma once
// The vertex rings of a branch exported as a tube: modelling programs (Xfrog, SpeedTree, Blender's
// skin and curve bevels) write a branch as rings of vertices around its axis with quads (or pairs
// of triangles) between consecutive rings, usually open at both ends. Starting from one open end
// (a boundary loop: edges of one face only), the next ring is the set of vertices not yet reached
// that share an edge with the current ring, a breadth-first walk along the strip of faces (the
// level sets of the graph distance from the base ring, as Xu et al. 2007 slice a point graph).
// A ring's centre is its vertices' mean, its radius their median distance to the centre.
#include <optional>
#include <vector>

#include "scans/obj_reader.hpp"

namespace fspm::scans {

// Faces with their vertices welded by position (exporters repeat a vertex per face or per UV
// seam), as local indices into `points`.
struct WeldedPatch {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::vector<std::uint32_t>> faces;
};

// The connected pieces of the faces `faces` of m (a group's): faces that share a vertex position
// belong to one piece.
std::vector<WeldedPatch> connected_patches(const GroupedMesh& m,
                                           const std::vector<std::size_t>& faces);

// A branch's axis: ring centres from one end to the other and their radii.
struct RingPolyline {
  std::vector<Eigen::Vector3d> centres;
  std::vector<double> radii_m;
};

// The rings of a tube patch, from an open end (or, for a tube closed by caps, from its lowest end
// along the principal axis once polygon caps of more than four corners are set aside). nullopt
// when the patch is no tube: fewer than two rings, or its rings' centres span less than half the
// largest radius (a flat polygon, a leaf whose rings are concentric).
std::optional<RingPolyline> tube_rings(const WeldedPatch& patch);

}  // namespace fspm::scans
