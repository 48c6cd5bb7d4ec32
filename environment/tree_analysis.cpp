#include "environment/tree_analysis.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "environment/light_model.hpp"
#include "environment/plastic_light.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {
namespace {

bool is_internode(const TreeGraph& t, NodeId n) { return t.kind(n) == OrganKind::kInternode; }

// Distances between nearest branching nodes (Pirk Fig. 4.2 a): path length from each branching
// node (or the root) down each child chain to the next branching node or tip.
std::vector<double> branching_distances(const TreeGraph& t) {
  std::vector<double> out;
  std::vector<std::size_t> internode_children(t.size(), 0);
  for (NodeId n = 1; n < t.size(); ++n) {
    if (is_internode(t, n)) ++internode_children[t.parent(n)];
  }
  // Accumulated length since the last branching node, in id order (parents first).
  std::vector<double> run(t.size(), 0.0);
  for (NodeId n = 0; n < t.size(); ++n) {
    if (!is_internode(t, n)) continue;
    const NodeId p = t.parent(n);
    const bool restart = p == kNoNode || internode_children[p] != 1;
    run[n] = (restart ? 0.0 : run[p]) + t.length(n);
    if (internode_children[n] != 1) out.push_back(run[n]);
  }
  return out;
}

}  // namespace

double mean_shift_mode(std::vector<double> samples, double bandwidth) {
  if (samples.empty()) return 0.0;
  std::sort(samples.begin(), samples.end());
  if (!(bandwidth > 0.0)) return samples[samples.size() / 2];
  std::vector<double> prefix(samples.size() + 1, 0.0);
  for (std::size_t i = 0; i < samples.size(); ++i) prefix[i + 1] = prefix[i] + samples[i];
  // Flat kernel: the window mean through prefix sums, so each step costs two binary searches.
  std::vector<double> modes;
  modes.reserve(samples.size());
  for (const double s : samples) {
    double m = s;
    for (int it = 0; it < 100; ++it) {
      const auto lo = std::lower_bound(samples.begin(), samples.end(), m - bandwidth);
      const auto hi = std::upper_bound(samples.begin(), samples.end(), m + bandwidth);
      const auto a = static_cast<std::size_t>(lo - samples.begin());
      const auto b = static_cast<std::size_t>(hi - samples.begin());
      const double next = (prefix[b] - prefix[a]) / static_cast<double>(b - a);
      if (std::abs(next - m) < 1e-9 * bandwidth) {
        m = next;
        break;
      }
      m = next;
    }
    modes.push_back(m);
  }
  std::sort(modes.begin(), modes.end());
  double best = modes.front();
  std::size_t best_count = 0;
  for (std::size_t i = 0; i < modes.size();) {
    std::size_t j = i;
    while (j < modes.size() && modes[j] - modes[i] <= 1e-3 * bandwidth) ++j;
    if (j - i > best_count) {
      best_count = j - i;
      best = modes[i + (j - i) / 2];
    }
    i = j;
  }
  return best;
}

Eigen::Vector3d inverse_tropism(const Eigen::Vector3d& h, const Eigen::Vector3d& t, double w_s) {
  if (w_s <= 1e-12) return h.normalized();
  const Eigen::Vector3d t_w = (1.0 - w_s) * t;
  // Pirk eq. 4.10: w_s^2 = p^2 |h|^2 - 2 p (h . t_w) + |t_w|^2, largest root; without a root the
  // zero of the derivative (the point of the line closest to the sphere's centre).
  const double a = h.squaredNorm();
  const double b = h.dot(t_w);
  const double disc = b * b - a * (t_w.squaredNorm() - w_s * w_s);
  const double p = disc >= 0.0 ? (b + std::sqrt(disc)) / a : b / a;
  const Eigen::Vector3d d = (p * h - t_w) / w_s;  // eq. 4.8
  const double norm = d.norm();
  return norm > 1e-12 ? Eigen::Vector3d(d / norm) : h.normalized();
}

std::vector<Sphere> cluster_spheres(const std::vector<LeafCluster>& clusters) {
  std::vector<Sphere> out;
  out.reserve(clusters.size());
  for (const LeafCluster& c : clusters) {
    out.push_back({c.center, c.radius_m, c.translucency, false});
  }
  return out;
}

