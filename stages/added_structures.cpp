#include "stages/added_structures.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "fspm/error.hpp"
#include "stages/profile_diagram.hpp"

namespace fspm::stages {
namespace {

bool is_edge(const TreeGraph& t, NodeId n) { return t.kind(n) == OrganKind::kInternode; }

double logit(double p) { return std::log(p / (1.0 - p)); }

// A lateral branch of the main chain: the main-chain edge it sits on (index into the chain),
// its first edge, and the arc length of the main chain at its base.
struct Lateral {
  std::size_t on = 0;
  NodeId base = kNoNode;
  double arc_m = 0.0;
};

// The main chain's edges in order from the root, and the arc length at the end of each.
void main_chain(const TreeGraph& tree, const std::vector<std::uint32_t>& chain,
                std::vector<NodeId>& edges, std::vector<double>& arc_end_m) {
  double arc = 0.0;
  for (NodeId i = 0; i < tree.size(); ++i) {
    if (!is_edge(tree, i) || chain[i] != 0) continue;
    arc += tree.length(i);
    edges.push_back(i);
    arc_end_m.push_back(arc);
  }
}

// Per node: whether its subtree carries a leaf (a live branch). All live in a tree without
// leaves (a bare skeleton), whose crown then starts at its lowest lateral.
std::vector<std::uint8_t> live(const TreeGraph& tree) {
  std::vector<std::uint8_t> has(tree.size(), 0);
  bool any = false;
  for (NodeId i = static_cast<NodeId>(tree.size()); i-- > 0;) {
    if (tree.kind(i) == OrganKind::kLeaf) has[i] = 1, any = true;
    if (i > 0 && has[i]) has[tree.parent(i)] = 1;
  }
  if (!any) has.assign(tree.size(), 1);
  return has;
}

// The live laterals of the main chain, from the root up. Leafless stubs are dead branches: the
// crown starts at the lowest live branch, as in forestry.
std::vector<Lateral> laterals(const TreeGraph& tree, const std::vector<std::uint32_t>& chain,
                              const std::vector<NodeId>& edges, const std::vector<double>& arc) {
  const std::vector<std::uint8_t> alive = live(tree);
  std::vector<Lateral> out;
  for (std::size_t j = 0; j < edges.size(); ++j) {
    for (const NodeId c : tree.children(edges[j])) {
      if (is_edge(tree, c) && chain[c] != 0 && alive[c]) out.push_back({j, c, arc[j]});
    }
  }
  return out;
}

// The first `count` main-chain edges: the one whose end is nearest the arc length `target_m`.
std::size_t nearest_edge(const std::vector<double>& arc_end_m, std::size_t count, double target_m) {
  const auto it = std::lower_bound(arc_end_m.begin(), arc_end_m.begin() + count, target_m);
  const std::size_t j = static_cast<std::size_t>(it - arc_end_m.begin());
  if (j == 0) return 0;
  if (j == count || target_m - arc_end_m[j - 1] < arc_end_m[j] - target_m) return j - 1;
  return j;
}

// Appends to `out` under `parent` a copy of the subtree at `source`, turned about the vertical
// by `turn_rad` and scaled by `scale` about its base, its base moved to the end of `parent`.
NodeId append_copy(TreeGraph& out, NodeId parent, NodeId source, double turn_rad, double scale) {
  TreeGraph copy = out.copy_subtree(source);
  const Eigen::Vector3d from = copy.start(0);
  const Eigen::Vector3d to = out.end(parent);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(turn_rad, Eigen::Vector3d::UnitZ()).matrix();
  for (NodeId i = 0; i < copy.size(); ++i) {
    const Eigen::Vector3d direction = turn * copy.direction(i);
    const double length = copy.length(i) * scale;
    copy.set_segment(i, to + scale * (turn * (copy.start(i) - from)),
                     to + scale * (turn * (copy.end(i) - from)));
    copy.set_direction(i, direction);
    copy.set_length(i, length);
    copy.set_radius(i, copy.radius(i) * scale);
  }
  return out.append_subtree(parent, copy);
}

// Where copies go: the main chain's edges and arc lengths, the live laterals on it, and the
// given tree's chains (for the profile diagrams).
struct MainChain {
  std::vector<NodeId> edges;
  std::vector<double> arc;
  std::vector<Lateral> side;
  const std::vector<std::uint32_t>* chain = nullptr;
};

// Records the heights at which the nodes appended since `root` are attached.
void mark_copy(AddedStructures& out, std::vector<double>& attach_height, NodeId root,
               double height_m) {
  attach_height.resize(out.tree.size(), std::numeric_limits<double>::quiet_NaN());
  std::fill(attach_height.begin() + root, attach_height.end(), height_m);
  ++out.copies;
}

// Pirk 5.3.5 heuristic: a segment whose tissue above by stratified clipping clearly exceeds that
// by main-axis cutting carries biomass grown from elsewhere on the axis (a branch there was
// lost); where both are low the crown is thin. Per layer of the profile diagrams.
std::vector<std::uint8_t> overlap_layers(const TreeGraph& tree, const MainChain& m,
                                         const AddedStructuresParams& params, double height_m,
                                         double& layer_m) {
  layer_m = params.overlap_layer_m > 0.0 ? params.overlap_layer_m : height_m / 20.0;
  const ProfileDiagram stc = profile_diagram(tree, *m.chain, layer_m, Clipping::kStratified);
  const ProfileDiagram mac = profile_diagram(tree, *m.chain, layer_m, Clipping::kMainAxis);
  std::vector<std::uint8_t> keep(stc.tissue_above.size(), 0);
  for (std::size_t k = 0; k < keep.size(); ++k) {
    const double s = stc.tissue_above[k], a = mac.tissue_above[k];
    keep[k] = s > (1.0 + params.overlap_significance) * a || std::max(s, a) < params.overlap_low;
  }
  return keep;
}

// Pirk 5.3.5: the overlap region is the main chain from the crown base s_b up over the length of
// the filled sub-crown region; the laterals one copy period above it are copied down by the
// period into it, on the segments the heuristic keeps.
void fill_overlap(const TreeGraph& tree, const MainChain& m, const AddedStructuresParams& params,
                  double s_b, double length_m, double period, AddedStructures& out,
                  std::vector<double>& attach_height) {
  const double golden_rad = std::numbers::pi * (3.0 - std::sqrt(5.0));
  const double base_z = tree.start(0).z();
  double layer_m = 0.0;
  const std::vector<std::uint8_t> keep =
      overlap_layers(tree, m, params, out.crown.height_m, layer_m);
  const std::size_t top = nearest_edge(m.arc, m.edges.size(), s_b + length_m);
  out.overlap_top_m = tree.end(m.edges[top]).z() - base_z;
  for (const Lateral& l : m.side) {
    const double target = l.arc_m - period;
    if (target < s_b - 1e-12 || target >= s_b + length_m - 1e-12) continue;
    const std::size_t j = nearest_edge(m.arc, m.edges.size(), target);
    if (j + 1 >= m.edges.size()) continue;
    if (tree.radius(l.base) * params.scale >= 0.9 * tree.radius(m.edges[j + 1])) continue;
    const double height_m = tree.end(m.edges[j]).z() - base_z;
    const auto layer = static_cast<std::size_t>(
        std::clamp(std::floor(height_m / layer_m), 0.0, static_cast<double>(keep.size() - 1)));
    if (!keep[layer]) continue;
    const NodeId root = append_copy(out.tree, m.edges[j], l.base, golden_rad, params.scale);
    mark_copy(out, attach_height, root, height_m);
    out.in_overlap.resize(out.tree.size(), 0);
    std::fill(out.in_overlap.begin() + root, out.in_overlap.end(), std::uint8_t{1});
    ++out.overlap_copies;
  }
  // Eq. 5.10 with the region's top as the crown base at the given height: its copies are shed
  // as the crown base of the stages rises through it.
  const double h = out.crown.height_m;
  out.overlap_curve = CrownRatioCurve(params.crown_ratio_at_zero_height, h,
                                      h > 0.0 ? (h - out.overlap_top_m) / h : 1.0, params.gamma);
}

}  // namespace

void AddedStructuresParams::validate() const {
  if (!(crown_ratio_at_zero_height > 0.0 && crown_ratio_at_zero_height < 1.0)) {
    throw ValueError("stages: the crown ratio at zero height must be in (0, 1)");
  }
  if (!(gamma > 0.0 && gamma <= 100.0)) throw ValueError("stages: gamma must be in (0, 100]");
  if (!(scale > 0.0 && scale <= 10.0)) throw ValueError("stages: copy scale must be in (0, 10]");
  if (!(overlap_layer_m >= 0.0 && overlap_layer_m <= 1e4) ||
      !(overlap_significance >= 0.0 && overlap_significance <= 100.0) ||
      !(overlap_low >= 0.0 && overlap_low <= 1.0)) {
    throw ValueError(
        "stages: expected an overlap layer in [0, 1e4] m, a significance in [0, 100] and a low "
        "share in [0, 1]");
  }
}

double tree_height(const TreeGraph& tree) {
  if (tree.empty()) return 0.0;
  double top = -std::numeric_limits<double>::infinity();
  for (NodeId i = 0; i < tree.size(); ++i) {
    if (is_edge(tree, i)) top = std::max({top, tree.start(i).z(), tree.end(i).z()});
  }
  return top - tree.start(0).z();
}

CrownShape crown_shape(const TreeGraph& tree, const std::vector<std::uint32_t>& chain) {
  CrownShape shape;
  shape.height_m = tree_height(tree);
  shape.crown_base_m = shape.height_m;  // no lateral: no crown
  std::vector<NodeId> edges;
  std::vector<double> arc;
  main_chain(tree, chain, edges, arc);
  const std::vector<Lateral> side = laterals(tree, chain, edges, arc);
  if (side.empty()) return shape;
  shape.crown_base_node = edges[side.front().on];
  shape.crown_base_m = tree.end(shape.crown_base_node).z() - tree.start(0).z();
  return shape;
}

CrownRatioCurve::CrownRatioCurve(double cr_0, double height_p_m, double cr_p, double gamma)
    : gamma_(gamma) {
  // Pirk eq. 5.10 with gamma = 1 through (0, CR_0) and (h_p, CR_p); a crown ratio above CR_0
  // (a crown down to the ground) keeps CR at CR_0.
  c0_ = logit(cr_0);
  const double target = std::clamp(cr_p, 1e-9, cr_0);
  c1_ = height_p_m > 0.0 ? (logit(target) - c0_) / height_p_m : 0.0;
}

double CrownRatioCurve::crown_ratio(double height_m) const {
  return std::pow(1.0 / (1.0 + std::exp(-(c0_ + c1_ * height_m))), gamma_);
}

double CrownRatioCurve::crown_base_m(double height_m) const {
  return height_m * (1.0 - crown_ratio(height_m));
}

AddedStructures add_structures(const TreeGraph& tree, const std::vector<std::uint32_t>& chain,
                               const AddedStructuresParams& params) {
  params.validate();
  AddedStructures out;
  out.tree = tree;
  out.first_added = static_cast<NodeId>(tree.size());
  out.crown = crown_shape(tree, chain);
  out.curve = CrownRatioCurve(params.crown_ratio_at_zero_height, out.crown.height_m,
                              out.crown.crown_ratio(), params.gamma);
  out.attach_height_m.assign(tree.size(), std::numeric_limits<double>::quiet_NaN());
  MainChain m;
  m.chain = &chain;
  main_chain(tree, chain, m.edges, m.arc);
  m.side = laterals(tree, chain, m.edges, m.arc);
  const std::vector<Lateral>& side = m.side;
  const std::vector<double>& arc = m.arc;
  if (side.empty() || side.front().on == 0 ||
      out.crown.crown_ratio() >= params.crown_ratio_at_zero_height) {
    return out;
  }
  // Pirk 5.3.5: copy the largest continuous block of crown laterals with the fewest copies. The
  // block is as long as the bare trunk, or the whole crown (plus one mean gap between laterals,
  // to keep the spacing) when that is shorter.
  const std::size_t bare = side.front().on;  // main-chain edges 0..bare-1 are bare
  const double s_b = arc[bare], s_0 = arc.front();
  const double span = side.back().arc_m - s_b;
  const double gap = side.size() > 1 ? span / static_cast<double>(side.size() - 1) : s_b - s_0;
  const double block = span + gap > 0.0 ? span + gap : s_b - s_0;
  const double period = std::min(s_b - s_0, block);
  if (!(period > 0.0)) return out;
  const double golden_rad = std::numbers::pi * (3.0 - std::sqrt(5.0));
  std::vector<double> attach_height = out.attach_height_m;
  for (int k = 1; s_b - k * period + period > s_0; ++k) {
    for (const Lateral& l : side) {
      const double target = l.arc_m - k * period;
      if (l.arc_m >= s_b + period || target < s_0 - 1e-12) continue;
      const std::size_t j = nearest_edge(arc, bare, target);
      // A copy nearly as thick as the trunk above it would continue the main chain (5.2.2)
      // and turn the trunk into a lateral; it is left out.
      if (tree.radius(l.base) * params.scale >= 0.9 * tree.radius(m.edges[j + 1])) continue;
      const NodeId at = m.edges[j];
      const NodeId root = append_copy(out.tree, at, l.base, k * golden_rad, params.scale);
      mark_copy(out, attach_height, root, tree.end(at).z() - tree.start(0).z());
    }
  }
  if (params.overlap) fill_overlap(tree, m, params, s_b, s_b - s_0, period, out, attach_height);
  attach_height.resize(out.tree.size(), std::numeric_limits<double>::quiet_NaN());
  out.attach_height_m = std::move(attach_height);
  if (!out.in_overlap.empty()) out.in_overlap.resize(out.tree.size(), 0);
  return out;
}

}  // namespace fspm::stages
