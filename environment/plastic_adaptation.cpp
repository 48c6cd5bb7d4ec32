#include "environment/plastic_adaptation.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

#include "environment/adaptation_state.hpp"
#include "environment/plastic_light.hpp"
#include "environment/solid_push.hpp"
#include "fspm/attribute_names.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {
namespace {

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

class Engine {
 public:
  Engine(const std::vector<const TreeGraph*>& trees,
         const std::vector<const TreeAnalysis*>& analyses, const Scene& scene);
  std::vector<AdaptationResult> run();

 private:
  void collect_clusters(const std::vector<const TreeGraph*>& trees,
                        const std::vector<const TreeAnalysis*>& analyses);
  void setup_tree(TreeRun& r);
  void aggregate(TreeRun& r);
  void bend(TreeRun& r, int level, int step);
  bool turn_blocked(const TreeRun& r, NodeId m, const Rigid& turn) const;
  void prune(TreeRun& r, int level);
  void prune_subtree(TreeRun& r, NodeId s);
  void prune_blocked(TreeRun& r, int step);
  // The light model's update; what it was told of is then done with.
  void update_light() {
    light_->update(s_);
    for (const std::uint32_t c : s_.moved) s_.group[c] = kStill;
    s_.moved.clear();
    s_.vanished.clear();
  }
  void finish(TreeRun& r);

  // The trees, their clusters' light field and what changed (adaptation_state.hpp).
  AdaptationState s_;
  // The clusters' light (AnalysisParams::light_model), kept up to date after every step.
  std::unique_ptr<PlasticLight> light_;
  bool has_solids_ = false;  // the scene has a solid box, sphere or mesh
};

Engine::Engine(const std::vector<const TreeGraph*>& trees,
               const std::vector<const TreeAnalysis*>& analyses, const Scene& scene)
    : s_(scene, analyses.empty() ? 64 : analyses.front()->params.light_directions,
         analyses.empty() ? 0.01 : analyses.front()->params.light_significance) {
  if (scene.sky.distribution) s_.field.set_sky_distribution(scene.sky.distribution);  // a real sky
  if (trees.size() != analyses.size()) {
    throw ValueError("plastic adaptation: one analysis per tree expected");
  }
  collect_clusters(trees, analyses);
  s_.field.set_obstacles(scene);
  for (const Box& b : scene.boxes) has_solids_ = has_solids_ || b.solid;
  for (const Sphere& b : scene.spheres) has_solids_ = has_solids_ || b.solid;
  for (const TriangleMesh& m : scene.meshes) has_solids_ = has_solids_ || m.solid;
  const AnalysisParams& params = s_.runs.front().a->params;
  for (const TreeRun& r : s_.runs) {
    if (r.a->params.light_model != params.light_model) {
      throw ValueError("plastic adaptation: the trees were analysed with different light models");
    }
  }
  light_ = make_plastic_light(params, "plastic adaptation");
  for (TreeRun& r : s_.runs) setup_tree(r);
  light_->start(s_);
}

// Every tree's clusters into one numbering (s_.runs[k].first_cluster on), the cluster state sized
// to them.
void Engine::collect_clusters(const std::vector<const TreeGraph*>& trees,
                              const std::vector<const TreeAnalysis*>& analyses) {
  s_.runs.resize(trees.size());
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
    s_.runs[k].tree = &t;
    s_.runs[k].a = &a;
    s_.runs[k].first_cluster = static_cast<std::uint32_t>(centers.size());
    for (const LeafCluster& c : a.clusters) {
      centers.push_back(c.center);
      radii.push_back(c.radius_m);
      gammas.push_back(c.translucency);
      s_.owner.push_back(static_cast<std::uint32_t>(k));
    }
    max_levels = std::max(max_levels, a.max_age + 1);
  }
  // Pirk 4.4.3: the younger trees start later so that all finish together.
  for (TreeRun& r : s_.runs) r.first_step = max_levels - (r.a->max_age + 1);