void AnalysisParams::validate() const {
  // A model that lights leaf clusters, or a ValueError naming it.
  plastic_light_factory(light_model, "plastic analysis");
  if (light_model == ClusterLightModel::kCanopy) {
    bool known = false;
    for (const LeafLightModelEntry& e : leaf_light_models())
      known = known || canopy_model == e.name;
    if (!known) {
      throw ValueError("plastic analysis: unknown canopy_model '" + canopy_model.substr(0, 40) +
                       "' (expected one of " + leaf_light_model_names() + ")");
    }
  }
  if (!(min_cluster_radius_m > 0.0 && std::isfinite(min_cluster_radius_m))) {
    throw ValueError("plastic analysis: min_cluster_radius_m must be a finite number > 0");
  }
  if (!(gamma0 > 0.0 && gamma0 <= 1.0)) {
    throw ValueError("plastic analysis: gamma0 must be in (0, 1]");
  }
  if (light_directions < 1 || !(light_significance > 0.0 && std::isfinite(light_significance))) {
    throw ValueError("plastic analysis: light_directions must be >= 1, light_significance > 0");
  }
  if (!(pruning_strength >= 0.0 && std::isfinite(pruning_strength))) {
    throw ValueError("plastic analysis: pruning_strength (c_psi) must be a finite number >= 0");
  }
  if (!(phototropism >= 0.0 && gravitropism >= 0.0 && phototropism + gravitropism < 1.0)) {
    throw ValueError("plastic analysis: tropism weights must be >= 0 with a sum < 1 (eq. 4.7)");
  }
  if (!(reference_percentile >= 0.0 && reference_percentile <= 1.0)) {
    throw ValueError("plastic analysis: reference_percentile must be in [0, 1]");
  }
  if (!std::isfinite(skeleton_radius_m)) {
    throw ValueError("plastic analysis: skeleton_radius_m must be a number (<= 0: automatic)");
  }
}

void cluster_buds(const TreeGraph& t, const std::vector<LeafCluster>& clusters,
                  std::vector<Eigen::Vector3d>& buds, std::vector<std::uint32_t>& bud_start) {
  buds.clear();
  bud_start.assign(1, 0);
  for (const LeafCluster& c : clusters) {
    // The tips (leaves, or bare shoot ends) carry the buds and leaves that cast shade.
    for (const NodeId m : c.nodes) {
      if (t.children(m).empty()) buds.push_back(t.end(m));
    }
    bud_start.push_back(static_cast<std::uint32_t>(buds.size()));
  }
}

namespace {

// Skeleton threshold and skeleton: internodes at least 2.5 times as thick as the thinnest (or
// params.skeleton_radius_m), connected to the root.
void find_skeleton(const TreeGraph& t, const AnalysisParams& params, TreeAnalysis& a) {
  const std::size_t n = t.size();
  double thinnest = std::numeric_limits<double>::infinity();
  for (NodeId i = 0; i < n; ++i) {
    if (is_internode(t, i) && t.radius(i) > 0.0) thinnest = std::min(thinnest, t.radius(i));
  }
  a.skeleton_radius_m = params.skeleton_radius_m > 0.0 ? params.skeleton_radius_m
                        : std::isfinite(thinnest)      ? 2.5 * thinnest
                                                       : 0.0;
  a.skeleton.assign(n, 0);
  for (NodeId i = 0; i < n; ++i) {
    const NodeId p = t.parent(i);
    // A skeleton is connected: a thick internode under a fine one stays fine.
    a.skeleton[i] =
        i == 0 || (is_internode(t, i) && t.radius(i) >= a.skeleton_radius_m && a.skeleton[p] != 0);
  }
}

// Fine subtrees hanging from the skeleton become leaf clusters: centre, bounding radius and
// translucency (eq. 4.4).
void form_leaf_clusters(const TreeGraph& t, const AnalysisParams& params, TreeAnalysis& a) {
  const std::size_t n = t.size();
  a.cluster_of.assign(n, kNoCluster);
  for (NodeId i = 1; i < n; ++i) {
    if (a.skeleton[i]) continue;
    const NodeId p = t.parent(i);
    if (a.skeleton[p]) {
      a.cluster_of[i] = static_cast<std::uint32_t>(a.clusters.size());
      a.clusters.push_back({});
      a.clusters.back().anchor = p;
    } else {
      a.cluster_of[i] = a.cluster_of[p];
    }
    a.clusters[a.cluster_of[i]].nodes.push_back(i);
  }
  for (LeafCluster& c : a.clusters) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const NodeId m : c.nodes) sum += t.end(m);
    c.center = sum / static_cast<double>(c.nodes.size());
    double r = params.min_cluster_radius_m;
    for (const NodeId m : c.nodes) {
      // A leaf node of the growth model is itself a sphere around its end.
      const double own = t.kind(m) == OrganKind::kLeaf ? t.radius(m) : 0.0;
      r = std::max(r, (t.end(m) - c.center).norm() + own);
    }
    c.radius_m = r;
    c.translucency = cluster_translucency(r, params.gamma0);  // eq. 4.4
  }
}

