#pragma once
// Analysis of a tree "grown in the open" for plastic adaptation (Pirk 4.3): the main skeleton is
// split from the fine branches by a thickness threshold, the fine parts become leaf clusters
// (Pirk eq. 4.4 translucency), internode length by mean-shift over the distances between nearest
// branching nodes, growth rates (eq. 4.1) and branch ages (eq. 4.2), the inverse tropism of every
// skeleton segment (eq. 4.8-4.10) and the minimum pruning factors (eq. 4.11-4.12).
//
// Light: evaluated once per leaf cluster (ClusterLightField); a segment's light direction is that
// of the clusters it carries (segment_light_direction).
//
// Light of earlier growth stages (optional, temporal_pruning): clusters propagated toward the root
// (eq. 4.5) give psi_s(t) at every stage t. By default only the final stage is used (see
// docs/environment.md: with all stages the thresholds become so low that nothing is pruned).
// The tropisms always use the light of the final stage, so an unchanged scene adapts to exactly
// the input tree.
#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "environment/cluster_grid_light.hpp"
#include "environment/cluster_light.hpp"
#include "environment/leaf_light_model.hpp"
#include "environment/light_model_registry.hpp"
#include "environment/occluders.hpp"
#include "environment/shadow_grid.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm::environment {

inline constexpr std::uint32_t kNoCluster = std::numeric_limits<std::uint32_t>::max();

struct AnalysisParams {
  // Internodes at least this thick belong to the skeleton; <= 0 picks 2.5 times the thinnest
  // internode radius (with the pipe model that is a branch carrying about ten tips).
  double skeleton_radius_m = 0.0;
  double min_cluster_radius_m = 0.3;
  double gamma0 = 0.5;                 // Pirk eq. 4.4
  double pruning_strength = 0.8;       // c_psi, Pirk eq. 4.12
  double reference_percentile = 0.05;  // psi_ref, Pirk 4.3.4
  // psi_s(t) over every earlier stage (eq. 4.5 cluster propagation) instead of the final one.
  bool temporal_pruning = false;
  // During adaptation the thresholds of eq. 4.12 follow the whole tree's resources per length
  // (psi at the root now against at the analysis), so a branch is pruned when it falls behind the
  // rest of the crown, not when the whole crown gets less light (see docs/environment.md).
  bool relative_pruning = true;
  // Tropism weights w_tau of eq. 4.6-4.7 (Pirk exposes them as user parameters; defaults: type A).
  double phototropism = 0.25;
  double gravitropism = 0.12;
  Eigen::Vector3d gravity_direction = -Eigen::Vector3d::UnitZ();
  // Which light the analysis and the adaptation give the leaf clusters, a model of
  // kClusterLightModelNames (light_model_registry.hpp): the crown's leaves as turbid media through
  // a leaf light model (`canopy_model`; the whole crown evaluated again at every age level that
  // moved or pruned something), the sky hemisphere with the other clusters as caps (Pirk eq. 4.3;
  // ClusterLightField, re-evaluated cluster by cluster where the change reaches), or Palubicki's
  // local shadow grid (ClusterGridLight), the light the growth model's default trees grew under.
  ClusterLightModel light_model = ClusterLightModel::kCanopy;
  // The leaf light model of light_model kCanopy (a name of leaf_light_models()).
  std::string canopy_model = kAdaptationLeafLightModel;
  // Light as in the growth model: few directions, a coarse shadow-volume cutoff (see Sky).
  int light_directions = 64;
  double light_significance = 0.01;
  // The grid of light_model kShadowGrid (cluster_grid_light.hpp).
  ShadowGridParams shadow_grid = cluster_grid_params();

  // Throws ValueError naming the parameter and its allowed range.
  void validate() const;
};

struct LeafCluster {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius_m = 0.0;
  double translucency = 1.0;  // gamma0 ^ radius (eq. 4.4)
  NodeId anchor = kNoNode;    // the skeleton node the fine subtree hangs from
  std::vector<NodeId> nodes;  // member nodes (the fine subtree)
  // Normalised leaf density (Pirk eq. 4.13, rho(i) = i): 1 at analysis time, rho0 i / i0 after
  // adaptation.
  double density = 1.0;
};

