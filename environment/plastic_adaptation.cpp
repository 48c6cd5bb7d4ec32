#include "environment/plastic_adaptation.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

#include "environment/cluster_grid_light.hpp"
#include "environment/cluster_light.hpp"
#include "environment/leaf_light_model.hpp"
#include "environment/sky_distribution.hpp"
#include "environment/solid_push.hpp"
#include "fspm/attribute_names.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {
namespace {

constexpr std::uint64_t kStill = 0;  // group of clusters nothing moved in this step
// Relative drift that counts, as a share of the distance (about 9 degrees of parallax: half the
// width of one of the 64 sky cells).
constexpr double kDriftParallax = 0.15;
// Possible change of a cluster's light (share of the open sky's) from drifted or vanished
// neighbours before it is re-evaluated: about the resolution of the 64-direction sky (one cell
// near the zenith carries 3 cos^2 / 64 = 4.7 % of the light).
constexpr double kLightChange = 0.05;
// Refreshes with at least 1/kBatchShare of the clusters due use one LightModel for all.
constexpr std::size_t kBatchShare = 8;
// Pirk 5.3.2, after Shinozaki's pipe model: a branch stops bending once it carries this many
// terminal edges of the skeleton; it is then "solid". Below, a segment's eq. 4.6 turn is scaled by
// its bendability (solid_edges - tips) / (solid_edges - 1): 1 for a skeleton tip, 0 when solid.
// Without it an old, thick segment turns like a young shoot and swings the whole crown it
// carries, which the growth model, where an internode never turns once grown, does not do
// (docs/environment.md).
constexpr std::uint32_t kSolidTerminalEdges = 5;

double bendability(std::uint32_t skeleton_tips) {
  if (skeleton_tips >= kSolidTerminalEdges) return 0.0;
  return static_cast<double>(kSolidTerminalEdges - skeleton_tips) /
         static_cast<double>(kSolidTerminalEdges - 1);
}

bool is_internode(const TreeGraph& t, NodeId n) { return t.kind(n) == OrganKind::kInternode; }

// x -> q x + t.
struct Rigid {
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  Eigen::Vector3d operator()(const Eigen::Vector3d& x) const { return q * x + t; }
};

// a after b.
Rigid compose(const Rigid& a, const Rigid& b) { return {a.q * b.q, a.q * b.t + a.t}; }

// First node of a lateral branch: a higher branching order than its parent or, for trees without
// orders, not the parent's first internode child.
std::vector<std::uint8_t> lateral_bases(const TreeGraph& t) {
  std::vector<std::uint8_t> out(t.size(), 0);
  bool has_orders = false;
  for (NodeId i = 0; i < t.size(); ++i) has_orders = has_orders || t.order(i) != 0;
  for (NodeId p = 0; p < t.size(); ++p) {
    bool first = true;
    for (const NodeId c : t.children(p)) {
      if (!is_internode(t, c)) continue;
      out[c] = has_orders ? t.order(c) > t.order(p) : !first;
      first = false;
    }
  }
  return out;
}

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
  std::vector<int> stamp;                    // step at which S was set
  std::vector<std::uint64_t> group;
  std::vector<double> zeta, length_below;
  std::vector<Eigen::Vector3d> light_sum;
  std::uint64_t aggregated_epoch = ~std::uint64_t{0};  // epoch_ of the last aggregate()
  AdaptationResult result;
};

class Engine {
 public:
  Engine(const std::vector<const TreeGraph*>& trees,
         const std::vector<const TreeAnalysis*>& analyses, const Scene& scene);
  std::vector<AdaptationResult> run();

 private:
  void collect_clusters(const std::vector<const TreeGraph*>& trees,
                        const std::vector<const TreeAnalysis*>& analyses);
  void setup_sky();
  void mark_near_other_trees();
  void setup_tree(TreeRun& r);
  void aggregate(TreeRun& r);
  void bend(TreeRun& r, int level, int step);
  bool turn_blocked(const TreeRun& r, NodeId m, const Rigid& turn) const;
  void prune(TreeRun& r, int level);
  void prune_subtree(TreeRun& r, NodeId s);
  void prune_blocked(TreeRun& r, int step);
  void mark_dirty(std::uint32_t c);
  void mark_evaluated(std::uint32_t c);
  void note_drift(std::uint32_t c, std::uint32_t j, const ClusterNeighbor& e);
  void release_vanished_shade();
  void check_moved();
  void refresh();
  void setup_grid();
  void regrid();
  void setup_canopy();
  void recanopy();
  void update_light() {
    if (canopy_) {
      recanopy();
    } else if (grid_) {
      regrid();
    } else {
      check_moved();
      refresh();
    }
  }
  void finish(TreeRun& r);
  const Eigen::Quaterniond& anchor_rotation(std::uint32_t c) const {
    const TreeRun& r = runs_[owner_[c]];
    return r.F[r.a->clusters[c - r.first_cluster].anchor].q;
  }

