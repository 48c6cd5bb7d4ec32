#include "stages/developmental_model.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>

#include "fspm/closest_name.hpp"
#include "fspm/error.hpp"

namespace fspm::stages {
namespace {

constexpr std::uint32_t kNoChain = ~std::uint32_t{0};

bool is_edge(const TreeGraph& t, NodeId n) { return t.kind(n) == OrganKind::kInternode; }

Eigen::Vector3d heading(const TreeGraph& t, NodeId n) {
  const Eigen::Vector3d d = t.direction(n);
  if (d.squaredNorm() > 0.0) return d.normalized();
  const Eigen::Vector3d s = t.end(n) - t.start(n);
  return s.squaredNorm() > 0.0 ? Eigen::Vector3d(s.normalized()) : Eigen::Vector3d::UnitZ();
}

double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// Within `tolerance` of each other, relative to the larger.
bool close(double a, double b, double tolerance) {
  const double scale = std::max(std::abs(a), std::abs(b));
  return scale == 0.0 || std::abs(a - b) <= tolerance * scale;
}

// r_u^(1/u) of eq. 5.8; inv_u = 0 stands for Murray's u = 2.5, the default, where the root
// solves y^5 = r_u^2: one Newton step from a single-precision seed (relative error ~1e-7, after
// the step ~1e-14) costs a fraction of std::pow.
double pipe_root(double r_u, double inv_u) {
  if (inv_u != 0.0) return std::pow(r_u, inv_u);
  if (!(r_u >= 1e-30 && r_u <= 1e30)) return std::pow(r_u, 0.4);  // beyond float's normal range
  const double y = std::pow(static_cast<float>(r_u), 0.4f);
  const double y2 = y * y, y4 = y2 * y2;
  return y - (y4 * y - r_u * r_u) / (5.0 * y4);
}

}  // namespace

std::string_view continuation_name(Continuation continuation) {
  return kContinuationNames.name(continuation);
}

Continuation continuation_from_name(std::string_view name) {
  return kContinuationNames.from_name(name, "stages");
}

void StagesParams::validate() const {
  if (rigid_tip_count < 1 || rigid_tip_count > 1'000'000) {
    throw ValueError("stages: rigid_tip_count must be in [1, 1000000]");
  }
  if (!(pipe_exponent >= 1.0 && pipe_exponent <= 4.0)) {
    throw ValueError("stages: pipe_exponent must be in [1, 4]");
  }
  if (!(same_level_tolerance >= 0.0 && same_level_tolerance <= 1.0)) {
    throw ValueError("stages: same_level_tolerance must be in [0, 1]");
  }
  added.validate();
  shed.validate();
  for (const AgeEdit& a : edits.age) {
    if (!(std::abs(a.delta_t) <= 1.0)) {
      throw ValueError("stages: a branch's age change must be in [-1, 1] (units of t), got " +
                       std::to_string(a.delta_t));
    }
  }
}

double seasonal_time(double t, int years, double c, double s) {
  if (years < 1 || !(c > 0.0) || !std::isfinite(t) || !std::isfinite(s)) {
    throw ValueError("seasonal time: expected years >= 1, c > 0 and finite t and s");
  }
  // Pirk eq. 5.11.
  const double n = years;
  return std::sin((t * n - s) * 2.0 * std::numbers::pi) / (2.0 * std::numbers::pi * n * c) + t;
}

DevelopmentalModel::DevelopmentalModel(const TreeGraph& tree, const StagesParams& params)
    : tree_(tree), params_(params), given_size_(static_cast<NodeId>(tree.size())) {
  params_.validate();
  if (tree_.empty() || !is_edge(tree_, 0)) {
    throw ValueError("developmental stages: the tree needs an internode at its root");
  }
  if (params_.added.enabled) add_missing_structures();
  assign_levels_and_chains();
  if (!params_.added.enabled) added_.crown = crown_shape(tree_, chain_);
  compute_growth_times();
  compute_bending();
  compute_radius_coefficients();
  apply_edits();
  reconstruct_shed_branches();
  build_plans();
  build_tip_organs();
}

// Pirk 5.3.5: the given tree's main chain decides where the copies go; the model then analyses
// the given tree with the copies as one branching graph.
void DevelopmentalModel::add_missing_structures() {
  StagesParams plain = params_;
  plain.added.enabled = false;
  const DevelopmentalModel given(tree_, plain);
  added_ = add_structures(tree_, given.chain(), params_.added);
  tree_ = std::move(added_.tree);
  added_.tree = TreeGraph{};
  added_end_ = static_cast<NodeId>(tree_.size());
}

std::size_t DevelopmentalModel::lateral_chain_count() const {
  return chain_rate_.empty() ? 0 : chain_rate_.size() - 1;
}

// The child that continues p's axis: Pirk's least deviation from p, or the thickest child (the
// least deviating among those within the tolerance of the thickest).
NodeId DevelopmentalModel::continuation(NodeId p, const std::vector<NodeId>& edges) const {
  const Eigen::Vector3d hp = heading(tree_, p);
  double thickest = 0.0;
  for (const NodeId c : edges) thickest = std::max(thickest, tree_.radius(c));
  NodeId best = kNoNode;
  double least = std::numeric_limits<double>::infinity();
  for (const NodeId c : edges) {
    if (params_.continuation == Continuation::kThickest &&
        tree_.radius(c) < (1.0 - params_.same_level_tolerance) * thickest) {
      continue;
    }
    const double a = angle_between(hp, heading(tree_, c));
    if (a < least) least = a, best = c;
  }
  return best;
}

// Pirk 5.2.2: Gravelius levels and chains. Node ids put parents first, so one pass in id order
// sees every parent before its children.
void DevelopmentalModel::assign_levels_and_chains() {
  const std::size_t n = tree_.size();
  level_.assign(n, 1);
  chain_.assign(n, kNoChain);
  offset_.assign(n, 0.0);
  chain_base_.assign(n, 0);
  chain_.front() = 0;
  chain_rate_.assign(1, 0.0);  // lengths for now; rates in compute_growth_times()
  std::vector<NodeId> edges;
  for (NodeId p = 0; p < n; ++p) {
    if (!is_edge(tree_, p)) {
      for (const NodeId c : tree_.children(p)) {
        if (is_edge(tree_, c)) {
          throw ValueError("developmental stages: internode " + std::to_string(c) +
                           " grows from an organ (a leaf, flower or bud), not from an internode");
        }
        level_[c] = level_[p];
      }
      continue;
    }
    chain_rate_[chain_[p]] += tree_.length(p);
    edges.clear();
    for (const NodeId c : tree_.children(p)) {
      if (is_edge(tree_, c)) {
        edges.push_back(c);
      } else {
        level_[c] = level_[p];  // an organ belongs to its edge
      }
    }
    if (edges.empty()) continue;
    const Eigen::Vector3d hp = heading(tree_, p);
    const NodeId apical = continuation(p, edges);
    bool decurrent = true;  // all children alike within the tolerance
    for (const NodeId c : edges) {
      decurrent =
          decurrent &&
          close(angle_between(hp, heading(tree_, c)),
                angle_between(hp, heading(tree_, edges.front())), params_.same_level_tolerance) &&
          close(tree_.radius(c), tree_.radius(edges.front()), params_.same_level_tolerance);
    }
    for (const NodeId c : edges) {
      if (c == apical) {
        chain_[c] = chain_[p];
        offset_[c] = offset_[p] + tree_.length(p);
        level_[c] = level_[p];
        continue;
      }
      chain_[c] = static_cast<std::uint32_t>(chain_rate_.size());
      chain_rate_.push_back(0.0);
      chain_base_[c] = 1;
      level_[c] = static_cast<std::uint16_t>(std::min<int>(
          level_[p] + (decurrent ? 0 : 1), std::numeric_limits<std::uint16_t>::max()));
    }
  }
}

// Pirk eq. 5.3-5.4: a chain starts when its parent chain reaches the branch point and grows at
// the rate that completes it at t = 1 (or by its growth profile, stages/growth_profile.hpp); an
// edge starts when the chain reaches it. Profiles chosen by chain are chosen from the constant
// rates (a first pass), then the times are computed again with them.
void DevelopmentalModel::compute_growth_times() {
  chain_length_ = chain_rate_;  // assign_levels_and_chains() left the lengths there
  chain_profile_.assign(chain_length_.size(), ChainProfile{});
  propagate_growth_times();
  if (params_.profiles == ProfileChoice::kConstant) return;
  if (params_.profiles == ProfileChoice::kByChain) {
    choose_chain_profiles();
  } else {
    chain_profile_.assign(chain_length_.size(), uniform_profile(params_.profiles));
  }
  propagate_growth_times();
}

void DevelopmentalModel::propagate_growth_times() {
  const std::size_t n = tree_.size();
  chain_start_.assign(chain_length_.size(), 0.0);
  chain_last_.assign(chain_length_.size(), kNoNode);
  chain_rate_.assign(chain_length_.size(), 0.0);
  start_time_.assign(n, 0.0);
  chain_rate_[0] = chain_length_[0];
  for (NodeId i = 0; i < n; ++i) {
    if (!is_edge(tree_, i)) {
      start_time_[i] = start_time_[tree_.parent(i)];
      continue;
    }
    const std::uint32_t c = chain_[i];
    chain_last_[c] = i;  // ids increase along a chain
    if (chain_base_[i]) {
      const NodeId p = tree_.parent(i);
      // The parent chain reaches the end of edge p (where the branch stands).
      chain_start_[c] = std::min(reach_time(chain_[p], offset_[p] + tree_.length(p)), 1.0);
      chain_rate_[c] = chain_length_[c] / std::max(1.0 - chain_start_[c], 1e-9);
    }
    start_time_[i] = reach_time(c, offset_[i]);
  }
}

// The time chain c has grown `length_m` (eq. 5.3 with the chain's profile).
double DevelopmentalModel::reach_time(std::uint32_t c, double length_m) const {
  const ChainProfile& profile = chain_profile_[c];
  if (profile.kind == GrowthProfile::kConstant) {
    return chain_rate_[c] > 0.0 ? chain_start_[c] + length_m / chain_rate_[c] : chain_start_[c];
  }
  const double share = chain_length_[c] > 0.0 ? length_m / chain_length_[c] : 0.0;
  return chain_start_[c] + (1.0 - chain_start_[c]) * profile_time(profile, share);
}

// The length chain c has grown at its own clock tc (eq. 5.3 with the chain's profile).
double DevelopmentalModel::grown_length(std::uint32_t c, double tc) const {
  const ChainProfile& profile = chain_profile_[c];
  if (profile.kind == GrowthProfile::kConstant) return chain_rate_[c] * (tc - chain_start_[c]);
  const double span = std::max(1.0 - chain_start_[c], 1e-9);
  return chain_length_[c] * profile_fraction(profile, (tc - chain_start_[c]) / span);
}

// Profiles by chain (choose_profile) from the constant rates of the first pass, against the
// median rate of each level.
void DevelopmentalModel::choose_chain_profiles() {
  const std::size_t chains = chain_length_.size();
  std::vector<std::uint16_t> chain_level(chains, 1);
  for (NodeId i = 0; i < tree_.size(); ++i) {
    if (is_edge(tree_, i) && (i == 0 || chain_base_[i])) chain_level[chain_[i]] = level_[i];
  }
  std::vector<std::vector<double>> rates;
  for (std::size_t c = 0; c < chains; ++c) {
    if (rates.size() <= chain_level[c]) rates.resize(chain_level[c] + 1u);
    rates[chain_level[c]].push_back(chain_rate_[c]);
  }
  std::vector<double> median(rates.size(), 0.0);
  for (std::size_t g = 0; g < rates.size(); ++g) {
    if (rates[g].empty()) continue;
    auto mid = rates[g].begin() + static_cast<std::ptrdiff_t>(rates[g].size() / 2);
    std::nth_element(rates[g].begin(), mid, rates[g].end());
    median[g] = *mid;
  }
  for (std::size_t c = 0; c < chains; ++c) {
    chain_profile_[c] = choose_profile(chain_level[c], chain_length_[c], chain_length_[0],
                                       chain_rate_[c], median[chain_level[c]], chain_start_[c]);
  }
}

// Pirk eq. 5.5: each lateral chain turns from the mean angle of its level's branches to its own,
// until its subtree carries rigid_tip_count growing tips (one per chain started in it).
void DevelopmentalModel::compute_bending() {
  const std::size_t n = tree_.size();
  // Mean branching angle per level of the lateral (alpha_avg^(n)).
  std::vector<double> angle_sum, angle_count;
  std::vector<double> final_angle(n, 0.0);
  for (NodeId i = 1; i < n; ++i) {
    if (!chain_base_[i]) continue;
    final_angle[i] = angle_between(heading(tree_, tree_.parent(i)), heading(tree_, i));
    if (angle_sum.size() <= level_[i]) angle_sum.resize(level_[i] + 1u, 0.0);
    if (angle_count.size() <= level_[i]) angle_count.resize(level_[i] + 1u, 0.0);
    angle_sum[level_[i]] += final_angle[i];
    angle_count[level_[i]] += 1.0;
  }
  // Start times of the chains in each subtree, smallest first, kept to rigid_tip_count.
  const auto keep = static_cast<std::size_t>(params_.rigid_tip_count);
  std::vector<std::vector<double>> starts(n);
  for (NodeId i = static_cast<NodeId>(n); i-- > 0;) {
    if (!is_edge(tree_, i)) continue;
    if (chain_base_[i] || i == 0) starts[i].push_back(chain_start_[chain_[i]]);
    std::sort(starts[i].begin(), starts[i].end());
    if (starts[i].size() > keep) starts[i].resize(keep);
    if (i > 0) {
      auto& up = starts[tree_.parent(i)];
      up.insert(up.end(), starts[i].begin(), starts[i].end());
    }
  }
  bend_axis_.assign(n, Eigen::Vector3d::Zero());
  bend_angle_.assign(n, 0.0);
  bend_end_.assign(n, 1.0);
  for (NodeId i = 1; i < n; ++i) {
    if (!chain_base_[i]) continue;
    const Eigen::Vector3d axis = heading(tree_, tree_.parent(i)).cross(heading(tree_, i));
    if (axis.norm() < 1e-12) continue;  // a lateral in line with its parent does not turn
    bend_axis_[i] = axis.normalized();
    bend_angle_[i] = final_angle[i] - angle_sum[level_[i]] / angle_count[level_[i]];
    bend_end_[i] = starts[i].size() >= keep ? starts[i][keep - 1] : 1.0;
  }
}

// Pirk eq. 5.7: b_p = sum r_i^u / r_p^u over the children of the given tree; r_avg over its tips.
void DevelopmentalModel::compute_radius_coefficients() {
  const std::size_t n = tree_.size();
  const double u = params_.pipe_exponent;
  radius_coefficient_.assign(n, 0.0);
  edge_children_.assign(n, 0);
  double tip_sum = 0.0;
  std::size_t tips = 0;
  for (NodeId i = 0; i < n; ++i) {
    if (!is_edge(tree_, i)) continue;
    double sum = 0.0;
    bool has_edge_child = false;
    for (const NodeId c : tree_.children(i)) {
      if (!is_edge(tree_, c)) continue;
      has_edge_child = true;
      sum += std::pow(tree_.radius(c), u);
    }
    const double rp = std::pow(tree_.radius(i), u);
    for (const NodeId c : tree_.children(i)) edge_children_[i] += is_edge(tree_, c) ? 1u : 0u;
    if (has_edge_child) {
      radius_coefficient_[i] = rp > 0.0 ? sum / rp : 0.0;
    } else {
      tip_sum += tree_.radius(i);
      ++tips;
    }
  }
  tip_radius_ = tips > 0 ? tip_sum / static_cast<double>(tips) : 0.0;
  tip_radius_pow_ = std::pow(tip_radius_, u);
  radius_pow_.assign(n, 0.0);
  heading_.assign(n, Eigen::Vector3d::UnitZ());
  for (NodeId i = 0; i < n; ++i) {
    radius_pow_[i] = std::pow(tree_.radius(i), u);
    heading_[i] = heading(tree_, i);
  }
}

TreeGraph DevelopmentalModel::stage(double t) const {
  TreeGraph out;
  stage(t, out);
  return out;
}

void DevelopmentalModel::stage(double t, TreeGraph& out) const {
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
  // Branches shed before the given tree are left out as they are placed (place_nodes).
  const bool sheds = added_.copies > 0;
  TreeGraph& grown = sheds ? grown_tree_ : out;
  grown.clear_keep_capacity();  // place_nodes() sizes its columns once (TreeGraph::Appender)
  place_nodes(t, grown);
  // Pirk 5.3.6: the branches shed later still count in the radii (eq. 5.8), so removing them
  // leaves the radii below unchanged.
  set_radii(grown);
  // A branch made younger (5.4.1) is still growing at t = 1.
  if (t < 1.0 || !chain_shift_.empty()) add_tip_leaves(grown);
  if (sheds) remove_shed(t, grown, out);
}

// Pirk eq. 5.10: an added branch is present while its base is at or above the crown base
// h (1 - CR(h)) of the stage's height h. With gamma = 1 the last stage has the given crown base,
// above every added branch; it is the given tree by definition, whatever the rounding.
void DevelopmentalModel::remove_shed(double t, const TreeGraph& grown, TreeGraph& out) const {
  const bool last = t >= 1.0 && params_.added.gamma == 1.0;
  const double height_m = added_.copies > 0 ? tree_height(grown) : 0.0;
  const double base_m = last || added_.copies == 0 ? std::numeric_limits<double>::infinity()
                                                   : added_.curve.crown_base_m(height_m);
  // The overlap region's copies follow eq. 5.10 with the region's top as the final crown base.
  const double overlap_base_m = last || added_.copies == 0
                                    ? std::numeric_limits<double>::infinity()
                                    : added_.overlap_curve.crown_base_m(height_m);
  kept_id_.assign(grown.size(), 0);  // 0: shed, 1: kept; then the new id
  for (NodeId k = 0; k < grown.size(); ++k) kept_id_[k] = 1;
  for (NodeId i = added_.first_added; i < added_end_; ++i) {
    const bool copy_root = tree_.parent(i) < added_.first_added;
    const bool overlap = !added_.in_overlap.empty() && added_.in_overlap[i];
    if (copy_root && stage_id_[i] != kNoNode &&
        added_.attach_height_m[i] < (overlap ? overlap_base_m : base_m)) {
      kept_id_[stage_id_[i]] = 0;
    }
  }
  out.clear_keep_capacity();
  out.reserve(grown.size());
  for (NodeId k = 0; k < grown.size(); ++k) {
    const NodeId p = grown.parent(k);
    if (!kept_id_[k] || (p != kNoNode && kept_id_[p] == kNoNode)) {
      kept_id_[k] = kNoNode;
      continue;
    }
    kept_id_[k] = out.add_node_unchecked(p == kNoNode ? kNoNode : kept_id_[p], grown.data(k));
  }
}

// Pirk 5.3.7: a tip of this stage that is not a tip of the given tree carries, for now, the
// organs of its chain's last edge (the leaves of the chain's tip in the given tree), placed as
// they sit around that edge's end and turned with the tip.
void DevelopmentalModel::add_tip_leaves(TreeGraph& out) const {
  const std::size_t placed = out.size();
  // Stage nodes come in the given tree's order (place_nodes), so the organs are added in it.
  for (NodeId k = 0; k < placed; ++k) {
    const std::uint32_t c = tip_chain_[k];
    if (c == kNoChain) continue;
    const NodeId i = given_of_[k];
    const Eigen::Quaterniond q = (flags_[i] & kTurned) ? turn_[i] : Eigen::Quaterniond::Identity();
    for (std::uint32_t o = tip_organ_start_[c]; o < tip_organ_start_[c + 1]; ++o) {
      NodeData d = tip_organs_[o];
      d.order = out.order(k);
      d.birth_time = out.birth_time(k);
      d.start = out.end(k) + q * d.start;
      d.end = out.end(k) + q * d.end;
      d.direction = q * d.direction;
      out.add_node_unchecked(k, d);
    }
  }
}

// Eq. 5.5: the part of a lateral chain's turn still to come at its clock tc, about its base,
// after the turn q of the nodes below. False when the node does not turn.
bool DevelopmentalModel::bend(NodeId i, double tc, Eigen::Quaterniond& q) const {
  const PlacePlan& a = plan_[i];
  if (!a.chain_base || a.kind != OrganKind::kInternode) return false;
  const BendPlan& b = bend_plan_[a.chain];
  if (b.angle == 0.0 || !(tc < b.end)) return false;
  const double span = std::max(b.end - a.start_time, 1e-12);
  const double done = std::clamp((tc - a.start_time) / span, 0.0, 1.0);
  q = q * Eigen::AngleAxisd(-(1.0 - done) * b.angle, b.axis);
  return true;
}

// Forward, parents first: grown length, rotation (the bends of the chain bases above), position.
// Reads one plan per node in id order (a stage streams through it; see build_plans()). Most
// nodes of an early stage stop at their parent's flags, without reading their plan. Flattened:
// GCC would otherwise call the appender and the bend check out of line for every node.
[[gnu::flatten]] void DevelopmentalModel::place_nodes(double t, TreeGraph& out) const {
  const std::size_t n = plan_.size();
  stage_id_.resize(n);
  flags_.resize(n);
  turn_.resize(n);
  given_of_.resize(n);  // a stage holds each node of tree_ once at most
  tip_chain_.resize(n);
  const std::span<const NodeId> parents = tree_.parents();
  const bool shifted = !chain_shift_.empty();
  // Eq. 5.3's constant rates need no profile (the common case, read once here).
  const bool profiled = params_.profiles != ProfileChoice::kConstant;
  const bool shedding = !shed_root_.empty();
  shed_pipes_.clear();
  TreeGraph::Appender append(out, n);
  for (NodeId i = 0; i < n; ++i) {
    const NodeId p = i == 0 ? kNoNode : parents[i];
    stage_id_[i] = kNoNode;
    flags_[i] = 0;
    if (p != kNoNode && !(flags_[p] & kComplete)) continue;  // absent or still growing
    const PlacePlan& a = plan_[i];
    if (shedding && a.chain_base && t >= chain_shed_time_[a.chain]) {
      // A branch shed before the given tree, gone with its subtree once complete; its pipes stay
      // in its parent's wood (eq. 5.8, as Pirk 5.3.6 keeps those of removed branches).
      shed_pipes_.push_back({stage_id_[p], radius_pow_[i]});
      // Its nodes follow it in one run of ids, and nothing else reads them in this stage.
      i = chain_shed_end_[a.chain] - 1;
      continue;
    }
    const bool edge = a.kind == OrganKind::kInternode;
    double length = a.length;
    // The chain's own clock: t, unless an edit shifted it (5.4.1).
    const double tc = edge && shifted ? t + chain_shift_[a.chain] : t;
    if (edge) {
      const double reach = (profiled ? grown_length(a.chain, tc)
                                     : chain_rate_[a.chain] * (tc - chain_start_[a.chain])) -
                           a.chain_offset;
      if (tc < 1.0 && !(reach > 0.0)) continue;  // not started yet
      // At t = 1 every edge is complete (rounding must not leave one a hair short).
      if (tc < 1.0) length = std::min(reach, length);
    }
    bool turned = p != kNoNode && (flags_[p] & kTurned);
    Eigen::Quaterniond q = turned ? turn_[p] : Eigen::Quaterniond::Identity();
    if (a.chain_base) turned = bend(i, tc, q) || turned;
    if (turned) turn_[i] = q;  // read only under a turned node
    NodeData d;
    d.kind = a.kind;
    d.order = a.order;
    d.birth_time = shifted ? a.start_time - chain_shift_[a.chain] : a.start_time;
    d.physiological_age = a.age;
    d.length = length;
    const NodeId pk = p == kNoNode ? kNoNode : stage_id_[p];
    const Eigen::Vector3d base = pk == kNoNode ? root_start_ : out.end(pk);
    d.direction = turned ? Eigen::Vector3d(q * a.heading) : a.heading;
    d.start = base;
    const SidePlan* side = a.side == kNoNode ? nullptr : &side_plan_[a.side];
    if (side) d.start += turned ? Eigen::Vector3d(q * side->offset) : side->offset;
    if (edge) {
      d.end = d.start + length * d.direction;
    } else {
      d.radius = side->radius;
      d.end = d.start + (turned ? Eigen::Vector3d(q * side->span) : side->span);
    }
    const NodeId k = append.add(pk, d);
    stage_id_[i] = k;
    given_of_[k] = i;
    tip_chain_[k] = edge && !a.chain_last ? a.chain : kNoChain;
    if (pk != kNoNode) tip_chain_[pk] = kNoChain;
    flags_[i] =
        static_cast<std::uint8_t>((length < a.length ? 0 : kComplete) | (turned ? kTurned : 0));
  }
}

// Backward, from the tips: radii by eq. 5.8 (r^u carried, so one root per inner edge). An edge
// whose subtree is complete has its given radius, which eq. 5.8 gives back by construction of b.
// Runs over the nodes place_nodes() put in `out` (stage ids follow the given tree's order).
void DevelopmentalModel::set_radii(TreeGraph& out) const {
  const double inv_u = params_.pipe_exponent == 2.5 ? 0.0 : 1.0 / params_.pipe_exponent;
  below_.assign(out.size(), Below{});
  for (const auto& [k, pipes] : shed_pipes_) {
    below_[k].sum += pipes;
    below_[k].has_child = 1;
  }
  for (NodeId k = static_cast<NodeId>(out.size()); k-- > 0;) {
    const NodeId i = given_of_[k];
    const RadiusPlan& a = radius_plan_[i];
    if (!a.edge) continue;
    const Below& b = below_[k];
    const bool complete = (flags_[i] & kComplete) && b.complete_children == a.edge_children;
    double r = a.radius, r_u = a.radius_pow;
    if (complete) {
      // the given radius
    } else if (b.has_child) {
      if (a.coefficient > 0.0) {
        r_u = b.sum / a.coefficient;
        r = pipe_root(r_u, inv_u);
      }
    } else if (a.coefficient > 0.0) {
      r = tip_radius_;  // a tip now that is not one in the given tree
      r_u = tip_radius_pow_;
    }
    out.set_radius(k, r);
    if (k > 0) {
      Below& up = below_[out.parent(k)];
      up.sum += r_u;
      up.has_child = 1;
      up.complete_children += complete ? 1u : 0u;
    }
  }
}

// The per-node data a stage reads, gathered from the analysis (and the edits) into one record
// per node, so that place_nodes() and set_radii() each stream through one array.
void DevelopmentalModel::build_plans() {
  const std::size_t n = tree_.size();
  plan_.assign(n, PlacePlan{});
  side_plan_.clear();
  radius_plan_.resize(n);
  root_start_ = tree_.start(0);
  bend_plan_.assign(chain_rate_.size(), BendPlan{});
  for (NodeId i = 0; i < n; ++i) {
    const NodeId p = i == 0 ? kNoNode : tree_.parent(i);
    const bool edge = is_edge(tree_, i);
    PlacePlan& a = plan_[i];
    const Eigen::Vector3d offset = tree_.start(i) - (p == kNoNode ? tree_.start(0) : tree_.end(p));
    if (!edge || offset != Eigen::Vector3d::Zero()) {
      a.side = static_cast<std::uint32_t>(side_plan_.size());
      side_plan_.push_back({offset, tree_.end(i) - tree_.start(i), tree_.radius(i)});
    }
    a.heading = edge ? heading_[i] : tree_.direction(i);
    a.length = tree_.length(i);
    a.chain_offset = offset_[i];
    a.start_time = start_time_[i];
    // An organ takes the chain (and clock) of the internode bearing it.
    NodeId bearer = i;
    while (!is_edge(tree_, bearer)) bearer = tree_.parent(bearer);
    a.chain = chain_[bearer];
    a.order = static_cast<std::uint16_t>(level_[i] - 1);
    a.age = tree_.physiological_age(i);
    a.kind = tree_.kind(i);
    a.chain_base = chain_base_[i];
    a.chain_last = edge && chain_last_[a.chain] == i;
    if (edge && a.chain_base) bend_plan_[a.chain] = {bend_axis_[i], bend_angle_[i], bend_end_[i]};
    RadiusPlan& r = radius_plan_[i];
    r.radius = tree_.radius(i);
    r.radius_pow = radius_pow_[i];
    r.coefficient = radius_coefficient_[i];
    r.edge_children = edge_children_[i];
    r.edge = edge;
  }
}

// The organs each chain's tip carries in the given tree, for add_tip_leaves().
void DevelopmentalModel::build_tip_organs() {
  tip_organs_.clear();
  tip_organ_start_.assign(1, 0);
  for (const NodeId last : chain_last_) {
    for (const NodeId organ : tree_.children(last)) {
      if (is_edge(tree_, organ)) continue;
      NodeData d = tree_.data(organ);
      d.start = tree_.start(organ) - tree_.end(last);
      d.end = tree_.end(organ) - tree_.end(last);
      tip_organs_.push_back(d);
    }
    tip_organ_start_.push_back(static_cast<std::uint32_t>(tip_organs_.size()));
  }
}

}  // namespace fspm::stages