struct TreeAnalysis {
  AnalysisParams params;
  double skeleton_radius_m = 0.0;
  double internode_length_m = 0.0;        // l_i, mean-shift mode
  double height_path_m = 0.0;             // d_r: path length root -> furthest tip
  std::vector<std::uint8_t> skeleton;     // per node: 1 skeleton, 0 fine part
  std::vector<std::uint32_t> cluster_of;  // per node: cluster index or kNoCluster
  std::vector<LeafCluster> clusters;
  std::vector<double> growth_rate;  // absolute nu_s (eq. 4.1, nu_hat / nu_hat_min)
  std::vector<int> age;             // season the segment was created, 0 = oldest (eq. 4.2)
  int max_age = 0;
  std::vector<double> cluster_light;       // i_c at analysis time
  std::vector<double> pruning_factor;      // psi_s at analysis time (0 for fine nodes)
  std::vector<double> min_pruning_factor;  // psi_s_min (eq. 4.12)
  double reference_pruning_factor = 0.0;   // psi_ref
  std::vector<double> tropism_weight;      // w_s (eq. 4.7)
  std::vector<Eigen::Vector3d> tropism;    // t at analysis time (unit weighted mean, eq. 4.6)
  std::vector<Eigen::Vector3d> original_direction;  // d_o (eq. 4.8-4.10)
  // The light cache the adaptation starts from (cluster_light.hpp): the sky's brightest point,
  // each cluster's mean light direction and its neighbour list with relative positions.
  Eigen::Vector3d brightest = Eigen::Vector3d::UnitZ();
  std::vector<Eigen::Vector3d> cluster_direction;
  std::vector<std::vector<ClusterNeighbor>> cluster_neighbors;
};

// Pirk eq. 4.11 for one cluster: 2 pi r^2 i.
inline double cluster_resources(double radius_m, double light) {
  return 2.0 * 3.14159265358979323846 * radius_m * radius_m * light;
}

// The light direction a skeleton segment bends toward: the resource-weighted mean light direction
// of the clusters below it (sum of cluster_resources * direction, accumulated toward the root),
// or `open` when they receive no light. Light is evaluated per cluster, not per node.
inline Eigen::Vector3d segment_light_direction(const Eigen::Vector3d& weighted_sum,
                                               const Eigen::Vector3d& open) {
  const double norm = weighted_sum.norm();
  return norm > 1e-12 ? Eigen::Vector3d(weighted_sum / norm) : open;
}

// One-dimensional mean-shift with a flat kernel of half-width `bandwidth` started from every
// sample; returns the mode that attracts the most samples (ties: the smaller). Empty -> 0.
double mean_shift_mode(std::vector<double> samples, double bandwidth);

// Inverse tropism (Pirk eq. 4.8-4.10): the unit d_o with h on the line of w_s d_o + (1 - w_s) t,
// the largest root of eq. 4.10, or the closest point when it has none.
Eigen::Vector3d inverse_tropism(const Eigen::Vector3d& h, const Eigen::Vector3d& t, double w_s);

// Translucency, light, tropisms and pruning of the tree alone in an open scene with the sky's
// brightest point `brightest`. Deterministic. Throws ValueError for an empty tree or invalid
// parameters.
TreeAnalysis analyze_tree(const TreeGraph& tree, const AnalysisParams& params = {},
                          const Eigen::Vector3d& brightest = Eigen::Vector3d::UnitZ());

// The member node ends of every cluster, grouped by cluster: those of cluster c are
// buds[bud_start[c] .. bud_start[c + 1]) (the buds of ClusterGridLight).
void cluster_buds(const TreeGraph& tree, const std::vector<LeafCluster>& clusters,
                  std::vector<Eigen::Vector3d>& buds, std::vector<std::uint32_t>& bud_start);

// The analysis' clusters as light-model spheres (non-solid).
std::vector<Sphere> cluster_spheres(const std::vector<LeafCluster>& clusters);

}  // namespace fspm::environment