  std::vector<TreeRun> runs_;
  const Scene& scene_;
  ClusterLightField field_;
  std::vector<Eigen::Vector3d> center0_;
  std::vector<Eigen::Quaterniond> eval_q_;  // cluster rotation at its last evaluation
  std::vector<std::uint64_t> cgroup_;       // cluster group in this step
  std::vector<std::uint32_t> moved_, vanished_, dirty_list_, check_list_;
  std::vector<std::uint8_t> dirty_, check_, relist_;
  std::vector<double> lost_;
  // Path lengths for the drift bound: per cluster (total and at its evaluation), and the sum of
  // the per-step maxima over all clusters (total and at each cluster's evaluation).
  std::vector<double> path_, eval_path_, eval_all_path_;
  double all_path_ = 0.0, step_max_ = 0.0;
  std::vector<std::uint32_t> owner_;  // tree of each cluster
  // Counts changes of what aggregate() reads (cluster light and life, pruned nodes), so that an
  // unchanged tree is not summed again.
  std::uint64_t epoch_ = 0;
  // Shadow-grid light (ClusterLightModel::kShadowGrid): every cluster's buds, as analysed and as
  // moved, refilled into the grid after every step that moved or pruned something.
  std::unique_ptr<ClusterGridLight> grid_;
  std::vector<double> grid_light_;  // the grid's light and direction before the sky's share
  std::vector<Eigen::Vector3d> grid_direction_;
  bool has_solids_ = false;  // the scene has a solid box, sphere or mesh
  std::vector<Eigen::Vector3d> buds0_, buds_;
  std::vector<std::uint32_t> bud_start_, bud_cluster_;
  std::uint64_t grid_epoch_ = ~std::uint64_t{0};
  // Canopy light (ClusterLightModel::kCanopy): the whole crown through a leaf light model,
  // evaluated again after every step that moved or pruned something.
  std::unique_ptr<LeafLightModel> canopy_;
  std::vector<Sphere> canopy_spheres_;
  std::vector<std::uint32_t> canopy_index_;
  std::vector<std::span<const float>> canopy_vis_;
  std::vector<LightSample> canopy_out_;
  int step_ = -1;  // the step run() is at
};

Engine::Engine(const std::vector<const TreeGraph*>& trees,
               const std::vector<const TreeAnalysis*>& analyses, const Scene& scene)
    : scene_(scene),
      field_(analyses.empty() ? 64 : analyses.front()->params.light_directions,
             analyses.empty() ? 0.01 : analyses.front()->params.light_significance,
             scene.sky.brightest) {
  if (scene.sky.distribution) field_.set_sky_distribution(scene.sky.distribution);  // a real sky
  if (trees.size() != analyses.size()) {
    throw ValueError("plastic adaptation: one analysis per tree expected");
  }
  collect_clusters(trees, analyses);
  field_.set_obstacles(scene);
  for (const Box& b : scene.boxes) has_solids_ = has_solids_ || b.solid;
  for (const Sphere& b : scene.spheres) has_solids_ = has_solids_ || b.solid;
  for (const TriangleMesh& m : scene.meshes) has_solids_ = has_solids_ || m.solid;
  const ClusterLightModel model = runs_.front().a->params.light_model;
  for (const TreeRun& r : runs_) {
    if (r.a->params.light_model != model ||
        (model == ClusterLightModel::kCanopy &&
         r.a->params.canopy_model != runs_.front().a->params.canopy_model)) {
      throw ValueError("plastic adaptation: the trees were analysed with different light models");
    }
  }
  switch (model) {
    case ClusterLightModel::kShadowGrid:
      setup_grid();
      break;
    case ClusterLightModel::kCanopy:
      setup_canopy();
      break;
    case ClusterLightModel::kSky:
      setup_sky();
      break;
  }
}

// Every tree's clusters into one numbering (runs_[k].first_cluster on), the cluster state sized
// to them.
void Engine::collect_clusters(const std::vector<const TreeGraph*>& trees,
                              const std::vector<const TreeAnalysis*>& analyses) {
  runs_.resize(trees.size());
  std::vector<Eigen::Vector3d> centers;
  std::vector<double> radii, gammas;
  int max_levels = 0;
  for (std::size_t k = 0; k < trees.size(); ++k) {
    const TreeGraph& t = *trees[k];
    const TreeAnalysis& a = *analyses[k];
    const std::size_t n = t.size();
    if (a.skeleton.size() != n || a.age.size() != n || a.cluster_of.size() != n ||
        a.cluster_light.size() != a.clusters.size() ||
        a.cluster_direction.size() != a.clusters.size() ||
        a.cluster_neighbors.size() != a.clusters.size()) {
      throw ValueError("plastic adaptation: the analysis was made for another tree");
    }
    runs_[k].tree = &t;
    runs_[k].a = &a;
    runs_[k].first_cluster = static_cast<std::uint32_t>(centers.size());
    for (const LeafCluster& c : a.clusters) {
      centers.push_back(c.center);
      radii.push_back(c.radius_m);
      gammas.push_back(c.translucency);
      owner_.push_back(static_cast<std::uint32_t>(k));
    }
    max_levels = std::max(max_levels, a.max_age + 1);
  }
  // Pirk 4.4.3: the younger trees start later so that all finish together.
  for (TreeRun& r : runs_) r.first_step = max_levels - (r.a->max_age + 1);

  field_.set_clusters(centers, radii, gammas);
  center0_ = centers;
  const std::size_t nc = centers.size();
  eval_q_.assign(nc, Eigen::Quaterniond::Identity());
  cgroup_.assign(nc, kStill);
  dirty_.assign(nc, 0);
  relist_.assign(nc, 0);
  lost_.assign(nc, 0.0);
  path_.assign(nc, 0.0);
  eval_path_.assign(nc, 0.0);
  eval_all_path_.assign(nc, 0.0);
  check_.assign(nc, 0);
}

// Sky light (Pirk eq. 4.3): the analysis' light is kept and only what changed against it is
// evaluated again: the sky (everything), obstacles (the clusters they shade), neighbouring trees
// (the clusters within reach of another tree).
void Engine::setup_sky() {
  bool sky_changed = false;
  const Eigen::Vector3d b = scene_.sky.brightest.norm() > 0
                                ? Eigen::Vector3d(scene_.sky.brightest.normalized())
                                : Eigen::Vector3d::UnitZ();
  for (const TreeRun& r : runs_) {
    const TreeAnalysis& a = *r.a;
    sky_changed = sky_changed || (a.brightest - b).norm() > 1e-12 ||
                  a.params.light_directions != runs_.front().a->params.light_directions ||
                  a.params.light_significance != runs_.front().a->params.light_significance;
    for (std::size_t c = 0; c < a.clusters.size(); ++c) {
      const std::uint32_t g = r.first_cluster + static_cast<std::uint32_t>(c);
      field_.set_light(g, a.cluster_light[c], a.cluster_direction[c]);
      field_.share_list(g, &a.cluster_neighbors[c], r.first_cluster);
    }
  }
  for (TreeRun& r : runs_) setup_tree(r);
  const auto nc = static_cast<std::uint32_t>(field_.size());
  if (sky_changed) {
    for (std::uint32_t c = 0; c < nc; ++c) mark_dirty(c);
  }
  if (field_.has_obstacles()) {
    for (std::uint32_t c = 0; c < nc; ++c) {
      if (field_.update_obstacles(c)) mark_dirty(c);
    }
  }
  if (runs_.size() > 1) mark_near_other_trees();
  refresh();
}

