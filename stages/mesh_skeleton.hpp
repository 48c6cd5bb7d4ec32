#pragma once
// The skeleton of a branch mesh (Pirk 2013, 5.2.1): the mesh is contracted onto its curve
// skeleton by Laplacian contraction (Au et al. 2008; stages/mesh_contraction.hpp), contracted
// vertices closer than t_dist are joined to their average (Pirk eq. 5.1-5.2;
// stages/vertex_joining.hpp), the joined vertices are linked along the mesh's edges and reduced
// to a spanning tree (stages/skeleton_graph.hpp) without short dead ends
// (stages/spur_pruning.hpp), and that tree becomes a tree graph rooted at
// its lowest end, with radii from the original vertices (stages/skeleton_tree.hpp).
#include <cstddef>

#include "fspm/tree_graph.hpp"
#include "stages/branch_mesh.hpp"
#include "stages/mesh_contraction.hpp"

namespace fspm::stages {

struct MeshSkeletonParams {
  ContractionParams contraction;
  // t_dist of eq. 5.1 in metres; 0: `join_factor` times the median distance a vertex moved in
  // the contraction (the median branch radius: Pirk's displacement "corresponds to the initial
  // thickness of the branch").
  double join_distance_m = 0.0;
  double join_factor = 1.0;
  // Separate tubes are linked where their skeletons come within this many t_dist.
  double link_factor = 4.0;
  // Dead ends shorter than this many t_dist are removed (stages/spur_pruning.hpp).
  double spur_factor = 3.0;
  void validate() const;  // throws ValueError for values out of range
};

struct MeshSkeleton {
  TreeGraph tree;
  int iterations = 0;       // contraction iterations done
  double area_ratio = 1.0;  // surface area after contraction over before
  double join_distance_m = 0.0;
  std::size_t joined_vertices = 0;
};

// Throws ValueError for a mesh that gives no skeleton edge.
MeshSkeleton mesh_skeleton(const BranchMesh& mesh, const MeshSkeletonParams& params = {});

}  // namespace fspm::stages