// Internode length l_i: mean-shift mode of the nearest-branching distances (Fig. 4.2 a).
void estimate_internode_length(const TreeGraph& t, TreeAnalysis& a) {
  std::vector<double> d = branching_distances(t);
  std::vector<double> sorted = d;
  std::sort(sorted.begin(), sorted.end());
  const double median = sorted.empty() ? 0.0 : sorted[sorted.size() / 2];
  a.internode_length_m = mean_shift_mode(std::move(d), 0.25 * median);
  if (!(a.internode_length_m > 0.0)) a.internode_length_m = std::max(t.length(0), 1e-3);
}

// Growth rates (Pirk eq. 4.1) from the path distances d_{s,r} (root to segment start) and
// d_{s,l} (segment start to the furthest tip below), and the season each segment started in
// (eq. 4.2).
void estimate_ages(const TreeGraph& t, TreeAnalysis& a) {
  const std::size_t n = t.size();
  std::vector<double> to_root(n, 0.0), to_leaf(n, 0.0);
  for (NodeId i = 1; i < n; ++i) {
    to_root[i] =
        to_root[t.parent(i)] + (is_internode(t, t.parent(i)) ? t.length(t.parent(i)) : 0.0);
  }
  for (NodeId i = static_cast<NodeId>(n); i-- > 0;) {
    const double own = is_internode(t, i) ? t.length(i) : 0.0;
    to_leaf[i] += own;
    if (i > 0) to_leaf[t.parent(i)] = std::max(to_leaf[t.parent(i)], to_leaf[i]);
  }
  a.height_path_m = to_leaf[0];
  const double d_r = a.height_path_m;
  // Pirk eq. 4.1 with the d_t = 0.2 d_r rule (closer to the leaves: copy from the parent).
  std::vector<double> rel(n, 1.0);
  double rel_min = std::numeric_limits<double>::infinity();
  for (NodeId i = 0; i < n; ++i) {
    const double denom = d_r - to_root[i];
    if (to_leaf[i] > 0.2 * d_r && denom > 0.0) {
      rel[i] = std::min(1.0, to_leaf[i] / denom);
    } else {
      rel[i] = i == 0 ? 1.0 : rel[t.parent(i)];
    }
    rel_min = std::min(rel_min, rel[i]);
  }
  a.growth_rate.resize(n);
  for (NodeId i = 0; i < n; ++i) a.growth_rate[i] = rel[i] / rel_min;
  // Pirk eq. 4.2. We read nu_s as internodes per season, so the segment adds l_s / (l_i nu_s)
  // seasons (the printed product would make the fastest branches the oldest).
  std::vector<double> age_f(n, 0.0);
  a.age.assign(n, 0);
  for (NodeId i = 0; i < n; ++i) {
    const double before = i == 0 ? 0.0 : age_f[t.parent(i)];
    const double own = is_internode(t, i) ? t.length(i) : 0.0;
    age_f[i] = before + own / (a.internode_length_m * a.growth_rate[i]);
    // The season in which the segment started (its start is at the parent's age).
    a.age[i] = static_cast<int>(std::floor(before + 1e-9));
    a.max_age = std::max(a.max_age, a.age[i]);
  }
}