// The clusters within light reach of another tree's box: evaluated again, and their neighbour
// lists, which the analysis made against their own tree only, made again.
void Engine::mark_near_other_trees() {
  const auto nc = static_cast<std::uint32_t>(field_.size());
  double reach = 0.0;
  for (std::uint32_t c = 0; c < nc; ++c) {
    if (field_.reach2(c) >= 0.0) reach = std::max(reach, std::sqrt(field_.reach2(c)));
  }
  reach += ClusterLightField::kListMargin_m;
  std::vector<Eigen::AlignedBox3d> boxes(runs_.size());
  for (std::uint32_t c = 0; c < nc; ++c) boxes[owner_[c]].extend(center0_[c]);
  for (auto& b : boxes) {
    if (!b.isEmpty()) b = Eigen::AlignedBox3d(b.min().array() - reach, b.max().array() + reach);
  }
  for (std::uint32_t c = 0; c < nc; ++c) {
    for (std::size_t k = 0; k < boxes.size(); ++k) {
      if (k != owner_[c] && boxes[k].contains(center0_[c])) {
        mark_dirty(c);
        relist_[c] = 1;
      }
    }
  }
}

void Engine::setup_grid() {
  const std::size_t nc = field_.size();
  bud_start_.assign(1, 0);
  for (TreeRun& r : runs_) {
    setup_tree(r);
    std::vector<Eigen::Vector3d> buds;
    std::vector<std::uint32_t> start;
    cluster_buds(*r.tree, r.a->clusters, buds, start);
    for (std::size_t c = 0; c + 1 < start.size(); ++c) {
      for (std::uint32_t b = start[c]; b < start[c + 1]; ++b) {
        buds0_.push_back(buds[b]);
        bud_cluster_.push_back(static_cast<std::uint32_t>(bud_start_.size() - 1));
      }
      bud_start_.push_back(static_cast<std::uint32_t>(buds0_.size()));
    }
  }
  buds_ = buds0_;
  grid_ = std::make_unique<ClusterGridLight>(runs_.front().a->params.shadow_grid, scene_);
  const Eigen::Vector3d brightest = scene_.sky.brightest.norm() > 0
                                        ? Eigen::Vector3d(scene_.sky.brightest.normalized())
                                        : Eigen::Vector3d::UnitZ();
  if (!field_.has_obstacles() && runs_.size() == 1 &&
      (runs_.front().a->brightest - brightest).norm() <= 1e-12) {
    // The analysis' own light: nothing differs from the open scene until something moves.
    const TreeAnalysis& a = *runs_.front().a;
    for (std::uint32_t c = 0; c < nc; ++c) {
      field_.set_light(c, a.cluster_light[c], a.cluster_direction[c]);
    }
    grid_epoch_ = epoch_;
    return;
  }
  for (std::uint32_t c = 0; c < nc; ++c) field_.update_obstacles(c);
  regrid();
}

// The buds follow their cluster's anchor; the grid is refilled and every living cluster's light
// read again, unless nothing moved or was pruned since the last time.
void Engine::regrid() {
  moved_.clear();
  vanished_.clear();
  if (grid_epoch_ == epoch_) return;
  // Only the anchors bent in this step have a new transform (an earlier step's buds were placed
  // at that step's refill: bend() changes epoch_ whenever it moves something).
  for (std::size_t b = 0; b < buds_.size(); ++b) {
    const std::uint32_t g = bud_cluster_[b];
    const TreeRun& r = runs_[owner_[g]];
    const NodeId anchor = r.a->clusters[g - r.first_cluster].anchor;
    if (r.stamp[anchor] >= 0 && r.stamp[anchor] == step_) buds_[b] = r.F[anchor](buds0_[b]);
  }
  grid_light_.assign(field_.lights().begin(), field_.lights().end());
  grid_direction_.assign(field_.directions().begin(), field_.directions().end());
  grid_->evaluate(buds_, bud_start_, field_.centers(), field_.alive_flags(), grid_light_,
                  grid_direction_);
  for (std::uint32_t c = 0; c < field_.size(); ++c) {
    if (!field_.alive(c)) continue;
    if (field_.obstacles_stale(c)) field_.update_obstacles(c);
    Eigen::Vector3d sky_direction;
    const double sky = field_.sky_light(c, sky_direction);
    combine_sky_and_grid(sky, sky_direction, grid_light_[c], grid_direction_[c]);
    field_.set_light(c, grid_light_[c], grid_direction_[c], true);
  }
  ++epoch_;
  grid_epoch_ = epoch_;
}