  s_.field.set_clusters(centers, radii, gammas);
  s_.center0 = centers;
  const std::size_t nc = centers.size();
  s_.group.assign(nc, kStill);
  s_.path.assign(nc, 0.0);
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
  if (r.aggregated_epoch == s_.epoch) return;
  r.aggregated_epoch = s_.epoch;
  const TreeGraph& t = *r.tree;
  const TreeAnalysis& a = *r.a;
  for (const NodeId m : r.skeleton) {
    r.zeta[m] = 0.0;
    r.length_below[m] = 0.0;
    r.light_sum[m].setZero();
  }
  for (std::uint32_t c = 0; c < a.clusters.size(); ++c) {
    const std::uint32_t g = r.first_cluster + c;
    if (!s_.field.alive(g)) continue;
    const double z = cluster_resources(a.clusters[c].radius_m, s_.field.light(g));
    r.zeta[a.clusters[c].anchor] += z;
    r.light_sum[a.clusters[c].anchor] += z * s_.field.direction(g);
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
  const std::uint64_t tree_tag = static_cast<std::uint64_t>(&r - s_.runs.data() + 1) << 32;
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
    const Eigen::Vector3d v = segment_light_direction(r.light_sum[m], s_.field.open_direction());
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
    if (r.stamp[anchor] != step || !s_.field.alive(gc)) continue;
    const Eigen::Vector3d moved_to = r.F[anchor](s_.center0[gc]);
    const double moved_m = (moved_to - s_.field.center(gc)).norm();
    s_.path[gc] += moved_m;
    s_.step_max = std::max(s_.step_max, moved_m);
    s_.field.move(gc, moved_to);
    s_.group[gc] = r.group[anchor];
    s_.moved.push_back(gc);
  }
  if (light_->relights_crown()) ++s_.epoch;  // the whole crown's light is due after a move
  s_.field.mark_moved();
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
    if (s_.scene.segment_blocked(f(t.start(n)), f(t.end(n))) &&
        !s_.scene.segment_blocked(r.F[n](t.start(n)), r.F[n](t.end(n)))) {
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
    ++s_.epoch;
    for (std::uint32_t j = r.cluster_start[m]; j < r.cluster_start[m + 1]; ++j) {
      const std::uint32_t gc = r.first_cluster + r.cluster_items[j];
      if (!s_.field.alive(gc)) continue;
      s_.field.remove(gc);
      s_.vanished.push_back(gc);
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
    if (s_.scene.segment_blocked(r.F[m](t.start(m)), r.F[m](t.end(m)))) prune_subtree(r, m);
  }
}

std::vector<AdaptationResult> Engine::run() {
  int steps = 0;
  for (const TreeRun& r : s_.runs) steps = std::max(steps, r.first_step + r.a->max_age + 1);
  for (int step = 0; step < steps; ++step) {
    s_.step = step;
    // Bend every tree's current level (lock-step, Pirk 4.4.3), then update the light once.
    for (TreeRun& r : s_.runs) {
      const int level = step - r.first_step;
      if (level < 0 || level > r.a->max_age) continue;
      if (r.age_begin[static_cast<std::size_t>(level) + 1] ==
          r.age_begin[static_cast<std::size_t>(level)]) {
        continue;  // no segment of this age
      }
      aggregate(r);
      bend(r, level, step);
    }
    for (TreeRun& r : s_.runs) {
      if (step >= r.first_step) prune_blocked(r, step);
    }
    update_light();
    for (TreeRun& r : s_.runs) {
      const int level = step - r.first_step;
      if (level >= 0 && level <= r.a->max_age) prune(r, level);
    }
    // The clusters a pruning brightened are re-evaluated with the next step's moves (the next
    // bending still sees the light before this pruning: one level of lag, one evaluation less).
    if (step + 1 == steps) update_light();
  }
  std::vector<AdaptationResult> out;
  for (TreeRun& r : s_.runs) {
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
    if (!s_.field.alive(g)) continue;
    alive[c] = 1;
    LeafCluster lc = a.clusters[c];
    lc.center = s_.field.center(g);
    std::size_t count = 0;
    for (const NodeId m : lc.nodes) count += pruned[m] == 0;
    lc.translucency = std::pow(a.clusters[c].translucency,
                               static_cast<double>(count) / static_cast<double>(lc.nodes.size()));
    // Pirk eq. 4.13 with rho(i) = i: the density scales with the light against the analysis.
    const double i0 = a.cluster_light[c];
    if (i0 > 1e-9) light_ratio[c] = s_.field.light(g) / i0;
    lc.density = i0 > 1e-9 ? std::clamp(light_ratio[c], 0.0, 2.0) : 1.0;
    res.clusters.push_back(std::move(lc));
  }
  scale_leaf_light(a, alive, light_ratio, pruned, t);
  // Clusters that ended up in a solid obstacle are pushed out (Pirk Fig. 4.6).
  res.pushed_clusters = push_clusters_out_of_solids(s_.scene, t, res.clusters);

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
  res.light_evaluations = s_.field.evaluations();
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
