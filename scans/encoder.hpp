#pragma once
// Encoding a point set into the cluster-based representation (Pirk sec. 3.3): ground removed,
// neighbour graph with weights |u - v|^beta, shortest-path tree from the trunk's base, skeleton
// nodes by path length, radii of eq. 3.1, main skeleton and clusters by eq. 3.2, alpha-shape hulls.
#include <optional>

#include "scans/alpha_hull.hpp"
#include "scans/cluster_model.hpp"
#include "scans/point_set.hpp"
#include "scans/species.hpp"

namespace fspm::scans {

struct EncodeOptions {
  SpeciesParameters species = default_species();
  int neighbours = 8;         // k of the neighbour graph
  double bin_length_m = 0.0;  // 0: default_bin_length_m
  // Points are thinned to one per voxel of this size first; 0: 1/1000 of the largest extent of
  // the point set, negative: no thinning.
  double voxel_m = 0.0;
  std::optional<double> root_diameter_m;  // d_root of eq. 3.1; estimated from the trunk if unset
  // Trunk points for the estimate lie up to this height above the lowest point; 0: breast height
  // (1.3 m) or a tenth of the point set's height, whichever is lower.
  double trunk_height_m = 0.0;
  AlphaHullOptions hull;
  // Ground points (a band above the cloud's lower envelope, scans/ground_filter.hpp) are removed
  // after thinning unless this is set; the root is the base of the trunk's column either way.
  bool keep_ground = false;
  // The main skeleton follows the trunk to the top and the limbs carrying main_branch_share of the
  // skeleton's length or reaching main_branch_reach of its longest path (0.1: four of the default
  // forty bins, the spur length of the branch skeleton) to their tips, eq. 3.2 deciding for the
  // rest (scans/cluster_split.hpp); false: eq. 3.2 alone, as Pirk.
  bool follow_main_axes = true;
  double main_branch_share = 0.05;
  double main_branch_reach = 0.1;

  // Throws ValueError naming the first field out of range.
  void validate() const;
};

// An occlusion gap the neighbour graph bridged (scans/neighbour_graph.hpp): a bridge longer than
// NeighbourGraph::gap_m, its ends in the input's coordinates.
struct BridgedGap {
  Eigen::Vector3d from = Eigen::Vector3d::Zero();  // in the piece beyond the gap
  Eigen::Vector3d to = Eigen::Vector3d::Zero();    // in the tree
  double length_m = 0.0;
};

struct EncodeResult {
  ClusterModel model;
  TreeGraph full_skeleton;  // every skeleton node, radii of eq. 3.1, before the cluster split
  // The full skeleton without side tips shorter than four bins (scans/tip_pruning.hpp): the
  // branches the scan shows, into the crown, where eq. 3.2 may have cut the main skeleton short.
  TreeGraph branch_skeleton;
  std::size_t points = 0;
  std::size_t thinned_points = 0;  // after voxel thinning
  std::size_t ground_points = 0;   // thinned points removed as ground
  std::size_t bridges = 0;         // edges added to join pieces the neighbour graph left apart
  std::vector<BridgedGap> gaps;    // the bridges longer than gap_m
  double gap_m = 0.0;              // NeighbourGraph::gap_m
  // The encoder works on the points minus this origin (scans/point_origin.hpp); the skeletons and
  // hulls above are moved back, in the input's coordinates.
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
};

// Throws ValueError for an empty point set, bad parameters, or when no root diameter is given
// and none can be estimated from the trunk.
EncodeResult encode_point_set(const PointSet& points, const EncodeOptions& options = {});

}  // namespace fspm::scans