void Engine::setup_canopy() {
  for (TreeRun& r : runs_) setup_tree(r);
  const AnalysisParams& params = runs_.front().a->params;
  Sky sky;
  sky.directions = params.light_directions;
  sky.significance = params.light_significance;
  sky.brightest = scene_.sky.brightest.norm() > 0
                      ? Eigen::Vector3d(scene_.sky.brightest.normalized())
                      : Eigen::Vector3d::UnitZ();
  // A real sky's light per direction (sky_distribution.hpp) instead of the cos^2 sky.
  if (scene_.sky.distribution) apply_sky_distribution(sky, scene_.sky.distribution);
  canopy_ = make_leaf_light_model(params.canopy_model, sky);
  if (!field_.has_obstacles() && runs_.size() == 1 && !sky.distribution &&
      (runs_.front().a->brightest - sky.brightest).norm() <= 1e-12) {
    // The analysis' own light: nothing differs from the open scene until something moves.
    const TreeAnalysis& a = *runs_.front().a;
    for (std::uint32_t c = 0; c < field_.size(); ++c) {
      field_.set_light(c, a.cluster_light[c], a.cluster_direction[c]);
    }
    grid_epoch_ = epoch_;
    return;
  }
  for (std::uint32_t c = 0; c < field_.size(); ++c) field_.update_obstacles(c);
  recanopy();
}

// Every living cluster's light through the leaf light model, at the clusters' current places,
// with each cluster's cached obstacle visibility (recomputed where it moved enough).
void Engine::recanopy() {
  moved_.clear();
  vanished_.clear();
  if (grid_epoch_ == epoch_) return;
  canopy_spheres_.clear();
  canopy_index_.clear();
  canopy_vis_.clear();
  bool any_obstacle = false;
  for (std::uint32_t c = 0; c < field_.size(); ++c) {
    if (!field_.alive(c)) continue;
    if (field_.obstacles_stale(c)) field_.update_obstacles(c);
    const TreeRun& r = runs_[owner_[c]];
    const LeafCluster& k = r.a->clusters[c - r.first_cluster];
    canopy_spheres_.push_back({field_.center(c), k.radius_m, k.translucency, false});
    canopy_index_.push_back(c);
    canopy_vis_.push_back(field_.obstacle_visibility(c));
    any_obstacle = any_obstacle || !canopy_vis_.back().empty();
  }
  canopy_out_.resize(canopy_spheres_.size());
  canopy_->evaluate(canopy_spheres_,
                    any_obstacle ? std::span<const std::span<const float>>(canopy_vis_)
                                 : std::span<const std::span<const float>>(),
                    canopy_out_);
  for (std::size_t k = 0; k < canopy_index_.size(); ++k) {
    field_.set_light(canopy_index_[k], canopy_out_[k].light, canopy_out_[k].direction, true);
  }
  ++epoch_;
  grid_epoch_ = epoch_;
}

void Engine::setup_tree(TreeRun& r) {
  const TreeGraph& t = *r.tree;
  const TreeAnalysis& a = *r.a;
  const std::size_t n = t.size();
  for (NodeId i = 0; i < n; ++i) {
    if (a.skeleton[i]) r.skeleton.push_back(i);
  }
  r.by_age = r.skeleton;
  std::stable_sort(r.by_age.begin(), r.by_age.end(),
                   [&](NodeId x, NodeId y) { return a.age[x] < a.age[y]; });
  r.age_begin.assign(static_cast<std::size_t>(a.max_age) + 2, 0);
  for (const NodeId m : r.by_age) ++r.age_begin[static_cast<std::size_t>(a.age[m]) + 1];
  for (std::size_t k = 1; k < r.age_begin.size(); ++k) r.age_begin[k] += r.age_begin[k - 1];
  // Skeleton pre-order (children of a skeleton node in id order).
  r.pre_pos.assign(n, 0);
  r.pre_size.assign(n, 1);
  {
    std::vector<NodeId> stack = {0};
    while (!stack.empty()) {
      const NodeId m = stack.back();
      stack.pop_back();
      r.pre_pos[m] = static_cast<std::uint32_t>(r.pre.size());
      r.pre.push_back(m);
      const std::size_t before = stack.size();
      for (const NodeId c : t.children(m)) {
        if (a.skeleton[c]) stack.push_back(c);
      }
      std::reverse(stack.begin() + static_cast<std::ptrdiff_t>(before), stack.end());
    }
    for (auto it = r.skeleton.rbegin(); it != r.skeleton.rend(); ++it) {
      if (*it != 0) r.pre_size[t.parent(*it)] += r.pre_size[*it];
    }
  }
  r.cluster_start.assign(n + 1, 0);
  for (const LeafCluster& c : a.clusters) ++r.cluster_start[c.anchor + 1];
  for (std::size_t i = 0; i < n; ++i) r.cluster_start[i + 1] += r.cluster_start[i];
  r.cluster_items.resize(a.clusters.size());
  {
    std::vector<std::uint32_t> fill(r.cluster_start.begin(), r.cluster_start.end() - 1);
    for (std::uint32_t c = 0; c < a.clusters.size(); ++c) {
      r.cluster_items[fill[a.clusters[c].anchor]++] = c;
    }
  }
  r.lateral = lateral_bases(t);
  r.skeleton_tips.assign(n, 0);
  for (auto it = r.skeleton.rbegin(); it != r.skeleton.rend(); ++it) {
    if (r.skeleton_tips[*it] == 0) r.skeleton_tips[*it] = 1;  // no skeleton child: a tip
    if (*it != 0) r.skeleton_tips[t.parent(*it)] += r.skeleton_tips[*it];
  }
  r.pruned.assign(n, 0);
  r.F.assign(n, Rigid{});
  r.stamp.assign(n, -1);
  r.group.assign(n, kStill);
  r.zeta.assign(n, 0.0);
  r.length_below.assign(n, 0.0);
  r.light_sum.assign(n, Eigen::Vector3d::Zero());
}