// Pruning factors of the final stage: zeta (eq. 4.11) over the clusters below, over the skeleton
// length below; `light_sum` gets every segment's light direction from the same sums (the
// adaptation repeats this loop exactly). Every factor is also appended to `all`.
void final_pruning_factors(const TreeGraph& t, TreeAnalysis& a,
                           std::vector<Eigen::Vector3d>& light_sum, std::vector<double>& all) {
  const std::size_t n = t.size();
  std::vector<double> zeta(n, 0.0), length_below(n, 0.0);
  light_sum.assign(n, Eigen::Vector3d::Zero());
  for (std::uint32_t c = 0; c < a.clusters.size(); ++c) {
    const double z = cluster_resources(a.clusters[c].radius_m, a.cluster_light[c]);
    zeta[a.clusters[c].anchor] += z;
    light_sum[a.clusters[c].anchor] += z * a.cluster_direction[c];
  }
  for (NodeId i = static_cast<NodeId>(n); i-- > 0;) {
    if (!a.skeleton[i]) continue;
    length_below[i] += t.length(i);
    if (i > 0) {
      zeta[t.parent(i)] += zeta[i];
      light_sum[t.parent(i)] += light_sum[i];
      length_below[t.parent(i)] += length_below[i];
    }
  }
  a.pruning_factor.assign(n, 0.0);
  for (NodeId i = 0; i < n; ++i) {
    if (!a.skeleton[i] || length_below[i] <= 0.0) continue;
    a.pruning_factor[i] = zeta[i] / length_below[i];
    all.push_back(a.pruning_factor[i]);
  }
}

// A leaf cluster of an earlier growth stage (Pirk 4.3.2, Fig. 4.3).
struct StageCluster {
  NodeId node;
  Eigen::Vector3d center;
  double radius_m;
  bool moved = false;
};

// Stage T: the segments younger than T are gone and their clusters move to the nearest remaining
// ancestor; clusters meeting on one node merge with the radius of eq. 4.5.
std::vector<StageCluster> earlier_stage(const TreeGraph& t, const TreeAnalysis& a, int T,
                                        std::vector<StageCluster> stage) {
  const Eigen::Vector3d root = t.start(0);
  for (StageCluster& c : stage) {
    c.moved = false;
    while (c.node != 0 && a.age[c.node] > T) {
      c.node = t.parent(c.node);
      c.moved = true;
    }
  }
  std::stable_sort(stage.begin(), stage.end(),
                   [](const StageCluster& x, const StageCluster& y) { return x.node < y.node; });
  std::vector<StageCluster> merged;
  for (std::size_t i = 0; i < stage.size();) {
    std::size_t j = i;
    while (j < stage.size() && stage[j].node == stage[i].node) ++j;
    if (j - i == 1 && !stage[i].moved) {
      merged.push_back(stage[i]);
    } else {
      // Pirk eq. 4.5, read with the distance ratio per child inside the sum:
      // r_n^3 = sum r_i^3 d_n / d_i (the printed product over all children shrinks a merged
      // cluster below any of its parts once a few merge); centre at the node.
      const Eigen::Vector3d centre = t.end(stage[i].node);
      const double d_n = (centre - root).norm();
      double volume = 0.0;
      for (std::size_t k = i; k < j; ++k) {
        const double d_i = (stage[k].center - root).norm();
        const double ratio = d_i > 1e-9 ? std::min(1.0, d_n / d_i) : 1.0;
        volume += std::pow(stage[k].radius_m, 3) * ratio;
      }
      merged.push_back({stage[i].node, centre, std::max(1e-3, std::cbrt(volume)), false});
    }
    i = j;
  }
  return merged;
}

// Every earlier stage's light gives psi_s(T) for the segments alive then: `stage_min` keeps each
// segment's smallest, `all` gets every one.
void stage_pruning_factors(const TreeGraph& t, const AnalysisParams& params, const Scene& scene,
                           const TreeAnalysis& a, std::vector<double>& stage_min,
                           std::vector<double>& all) {
  const std::size_t n = t.size();
  std::vector<double> zeta(n, 0.0), length_below(n, 0.0);
  std::vector<StageCluster> stage;
  for (const LeafCluster& c : a.clusters) stage.push_back({c.anchor, c.center, c.radius_m, false});
  for (int T = params.temporal_pruning ? a.max_age - 1 : -1; T >= 0; --T) {
    stage = earlier_stage(t, a, T, std::move(stage));
    Scene past = scene;
    past.spheres.clear();
    for (const StageCluster& c : stage) {
      past.spheres.push_back(
          {c.center, c.radius_m, cluster_translucency(c.radius_m, params.gamma0), false});
    }
    const LightModel past_light(past);
    std::fill(zeta.begin(), zeta.end(), 0.0);
    std::fill(length_below.begin(), length_below.end(), 0.0);
    for (std::uint32_t c = 0; c < stage.size(); ++c) {
      const double r = stage[c].radius_m;
      zeta[stage[c].node] += cluster_resources(r, past_light.evaluate(stage[c].center, c).light);
    }
    for (NodeId i = static_cast<NodeId>(n); i-- > 0;) {
      if (!a.skeleton[i] || a.age[i] > T) continue;
      length_below[i] += t.length(i);
      if (i > 0) {
        zeta[t.parent(i)] += zeta[i];
        length_below[t.parent(i)] += length_below[i];
      }
    }
    for (NodeId i = 0; i < n; ++i) {
      if (!a.skeleton[i] || a.age[i] > T || length_below[i] <= 0.0) continue;
      const double psi = zeta[i] / length_below[i];
      all.push_back(psi);
      stage_min[i] = std::min(stage_min[i], psi);
    }
  }
}

