#pragma once
// Light per leaf cluster for plastic trees (Pirk eq. 4.3 evaluated only at cluster centres), with
// everything an incremental update needs: each cluster's neighbour list (the clusters whose shadow
// volume, widened by a margin, contains it, and those in its own) with the relative positions at
// its last evaluation, and its cached obstacle visibility per sky direction. The adaptation moves
// and removes clusters and re-evaluates only those whose surroundings changed (Pirk 4.6: "the
// transformations are applied only in the affected areas").
//
// The light of one cluster is the same integral as LightModel's: the other clusters are spherical
// caps of translucency gamma inside their shadow volumes (significance cutoff), obstacles are
// ray-cast once per direction and cached. Disjoint caps above the horizon without obstacles are
// integrated in closed form (exact), otherwise over the stratified directions.
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "environment/hemisphere.hpp"
#include "environment/light_model.hpp"
#include "environment/scene.hpp"
#include "environment/sky_occlusion_kernel.hpp"
#include "environment/sphere_cap.hpp"

namespace fspm::environment {

struct ClusterNeighbor {
  std::uint32_t index = 0;   // the other cluster
  Eigen::Vector3f relative;  // its centre minus ours at our last evaluation
};

class ClusterLightField {
 public:
  // Margin added to the shadow reach when neighbour lists are built.
  static constexpr double kListMargin_m = 0.5;

  ClusterLightField(int directions, double significance, const Eigen::Vector3d& brightest);
  // A real sky's light per direction in place of the cos^2 sky (sky_distribution.hpp: weights,
  // mean direction, cutoff lowered by its peak, closed forms off). Call before set_clusters.
  void set_sky_distribution(std::shared_ptr<const SkyDistribution> distribution);

  // Replaces the clusters (centres, radii, translucencies); all alive, nothing evaluated.
  void set_clusters(std::span<const Eigen::Vector3d> centers, std::span<const double> radii,
                    std::span<const double> translucency);
  std::size_t size() const { return center_.size(); }

  // Obstacles (the scene's boxes, meshes, ground and spheres). Clusters are never obstacles.
  void set_obstacles(const Scene& scene);
  bool has_obstacles() const { return has_obstacles_; }

  // Rebuilds the point grid over the alive clusters' current centres (call after moving them and
  // before evaluate()).
  void rebuild_grid();

  // Recomputes cluster c's obstacle visibility at its current centre; true when it differs from
  // the cached one.
  bool update_obstacles(std::uint32_t c);
  // True when c moved far enough since its obstacle visibility was computed to need a new one.
  bool obstacles_stale(std::uint32_t c) const;
  // Cluster c's cached obstacle transmission per sky direction (directions(n) order), empty when
  // nothing is in the way.
  std::span<const float> obstacle_visibility(std::uint32_t c) const { return obstacle_vis_[c]; }
  // Cluster c's light from the sky through the obstacles alone (its cached visibility, no
  // clusters): the share of the open sky's light, and its mean direction in `direction`. Summed
  // when the visibility changes, not when asked: the shadow-grid adaptation asks for every
  // cluster at every age level.
  double sky_light(std::uint32_t c, Eigen::Vector3d& direction) const;

  // Light and direction of cluster c from the alive clusters and the cached obstacle visibility.
  // The candidates are c's neighbour list (whose relative positions are refreshed) unless c
  // drifted by more than half the list margin against one of them, or `rebuild`: then the list
  // is rebuilt from the point grid (rebuilt on demand after mark_moved()).
  void evaluate(std::uint32_t c, bool rebuild = false);
  // Evaluates every cluster in `which` with one LightModel built over the obstacles and the alive
  // clusters (cheaper than per-cluster evaluation when many are due); refreshes their lists'
  // relative positions (rebuilding the list from the grid for those flagged in `relist`).
  void evaluate_batch(std::span<const std::uint32_t> which, std::span<const std::uint8_t> relist);

  // Positions changed: the point grid is rebuilt before it is next needed.
  void mark_moved() { grid_stale_ = true; }

  // Neighbour list of c, possibly still the analysis' (read through an index offset).
  struct ListView {
    const ClusterNeighbor* data = nullptr;
    std::size_t size = 0;
    std::uint32_t offset = 0;
    const ClusterNeighbor* begin() const { return data; }
    const ClusterNeighbor* end() const { return data + size; }
  };
  ListView neighbors(std::uint32_t c) const {
    if (external_[c] != nullptr) {
      return {external_[c]->data(), external_[c]->size(), external_offset_[c]};
    }
    return {neighbors_[c].data(), neighbors_[c].size(), 0};
  }
  // Uses `list` (indices + offset) as c's neighbour list until c is next evaluated; `list` must
  // outlive the field's use of it.
  void share_list(std::uint32_t c, const std::vector<ClusterNeighbor>* list, std::uint32_t offset) {
    external_[c] = list;
    external_offset_[c] = offset;
    listed_[c] = 1;
  }
  double reach(std::uint32_t c) const { return reach_[c]; }
  // Upper bound of the share of light cluster j takes from a point at offset d from its centre
  // (0 outside its shadow volume or below the point's horizon).
  double loss_bound(std::uint32_t j, const Eigen::Vector3d& d) const;