// Resources (eq. 4.11), remaining skeleton length and light directions below every skeleton node:
// the same loop as analyze_tree, so an unchanged scene reproduces the analysis bit for bit.
void Engine::aggregate(TreeRun& r) {
  if (r.aggregated_epoch == epoch_) return;
  r.aggregated_epoch = epoch_;
  const TreeGraph& t = *r.tree;
  const TreeAnalysis& a = *r.a;
  for (const NodeId m : r.skeleton) {
    r.zeta[m] = 0.0;
    r.length_below[m] = 0.0;
    r.light_sum[m].setZero();
  }
  for (std::uint32_t c = 0; c < a.clusters.size(); ++c) {
    const std::uint32_t g = r.first_cluster + c;
    if (!field_.alive(g)) continue;
    const double z = cluster_resources(a.clusters[c].radius_m, field_.light(g));
    r.zeta[a.clusters[c].anchor] += z;
    r.light_sum[a.clusters[c].anchor] += z * field_.direction(g);
  }
  for (auto it = r.skeleton.rbegin(); it != r.skeleton.rend(); ++it) {
    const NodeId i = *it;
    if (r.pruned[i]) continue;
    r.length_below[i] += t.length(i);
    if (i > 0) {
      const NodeId p = t.parent(i);
      r.zeta[p] += r.zeta[i];
      r.light_sum[p] += r.light_sum[i];
      r.length_below[p] += r.length_below[i];
    }
  }
}

// Pirk 4.4.1 and eq. 4.6: the segments of age `level` bend toward the light of their clusters; each
// rotation is carried into the segment's subtree, recording which rigid group each node moved
// with. The cost is the segments of this age plus the nodes that actually move.
void Engine::bend(TreeRun& r, int level, int step) {
  const TreeGraph& t = *r.tree;
  const TreeAnalysis& a = *r.a;
  const double wp = a.params.phototropism;
  const double wg = a.params.gravitropism;
  const double w_sum = wp + wg;
  if (w_sum <= 0.0) return;
  const Eigen::Vector3d g = a.params.gravity_direction.normalized();
  const std::uint64_t tree_tag = static_cast<std::uint64_t>(&r - runs_.data() + 1) << 32;
  bool any = false;
  // Only the segments of this age are looked at; a bent one carries its subtree (a contiguous
  // range of the skeleton pre-order) along. Ids put ancestors first, so a segment sees the
  // rotations of its bent ancestors of the same age before its own.
  const auto lo = r.age_begin[static_cast<std::size_t>(level)];
  const auto hi = r.age_begin[static_cast<std::size_t>(level) + 1];
  for (std::size_t k = lo; k < hi; ++k) {
    const NodeId m = r.by_age[k];
    const double bendable = bendability(r.skeleton_tips[m]);
    if (r.pruned[m] || bendable <= 0.0) continue;
    // Eq. 4.6 in the frame the segment has been carried into: the old heading (analysis
    // tropism) and the new one (light direction of its clusters now).
    const Eigen::Quaterniond& q_cur = r.F[m].q;
    const double ws = a.tropism_weight[m];
    const Eigen::Vector3d d_o = q_cur * a.original_direction[m];
    const Eigen::Vector3d v = segment_light_direction(r.light_sum[m], field_.open_direction());
    const Eigen::Vector3d t_new = (wp * v + wg * g) / w_sum;
    const Eigen::Vector3d h_old = ws * d_o + (1.0 - ws) * (q_cur * a.tropism[m]);
    const Eigen::Vector3d h_new = ws * d_o + (1.0 - ws) * t_new;
    if (h_old.norm() <= 1e-12 || h_new.norm() <= 1e-12) continue;
    const Eigen::Quaterniond q = Eigen::Quaterniond::Identity().slerp(
        bendable, Eigen::Quaterniond::FromTwoVectors(h_old, h_new));
    // Below 1e-4 rad (2 mm at 20 m) a turn is not worth moving the subtree and re-checking the
    // light of everything it carries.
    if (q.vec().norm() < 5e-5) continue;
    const Eigen::Vector3d pivot = r.F[m](t.start(m));
    const Rigid turn{q, pivot - q * pivot};  // x -> q (x - pivot) + pivot
    if (turn_blocked(r, m, turn)) continue;
    const std::uint64_t grp = tree_tag | (static_cast<std::uint64_t>(m) + 1);
    ++r.result.bent_segments;
    any = true;
    for (std::uint32_t j = r.pre_pos[m]; j < r.pre_pos[m] + r.pre_size[m]; ++j) {
      const NodeId n = r.pre[j];
      if (r.pruned[n]) continue;
      r.F[n] = compose(turn, r.F[n]);
      r.stamp[n] = step;
      r.group[n] = grp;
    }
  }
  if (!any) return;
  // Pirk 4.4.2: the clusters follow their anchors.
  for (std::uint32_t c = 0; c < a.clusters.size(); ++c) {
    const NodeId anchor = a.clusters[c].anchor;
    const std::uint32_t gc = r.first_cluster + c;
    if (r.stamp[anchor] != step || !field_.alive(gc)) continue;
    const Eigen::Vector3d moved_to = r.F[anchor](center0_[gc]);
    const double moved_m = (moved_to - field_.center(gc)).norm();
    path_[gc] += moved_m;
    step_max_ = std::max(step_max_, moved_m);
    field_.move(gc, moved_to);
    cgroup_[gc] = r.group[anchor];
    moved_.push_back(gc);
  }
  if (grid_ || canopy_) ++epoch_;  // the whole crown's light is read again after every move
  field_.mark_moved();
}

// A branch does not bend through a solid (a solid obstacle, or the ground when the scene has one:
// prune_blocked's rule): a turn that would carry the segment or any living segment of its subtree
// into one is not made, as a growing shoot that meets a solid does not enter it (growth_model.cpp).
// Only bendable segments turn, and they carry fewer than kSolidTerminalEdges skeleton tips, so the
// subtrees checked are small.
bool Engine::turn_blocked(const TreeRun& r, NodeId m, const Rigid& turn) const {
  if (!has_solids_) return false;
  const TreeGraph& t = *r.tree;
  for (std::uint32_t j = r.pre_pos[m]; j < r.pre_pos[m] + r.pre_size[m]; ++j) {
    const NodeId n = r.pre[j];
    if (r.pruned[n]) continue;
    const Rigid f = compose(turn, r.F[n]);
    // Only a segment the turn moves into a solid counts: one already in it (grown into the wall)
    // is pruned by prune_blocked whether it turns or not.
    if (scene_.segment_blocked(f(t.start(n)), f(t.end(n))) &&
        !scene_.segment_blocked(r.F[n](t.start(n)), r.F[n](t.end(n)))) {
      return true;
    }
  }
  return false;
}