// Pirk eq. 4.12 over every stage: the reference factor (a percentile of all) and each skeleton
// segment's minimum.
void minimum_pruning_factors(const AnalysisParams& params, const std::vector<double>& stage_min,
                             std::vector<double> all, TreeAnalysis& a) {
  if (!all.empty()) {
    std::sort(all.begin(), all.end());
    const auto k =
        static_cast<std::size_t>(params.reference_percentile * static_cast<double>(all.size() - 1));
    a.reference_pruning_factor = all[k];
  }
  a.min_pruning_factor.assign(stage_min.size(), 0.0);
  for (std::size_t i = 0; i < stage_min.size(); ++i) {
    if (!a.skeleton[i]) continue;
    a.min_pruning_factor[i] =
        params.pruning_strength * std::min(a.reference_pruning_factor, stage_min[i]);
  }
}

// Inverse tropism per skeleton segment (eq. 4.7-4.10) with the light direction of its clusters.
void inverse_tropisms(const TreeGraph& t, const AnalysisParams& params,
                      const std::vector<Eigen::Vector3d>& light_sum,
                      const Eigen::Vector3d& open_direction, TreeAnalysis& a) {
  const std::size_t n = t.size();
  const double w_sum = params.phototropism + params.gravitropism;
  const Eigen::Vector3d g = params.gravity_direction.normalized();
  a.tropism_weight.assign(n, 1.0);
  a.tropism.assign(n, Eigen::Vector3d::Zero());
  a.original_direction.assign(n, Eigen::Vector3d::UnitZ());
  for (NodeId i = 0; i < n; ++i) {
    const Eigen::Vector3d h =
        t.direction(i).norm() > 0.0 ? Eigen::Vector3d(t.direction(i)) : Eigen::Vector3d::UnitZ();
    a.original_direction[i] = h.normalized();
    if (!a.skeleton[i] || w_sum <= 0.0) continue;
    const Eigen::Vector3d v = segment_light_direction(light_sum[i], open_direction);
    a.tropism[i] = (params.phototropism * v + params.gravitropism * g) / w_sum;
    a.tropism_weight[i] = std::pow(1.0 - w_sum, t.length(i) / a.internode_length_m);
    a.original_direction[i] = inverse_tropism(h, a.tropism[i], a.tropism_weight[i]);
  }
}

}  // namespace

// Pirk 4.3: skeleton and clusters, ages, the final stage's light, pruning factors over every
// growth stage, and the tropisms that grew the tree.
TreeAnalysis analyze_tree(const TreeGraph& t, const AnalysisParams& params,
                          const Eigen::Vector3d& brightest) {
  if (t.empty()) throw ValueError("plastic analysis: the tree is empty");
  params.validate();
  TreeAnalysis a;
  a.params = params;
  find_skeleton(t, params, a);
  form_leaf_clusters(t, params, a);
  estimate_internode_length(t, a);
  estimate_ages(t, a);

  // Light of the final stage: the tree's clusters alone under an open sky, one evaluation per
  // cluster (the adaptation starts from this cache).
  Scene scene;
  scene.sky.brightest = brightest.normalized();
  scene.sky.directions = params.light_directions;
  scene.sky.significance = params.light_significance;
  scene.sky.validate();
  a.brightest = scene.sky.brightest;
  ClusterLightField field(params.light_directions, params.light_significance, a.brightest);
  make_plastic_light(params, "plastic analysis")->analyse(t, scene, field, a);

  std::vector<Eigen::Vector3d> light_sum;
  std::vector<double> all;
  final_pruning_factors(t, a, light_sum, all);
  std::vector<double> stage_min = a.pruning_factor;
  stage_pruning_factors(t, params, scene, a, stage_min, all);
  minimum_pruning_factors(params, stage_min, std::move(all), a);
  inverse_tropisms(t, params, light_sum, field.open_direction(), a);
  return a;
}

}  // namespace fspm::environment
