#pragma once
// The state of a plastic adaptation in progress (plastic_adaptation.cpp, Pirk 4.4) that its
// cluster light models (plastic_light.hpp) read and keep up to date: the trees being adapted with
// their transforms, the light field of every tree's leaf clusters in one numbering, and what
// changed since the light was last updated (the clusters moved in this step and the rigid group
// each moved with, the clusters pruned, a counter of changes).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "environment/cluster_light.hpp"
#include "environment/plastic_adaptation.hpp"
#include "environment/scene.hpp"
#include "environment/tree_analysis.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm::environment {

// The rigid group of a cluster nothing moved in this step.
inline constexpr std::uint64_t kStill = 0;

// x -> q x + t.
struct Rigid {
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  Eigen::Vector3d operator()(const Eigen::Vector3d& x) const { return q * x + t; }
};

// a after b.
inline Rigid compose(const Rigid& a, const Rigid& b) { return {a.q * b.q, a.q * b.t + a.t}; }

// One tree of a (lock-step) adaptation.
struct TreeRun {
  const TreeGraph* tree = nullptr;
  const TreeAnalysis* a = nullptr;
  std::uint32_t first_cluster = 0;       // index of its cluster 0 in the shared light field
  int first_step = 0;                    // step at which its age level 0 runs
  std::vector<NodeId> skeleton;          // skeleton nodes by id
  std::vector<NodeId> by_age;            // skeleton nodes sorted by (age, id): parents first
  std::vector<std::uint32_t> age_begin;  // by_age index of the first node of each age
  std::vector<std::uint32_t> pre, pre_pos, pre_size;        // skeleton pre-order
  std::vector<std::uint32_t> cluster_start, cluster_items;  // clusters anchored per node (CSR)
  std::vector<std::uint8_t> lateral, pruned;
  std::vector<std::uint32_t> skeleton_tips;  // skeleton tips in each skeleton node's subtree
  std::vector<Rigid> F;                      // accumulated transform
  std::vector<int> stamp;                    // step at which F was last changed (-1: never)
  std::vector<std::uint64_t> group;
  std::vector<double> zeta, length_below;
  std::vector<Eigen::Vector3d> light_sum;
  std::uint64_t aggregated_epoch = ~std::uint64_t{0};  // epoch of the last aggregate()
  AdaptationResult result;
};

struct AdaptationState {
  AdaptationState(const Scene& scene_in, int directions, double significance)
      : scene(scene_in), field(directions, significance, scene_in.sky.brightest) {}

  std::vector<TreeRun> runs;
  const Scene& scene;
  // Every tree's clusters (runs[k].first_cluster on): centre, life, light and direction.
  ClusterLightField field;
  std::vector<Eigen::Vector3d> center0;  // per cluster: its centre as analysed
  std::vector<std::uint32_t> owner;      // per cluster: its tree
  // Since the light was last updated: the clusters moved in this step, each with the rigid group
  // it moved with (group; kStill for the others), and its path length; the largest move of this
  // step; the clusters pruned. The engine empties `moved` (resetting their groups) and `vanished`
  // after each update.
  std::vector<std::uint32_t> moved, vanished;
  std::vector<std::uint64_t> group;
  std::vector<double> path;
  double step_max = 0.0;
  // Counts changes of what the engine's sums read (cluster light and life, pruned nodes): a light
  // model that sets new light counts one.
  std::uint64_t epoch = 0;
  int step = -1;  // the step the adaptation is at

  const TreeRun& run_of(std::uint32_t c) const { return runs[owner[c]]; }
  const LeafCluster& cluster(std::uint32_t c) const {
    const TreeRun& r = runs[owner[c]];
    return r.a->clusters[c - r.first_cluster];
  }
  // The rotation cluster c has been carried by (its anchor's).
  const Eigen::Quaterniond& anchor_rotation(std::uint32_t c) const {
    const TreeRun& r = runs[owner[c]];
    return r.F[r.a->clusters[c - r.first_cluster].anchor].q;
  }
  // The scene sky's brightest direction, +z when it has none.
  Eigen::Vector3d brightest() const {
    return scene.sky.brightest.norm() > 0 ? Eigen::Vector3d(scene.sky.brightest.normalized())
                                          : Eigen::Vector3d::UnitZ();
  }
};

}  // namespace fspm::environment