// Pirk 4.4.1: after a level, every lateral branch up to that age whose resources per remaining
// length fall below its minimum pruning factor (eq. 4.12) is pruned with its subtree.
void Engine::prune(TreeRun& r, int level) {
  const TreeAnalysis& a = *r.a;
  aggregate(r);
  // With relative pruning the thresholds scale with the tree's resources per length.
  const double scale =
      a.params.relative_pruning && a.pruning_factor[0] > 0.0 && r.length_below[0] > 0.0
          ? r.zeta[0] / r.length_below[0] / a.pruning_factor[0]
          : 1.0;
  for (const NodeId s : r.skeleton) {
    if (s == 0 || !r.lateral[s] || r.pruned[s]) continue;
    if (a.age[s] > level || r.length_below[s] <= 0.0) continue;
    if (r.zeta[s] / r.length_below[s] >= scale * a.min_pruning_factor[s]) continue;
    prune_subtree(r, s);
  }
}

void Engine::prune_subtree(TreeRun& r, NodeId s) {
  for (std::uint32_t k = r.pre_pos[s]; k < r.pre_pos[s] + r.pre_size[s]; ++k) {
    const NodeId m = r.pre[k];
    if (r.pruned[m]) continue;
    r.pruned[m] = 1;
    ++epoch_;
    for (std::uint32_t j = r.cluster_start[m]; j < r.cluster_start[m + 1]; ++j) {
      const std::uint32_t gc = r.first_cluster + r.cluster_items[j];
      if (!field_.alive(gc)) continue;
      field_.remove(gc);
      vanished_.push_back(gc);
    }
  }
}

// A branch cannot pass through a solid obstacle: a skeleton segment that enters one where it
// stands now (at the first step: as grown; later: after it moved) is pruned with its subtree.
// Clusters that enter a solid are clipped or pushed out at the end (Pirk Fig. 4.6).
void Engine::prune_blocked(TreeRun& r, int step) {
  if (!has_solids_) return;
  const TreeGraph& t = *r.tree;
  for (const NodeId m : r.skeleton) {
    if (m == 0 || r.pruned[m] || (step > r.first_step && r.stamp[m] != step)) continue;
    if (scene_.segment_blocked(r.F[m](t.start(m)), r.F[m](t.end(m)))) prune_subtree(r, m);
  }
}

void Engine::mark_dirty(std::uint32_t c) {
  if (dirty_[c] || !field_.alive(c)) return;
  dirty_[c] = 1;
  dirty_list_.push_back(c);
}

// A neighbour j that drifted against c by more than the tolerance (and kDriftParallax of its
// distance) may have changed c's light by up to the share it can take (loss_bound); c is
// re-evaluated once these possible changes reach kLightChange.
void Engine::note_drift(std::uint32_t c, std::uint32_t j, const ClusterNeighbor& e) {
  const Eigen::Vector3d now = field_.center(j) - field_.center(c);
  const Eigen::Vector3d then = e.relative.cast<double>();
  // Cheap test first: j shades c neither now nor then (out of reach or below the horizon).
  const double r_j = field_.radius(j), reach2 = field_.reach2(j);
  if ((now.z() + r_j <= 0.0 || now.squaredNorm() > reach2) &&
      (then.z() + r_j <= 0.0 || then.squaredNorm() > reach2)) {
    return;
  }
  const double dist = then.norm();
  const double tol = std::max(kDriftTolerance_m, kDriftParallax * dist);
  const double drift2 = (now - then).squaredNorm();
  if (drift2 <= tol * tol) return;
  // A cap turned by the angle a changes the integral of I = cos^2 by at most its share times a
  // (|dI/dtheta| <= 1): the light can change by loss_bound * min(1, drift / distance).
  const double turn = dist > 0.0 ? std::min(1.0, std::sqrt(drift2) / dist) : 1.0;
  lost_[c] += turn * std::max(field_.loss_bound(j, now), field_.loss_bound(j, then));
  if (lost_[c] >= kLightChange) {
    mark_dirty(c);
  }
}

// A vanished cluster no longer shades the clusters in its shadow volume: they are re-evaluated
// once the light they may have gained since their evaluation reaches kLightChange.
void Engine::release_vanished_shade() {
  for (const std::uint32_t c : vanished_) {
    const ClusterLightField::ListView view = field_.neighbors(c);
    for (const ClusterNeighbor& e : view) {
      const std::uint32_t j = e.index + view.offset;
      if (!field_.alive(j) || dirty_[j]) continue;
      lost_[j] += field_.loss_bound(c, field_.center(j) - field_.center(c));
      if (lost_[j] >= kLightChange) mark_dirty(j);
    }
  }
  vanished_.clear();
}

