#include "environment/plastic_adaptation.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <optional>

#include "environment/light_model.hpp"
#include "fspm/error.hpp"
#include "fspm/tree_traversal.hpp"

namespace fspm::environment {
namespace {

// Clusters that moved less than this since their light was computed keep it (Pirk 4.4: work
// only on the parts the change affects).
constexpr double kLightTolerance_m = 0.05;

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

}  // namespace

AdaptationResult adapt_tree(const TreeGraph& tree, const TreeAnalysis& a, const Scene& scene) {
  const std::size_t n = tree.size();
  if (a.skeleton.size() != n || a.age.size() != n || a.cluster_of.size() != n) {
    throw ValueError("plastic adaptation: the analysis was made for another tree");
  }
  AdaptationResult r;
  r.tree = tree;
  TreeGraph& t = r.tree;
  if (n == 0) return r;

  // Pre-order positions: the subtree of s is order[pos[s], pos[s] + size[s]).
  const std::vector<NodeId> order = preorder(tree);
  std::vector<std::uint32_t> pos(n), size(n, 1);
  for (std::uint32_t k = 0; k < order.size(); ++k) pos[order[k]] = k;
  for (NodeId i = static_cast<NodeId>(n); i-- > 1;) size[tree.parent(i)] += size[i];

  std::vector<std::vector<NodeId>> by_age(static_cast<std::size_t>(a.max_age) + 1);
  for (NodeId i = 0; i < n; ++i) {
    if (a.skeleton[i]) by_age[static_cast<std::size_t>(a.age[i])].push_back(i);
  }
  const std::vector<std::uint8_t> lateral = lateral_bases(tree);
  std::vector<std::uint8_t> pruned(n, 0);
  std::vector<Eigen::Quaterniond> acc(n, Eigen::Quaterniond::Identity());
  std::vector<LeafCluster> clusters = a.clusters;
  std::vector<std::uint8_t> alive(clusters.size(), 1);

  Scene world = scene;
  world.sky.directions = a.params.light_directions;
  world.sky.significance = a.params.light_significance;
  const std::size_t obstacle_spheres = world.spheres.size();
  const auto rebuild_light = [&] {
    world.spheres.resize(obstacle_spheres);
    for (std::size_t c = 0; c < clusters.size(); ++c) {
      if (alive[c]) {
        world.spheres.push_back(
            {clusters[c].center, clusters[c].radius_m, clusters[c].translucency, false});
      }
    }
    return LightModel(world);
  };
  const auto update_clusters = [&] {
    // Pirk 4.4.2: a cluster moves by the mean offset of its remaining nodes.
    for (std::size_t c = 0; c < clusters.size(); ++c) {
      if (!alive[c]) continue;
      Eigen::Vector3d offset = Eigen::Vector3d::Zero();
      std::size_t count = 0;
      for (const NodeId m : clusters[c].nodes) {
        if (pruned[m]) continue;
        offset += t.end(m) - tree.end(m);
        ++count;
      }
      if (count == 0) {
        alive[c] = 0;
        continue;
      }
      clusters[c].center = a.clusters[c].center + offset / static_cast<double>(count);
      // Pirk eq. 4.14: gamma' = gamma ^ (n_c / n_0).
      clusters[c].translucency =
          std::pow(a.clusters[c].translucency,
                   static_cast<double>(count) / static_cast<double>(clusters[c].nodes.size()));
    }
  };

  const double wp = a.params.phototropism;
  const double wg = a.params.gravitropism;
  const double w_sum = wp + wg;
  const Eigen::Vector3d g = a.params.gravity_direction.normalized();
  std::vector<double> zeta(n), length_below(n), cluster_zeta(clusters.size(), 0.0);
  // The light is rebuilt only after something moved or was pruned ("work only on the parts the
  // change affects", Pirk 4.4, at the granularity of whole levels).
  std::optional<LightModel> light;
  bool stale = true;
  bool all_stale = true;  // after pruning every cluster's shadows changed
  std::vector<Eigen::Vector3d> evaluated_at(clusters.size());
  const double tolerance2 = kLightTolerance_m * kLightTolerance_m;
  const auto refresh = [&] {
    if (!stale) return;
    light.emplace(rebuild_light());
    std::uint32_t sphere = static_cast<std::uint32_t>(obstacle_spheres);
    for (std::size_t c = 0; c < clusters.size(); ++c) {
      if (!alive[c]) {
        cluster_zeta[c] = 0.0;
        continue;
      }
      const std::uint32_t own = sphere++;
      // A cluster that barely moved since its light was last computed keeps it.
      if (!all_stale && (clusters[c].center - evaluated_at[c]).squaredNorm() < tolerance2) continue;
      evaluated_at[c] = clusters[c].center;
      const double i_c = light->evaluate(clusters[c].center, own).light;
      const double rc = clusters[c].radius_m;
      cluster_zeta[c] = 2.0 * M_PI * rc * rc * i_c;  // Pirk eq. 4.11
    }
    stale = false;
    all_stale = false;
  };
  for (std::size_t level = 0; level < by_age.size(); ++level) {
    bool moved = false;
    if (w_sum > 0.0 && !by_age[level].empty()) {
      refresh();
      for (const NodeId s : by_age[level]) {
        if (pruned[s]) continue;
        // Pirk eq. 4.6 in the frame the segment has been carried into by its ancestors: the old
        // heading (analysis tropism) and the new one (light direction here and now).
        const double ws = a.tropism_weight[s];
        const Eigen::Vector3d d_o = acc[s] * a.original_direction[s];
        const Eigen::Vector3d v = light->evaluate(t.start(s)).direction;
        const Eigen::Vector3d t_new = (wp * v + wg * g) / w_sum;
        const Eigen::Vector3d h_old = ws * d_o + (1.0 - ws) * (acc[s] * a.tropism[s]);
        const Eigen::Vector3d h_new = ws * d_o + (1.0 - ws) * t_new;
        if (h_old.norm() < 1e-12 || h_new.norm() < 1e-12) continue;
        const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(h_old, h_new);
        if (q.vec().norm() < 1e-9) continue;
        ++r.bent_segments;
        moved = true;
        const Eigen::Vector3d pivot = t.start(s);
        const Eigen::Matrix3d rot = q.toRotationMatrix();
        for (std::uint32_t k = pos[s]; k < pos[s] + size[s]; ++k) {
          const NodeId m = order[k];
          const double len = t.length(m);
          const Eigen::Vector3d dir = rot * t.direction(m);
          t.set_segment(m, pivot + rot * (t.start(m) - pivot), pivot + rot * (t.end(m) - pivot));
          t.set_length(m, len);
          t.set_direction(m, dir);
          acc[m] = q * acc[m];
        }
      }
    }
    if (moved) {
      update_clusters();
      stale = true;
    }

    // Pruning after the level (Pirk 4.4.1): resources of eq. 4.11 over the remaining length.
    refresh();
    std::fill(zeta.begin(), zeta.end(), 0.0);
    std::fill(length_below.begin(), length_below.end(), 0.0);
    for (std::size_t c = 0; c < clusters.size(); ++c) {
      if (alive[c]) zeta[clusters[c].anchor] += cluster_zeta[c];
    }
    for (NodeId i = static_cast<NodeId>(n); i-- > 0;) {
      if (!a.skeleton[i] || pruned[i]) continue;
      length_below[i] += t.length(i);
      if (i > 0) {
        zeta[t.parent(i)] += zeta[i];
        length_below[t.parent(i)] += length_below[i];
      }
    }
    bool any = false;
    for (NodeId s = 1; s < n; ++s) {
      if (!a.skeleton[s] || !lateral[s] || pruned[s]) continue;
      if (a.age[s] > static_cast<int>(level) || length_below[s] <= 0.0) continue;
      if (zeta[s] / length_below[s] >= a.min_pruning_factor[s]) continue;
      for (std::uint32_t k = pos[s]; k < pos[s] + size[s]; ++k) pruned[order[k]] = 1;
      any = true;
    }
    if (any) {
      update_clusters();
      stale = true;
      all_stale = true;
    }
  }

  t.add_attribute("displacement", 0.0);
  t.add_attribute("pruned", 0.0);
  auto disp = t.attribute("displacement");
  auto pr = t.attribute("pruned");
  std::vector<std::uint8_t> internode_child(n, 0);
  for (NodeId i = 1; i < n; ++i) {
    if (is_internode(t, i)) internode_child[t.parent(i)] = 1;
  }
  for (NodeId i = 0; i < n; ++i) {
    disp[i] = (t.end(i) - tree.end(i)).norm();
    pr[i] = pruned[i];
    r.pruned_nodes += pruned[i];
    if (pruned[i] || !is_internode(t, i) || internode_child[i]) continue;
    ++r.tips;
    r.mean_tip_displacement_m += disp[i];
    r.mean_tip_shift += t.end(i) - tree.end(i);
  }
  if (r.tips > 0) {
    r.mean_tip_displacement_m /= static_cast<double>(r.tips);
    r.mean_tip_shift /= static_cast<double>(r.tips);
  }
  for (std::size_t c = 0; c < clusters.size(); ++c) {
    if (alive[c]) r.clusters.push_back(clusters[c]);
  }
  return r;
}

std::vector<AdaptationResult> adapt_trees(const std::vector<const TreeGraph*>& trees,
                                          const std::vector<const TreeAnalysis*>& analyses,
                                          const Scene& scene) {
  if (trees.size() != analyses.size()) {
    throw ValueError("plastic adaptation: one analysis per tree expected");
  }
  std::vector<AdaptationResult> out;
  out.reserve(trees.size());
  for (std::size_t i = 0; i < trees.size(); ++i) {
    Scene shared = scene;
    for (std::size_t j = 0; j < trees.size(); ++j) {
      if (j == i) continue;
      for (const Sphere& s : cluster_spheres(analyses[j]->clusters)) shared.spheres.push_back(s);
    }
    out.push_back(adapt_tree(*trees[i], *analyses[i], shared));
  }
  return out;
}

TreeGraph remove_pruned(const TreeGraph& adapted) {
  TreeGraph out = adapted;
  if (!out.has_attribute("pruned")) return out;
  // Remove the highest pruned subtree roots first so earlier ids stay valid.
  for (NodeId i = static_cast<NodeId>(out.size()); i-- > 0;) {
    const auto pr = out.attribute("pruned");
    if (i >= out.size() || pr[i] == 0.0) continue;
    const NodeId p = out.parent(i);
    if (p != kNoNode && pr[p] != 0.0) continue;
    out.remove_subtree(i);
  }
  return out;
}

}  // namespace fspm::environment