  // Per-cluster state, read by the adaptation's incremental bookkeeping.
  const Eigen::Vector3d& center(std::uint32_t c) const { return center_[c]; }
  bool alive(std::uint32_t c) const { return alive_[c] != 0; }
  double light(std::uint32_t c) const { return light_[c]; }
  const Eigen::Vector3d& direction(std::uint32_t c) const { return direction_[c]; }
  double radius(std::uint32_t c) const { return radius_[c]; }
  // Squared shadow reach of c (negative: it shades nothing).
  double reach2(std::uint32_t c) const { return reach2_[c]; }
  std::span<const Eigen::Vector3d> centers() const { return center_; }
  std::span<const std::uint8_t> alive_flags() const { return alive_; }
  std::span<const double> lights() const { return light_; }
  std::span<const Eigen::Vector3d> directions() const { return direction_; }

  // Moves c's centre; call mark_moved() once a step's moves are done.
  void move(std::uint32_t c, const Eigen::Vector3d& to) { center_[c] = to; }
  // Removes c (pruned): it no longer shades and is no longer evaluated.
  void remove(std::uint32_t c) { alive_[c] = 0; }
  // Light and direction of c given from outside (the analysis' cache, the shadow grid); counted as
  // an evaluation when `evaluated`.
  void set_light(std::uint32_t c, double light, const Eigen::Vector3d& direction,
                 bool evaluated = false) {
    light_[c] = light;
    direction_[c] = direction;
    if (evaluated) ++evaluations_;
  }
  // The neighbour lists built by evaluate(), moved out (the field keeps empty lists).
  std::vector<std::vector<ClusterNeighbor>> take_neighbor_lists() { return std::move(neighbors_); }
  std::size_t evaluations() const { return evaluations_; }  // diagnostics

  const Eigen::Vector3d& open_direction() const { return open_direction_; }

 private:
  using Cap = SphereCap;
  void obstacle_visibility(const Eigen::Vector3d& p, std::vector<float>& vis,
                           double& distance) const;
  void update_sky_light(std::uint32_t c);

  std::vector<Eigen::Vector3d> center_;
  std::vector<double> radius_, gamma_, reach2_, reach_;
  std::vector<std::uint8_t> alive_;
  std::vector<double> light_;
  std::vector<Eigen::Vector3d> direction_;
  std::vector<std::vector<ClusterNeighbor>> neighbors_;
  std::size_t evaluations_ = 0;
  HemisphereDirections dirs_;
  std::vector<double> weight_;
  double weight_sum_ = 0.0;
  double significance_ = 0.01;
  std::shared_ptr<const SkyDistribution> distribution_;  // null: the cos^2 sky
  Eigen::Vector3d brightest_ = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d open_direction_ = Eigen::Vector3d::UnitZ();
  double max_reach_ = 0.0;
  double max_radius_ = 0.0;

  // Obstacles.
  Scene obstacles_;
  bool has_obstacles_ = false;
  std::vector<std::vector<float>> obstacle_vis_;  // per cluster: empty = open sky
  std::vector<double> sky_share_;                 // sky_light() per cluster, from obstacle_vis_
  std::vector<Eigen::Vector3d> sky_direction_;
  std::vector<BoxRayDirections> box_rays_;     // the sky directions in box k's frame
  mutable std::vector<std::uint8_t> box_hit_;  // scratch: which directions hit the box
  std::vector<Eigen::Vector3d> obstacle_at_;   // centre where it was computed
  std::vector<double> obstacle_tolerance2_;    // squared move that makes it stale

  // Uniform point grid (CSR) over alive centres.
  Eigen::Vector3d grid_lo_ = Eigen::Vector3d::Zero();
  Eigen::Vector3i grid_n_ = Eigen::Vector3i::Zero();
  double cell_ = 1.0;
  std::vector<std::uint32_t> cell_start_, cell_items_;

  std::vector<const std::vector<ClusterNeighbor>*> external_;
  std::vector<std::uint32_t> external_offset_;
  std::vector<std::uint8_t> listed_;  // has a neighbour list
  bool grid_stale_ = true;
  std::vector<float> xs_, ys_, zs_;  // direction components (single precision lanes)

  void gather_from_grid(std::uint32_t c, double& all);
  void add_occluder(std::uint32_t c, std::uint32_t j, const Eigen::Vector3d& d, double& all);
  // c's own neighbour list, first copied from a shared one (share_list) that it may then update.
  std::vector<ClusterNeighbor>& own_neighbor_list(std::uint32_t c);
  // Applies caps_ to vis_, each cap only over the rings of directions it can reach.
  void occlude_cap_rings(DirectionColumns<float> columns);

  // Scratch (no allocation per evaluation once warm).
  std::vector<Cap> caps_;
  std::vector<float> vis_;
  std::vector<float> scratch_vis_;
  std::vector<OccludingCap<float>> packed_caps_;
  std::vector<std::uint32_t> scratch_fill_;
};

}  // namespace fspm::environment