// Which clusters' light the moves of this step changed: relative drift against a neighbour that
// moved with another group, a turn against the sky, or new obstacle visibility.
void Engine::check_moved() {
  const double cos_half_turn = std::cos(0.5 * kTurnTolerance_rad);
  // Relative drift since c's evaluation is at most its own path since then plus the largest
  // path any cluster can have made since then (the sum of the per-step maxima): below the
  // tolerance no pair needs a look (small changes, e.g. a box beside the crown, stay cheap).
  all_path_ += step_max_;
  step_max_ = 0.0;
  const auto may_drift = [&](std::uint32_t c) {
    return (path_[c] - eval_path_[c]) + (all_path_ - eval_all_path_[c]) > kDriftTolerance_m;
  };
  // The same bound over all clusters at once: when even the worst pair cannot have drifted by
  // the tolerance, no list needs a look.
  double own_max = 0.0, oldest = all_path_;
  for (const std::uint32_t c : moved_) own_max = std::max(own_max, path_[c] - eval_path_[c]);
  for (std::uint32_t c = 0; c < field_.size(); ++c) {
    if (field_.alive(c)) oldest = std::min(oldest, eval_all_path_[c]);
  }
  const bool any_drift = own_max + (all_path_ - oldest) > kDriftTolerance_m;
  for (const std::uint32_t c : moved_) {
    if (!field_.alive(c)) continue;
    if (std::abs(anchor_rotation(c).dot(eval_q_[c])) < cos_half_turn) mark_dirty(c);
    if (field_.obstacles_stale(c) && field_.update_obstacles(c)) mark_dirty(c);
    if (!any_drift) continue;
    const bool c_may = may_drift(c);
    const ClusterLightField::ListView view = field_.neighbors(c);
    for (const ClusterNeighbor& e : view) {
      const std::uint32_t j = e.index + view.offset;
      if (!field_.alive(j) || cgroup_[j] == cgroup_[c]) continue;
      if (cgroup_[j] == kStill && !check_[j] && may_drift(j)) {
        check_[j] = 1;
        check_list_.push_back(j);
      }
      if (c_may && !dirty_[c]) note_drift(c, j, e);
    }
  }
  for (const std::uint32_t c : check_list_) {
    check_[c] = 0;
    if (dirty_[c]) continue;
    const ClusterLightField::ListView view = field_.neighbors(c);
    for (const ClusterNeighbor& e : view) {
      const std::uint32_t j = e.index + view.offset;
      if (!field_.alive(j) || cgroup_[j] == kStill) continue;
      note_drift(c, j, e);
      if (dirty_[c]) break;
    }
  }
  check_list_.clear();
  for (const std::uint32_t c : moved_) cgroup_[c] = kStill;
  moved_.clear();
  release_vanished_shade();
}

void Engine::refresh() {
  if (dirty_list_.empty()) return;
  ++epoch_;
  std::sort(dirty_list_.begin(), dirty_list_.end());
  // Many due: one LightModel (shadow-volume grid, vectorized caps) for all of them; few: each
  // from its own neighbour list.
  if (dirty_list_.size() * kBatchShare >= field_.size()) {
    field_.evaluate_batch(dirty_list_, relist_);
    for (const std::uint32_t c : dirty_list_) mark_evaluated(c);
    dirty_list_.clear();
    return;
  }
  field_.rebuild_grid();
  for (const std::uint32_t c : dirty_list_) {
    dirty_[c] = 0;
    if (!field_.alive(c)) continue;
    field_.evaluate(c, relist_[c] != 0);
    mark_evaluated(c);
  }
  dirty_list_.clear();
}

// Cluster c's light was just evaluated: nothing is due, and the drift and turn bounds restart.
void Engine::mark_evaluated(std::uint32_t c) {
  dirty_[c] = 0;
  relist_[c] = 0;
  eval_q_[c] = anchor_rotation(c);
  lost_[c] = 0.0;
  eval_path_[c] = path_[c];
  eval_all_path_[c] = all_path_;
}

std::vector<AdaptationResult> Engine::run() {
  int steps = 0;
  for (const TreeRun& r : runs_) steps = std::max(steps, r.first_step + r.a->max_age + 1);
  for (int step = 0; step < steps; ++step) {
    step_ = step;
    // Bend every tree's current level (lock-step, Pirk 4.4.3), then update the light once.
    for (TreeRun& r : runs_) {
      const int level = step - r.first_step;
      if (level < 0 || level > r.a->max_age) continue;
      if (r.age_begin[static_cast<std::size_t>(level) + 1] ==
          r.age_begin[static_cast<std::size_t>(level)]) {
        continue;  // no segment of this age
      }
      aggregate(r);
      bend(r, level, step);
    }
    for (TreeRun& r : runs_) {
      if (step >= r.first_step) prune_blocked(r, step);
    }
    update_light();
    for (TreeRun& r : runs_) {
      const int level = step - r.first_step;
      if (level >= 0 && level <= r.a->max_age) prune(r, level);
    }
    // The clusters a pruning brightened are re-evaluated with the next step's moves (the next
    // bending still sees the light before this pruning: one level of lag, one evaluation less).
    if (step + 1 == steps) update_light();
  }
  std::vector<AdaptationResult> out;
  for (TreeRun& r : runs_) {
    finish(r);
    out.push_back(std::move(r.result));
  }
  return out;
}

// The leaves' attribute "light" after adaptation: the light the tree recorded (in the scene it
// grew in) times the change its cluster's light underwent, as eq. 4.13 reads it; pruned leaves
// and leaves of vanished clusters have none (nan). Cheap beside a new light evaluation, and 1x
// (unchanged) where nothing moved or shaded.
void scale_leaf_light(const TreeAnalysis& a, const std::vector<std::uint8_t>& alive,
                      const std::vector<double>& light_ratio,
                      const std::vector<std::uint8_t>& pruned, TreeGraph& t) {
  if (!t.has_attribute(kLightAttribute)) return;
  auto light = t.attribute(kLightAttribute);
  for (NodeId i = 0; i < t.size(); ++i) {
    if (t.kind(i) == OrganKind::kLeaf && pruned[i]) light[i] = std::nan("");
  }
  for (std::uint32_t c = 0; c < a.clusters.size(); ++c) {
    for (const NodeId m : a.clusters[c].nodes) {
      if (t.kind(m) != OrganKind::kLeaf) continue;
      // At most the open sky's light (1): the ratio is an estimate from the cluster field.
      light[m] = alive[c] ? std::min(light[m] * light_ratio[c], 1.0) : std::nan("");
    }
  }
}

void Engine::finish(TreeRun& r) {
  const TreeGraph& tree = *r.tree;
  const TreeAnalysis& a = *r.a;
  AdaptationResult& res = r.result;
  res.tree = tree;
  TreeGraph& t = res.tree;
  const std::size_t n = tree.size();
  // Final positions: skeleton nodes by their own transform, fine nodes by their cluster anchor's.
  std::vector<std::uint8_t> pruned(n, 0);
  for (NodeId i = 0; i < n; ++i) {
    const NodeId owner = a.skeleton[i] ? i : a.clusters[a.cluster_of[i]].anchor;
    pruned[i] = r.pruned[owner];
    const Rigid& f = r.F[owner];
    if (f.q.vec().squaredNorm() == 0.0 && f.t.squaredNorm() == 0.0) continue;
    const double len = t.length(i);
    t.set_segment(i, f(tree.start(i)), f(tree.end(i)));
    t.set_length(i, len);
    t.set_direction(i, f.q * tree.direction(i));
  }
  // Leaf clusters: moved with their anchor, eq. 4.14 translucency, eq. 4.13 density.
  std::vector<std::uint8_t> alive(a.clusters.size(), 0);
  std::vector<double> light_ratio(a.clusters.size(), 1.0);
  for (std::uint32_t c = 0; c < a.clusters.size(); ++c) {
    const std::uint32_t g = r.first_cluster + c;
    if (!field_.alive(g)) continue;
    alive[c] = 1;
    LeafCluster lc = a.clusters[c];
    lc.center = field_.center(g);
    std::size_t count = 0;
    for (const NodeId m : lc.nodes) count += pruned[m] == 0;
    lc.translucency = std::pow(a.clusters[c].translucency,
                               static_cast<double>(count) / static_cast<double>(lc.nodes.size()));
    // Pirk eq. 4.13 with rho(i) = i: the density scales with the light against the analysis.
    const double i0 = a.cluster_light[c];
    if (i0 > 1e-9) light_ratio[c] = field_.light(g) / i0;
    lc.density = i0 > 1e-9 ? std::clamp(light_ratio[c], 0.0, 2.0) : 1.0;
    res.clusters.push_back(std::move(lc));
  }
  scale_leaf_light(a, alive, light_ratio, pruned, t);
  // Clusters that ended up in a solid obstacle are pushed out (Pirk Fig. 4.6).
  res.pushed_clusters = push_clusters_out_of_solids(scene_, t, res.clusters);

  t.add_attribute("displacement", 0.0);
  t.add_attribute(kPrunedAttribute, 0.0);
  t.add_attribute("leaf_density", 1.0);
  auto disp = t.attribute("displacement");
  auto pr = t.attribute(kPrunedAttribute);
  auto dens = t.attribute("leaf_density");
  for (const LeafCluster& lc : res.clusters) {
    for (const NodeId m : lc.nodes) dens[m] = lc.density;
  }
  std::vector<std::uint8_t> internode_child(n, 0);
  for (NodeId i = 1; i < n; ++i) {
    if (is_internode(t, i)) internode_child[t.parent(i)] = 1;
  }
  std::size_t internodes = 0, pruned_internodes = 0;
  for (NodeId i = 0; i < n; ++i) {
    disp[i] = (t.end(i) - tree.end(i)).norm();
    pr[i] = pruned[i];
    res.pruned_nodes += pruned[i];
    if (is_internode(t, i)) {
      ++internodes;
      res.internode_centroid += tree.end(i);
      if (pruned[i]) ++pruned_internodes, res.pruned_centroid += tree.end(i);
    }
    if (pruned[i] || !is_internode(t, i) || internode_child[i]) continue;
    ++res.tips;
    res.mean_tip_displacement_m += disp[i];
    res.mean_tip_shift += t.end(i) - tree.end(i);
  }
  if (internodes > 0) res.internode_centroid /= static_cast<double>(internodes);
  if (pruned_internodes > 0) res.pruned_centroid /= static_cast<double>(pruned_internodes);
  if (res.tips > 0) {
    res.mean_tip_displacement_m /= static_cast<double>(res.tips);
    res.mean_tip_shift /= static_cast<double>(res.tips);
  }
  res.light_evaluations = field_.evaluations();
}

}  // namespace

AdaptationResult adapt_tree(const TreeGraph& tree, const TreeAnalysis& a, const Scene& scene) {
  if (a.skeleton.size() != tree.size()) {
    throw ValueError("plastic adaptation: the analysis was made for another tree");
  }
  if (tree.empty()) {
    AdaptationResult r;
    r.tree = tree;
    return r;
  }
  Engine engine({&tree}, {&a}, scene);
  return std::move(engine.run().front());
}

std::vector<AdaptationResult> adapt_trees(const std::vector<const TreeGraph*>& trees,
                                          const std::vector<const TreeAnalysis*>& analyses,
                                          const Scene& scene) {
  if (trees.size() != analyses.size()) {
    throw ValueError("plastic adaptation: one analysis per tree expected");
  }
  for (std::size_t k = 0; k < trees.size(); ++k) {
    if (trees[k] == nullptr || analyses[k] == nullptr || trees[k]->empty()) {
      throw ValueError("plastic adaptation: empty tree or missing analysis");
    }
  }
  if (trees.empty()) return {};
  Engine engine(trees, analyses, scene);
  return engine.run();
}

TreeGraph remove_pruned(const TreeGraph& adapted) {
  TreeGraph out = adapted;
  if (!out.has_attribute(kPrunedAttribute)) return out;
  // Remove the highest pruned subtree roots first so earlier ids stay valid.
  for (NodeId i = static_cast<NodeId>(out.size()); i-- > 0;) {
    const auto pr = out.attribute(kPrunedAttribute);
    if (i >= out.size() || pr[i] == 0.0) continue;
    const NodeId p = out.parent(i);
    if (p != kNoNode && pr[p] != 0.0) continue;
    out.remove_subtree(i);
  }
  return out;
}

}  // namespace fspm::environment
