// Growth-based editing of selected branches (Pirk 2013, 5.4.1; stages/branch_edits.hpp): the
// edits change the analysed model, so that every stage computed afterwards carries them.
#include <Eigen/Geometry>
#include <algorithm>
#include <limits>
#include <map>
#include <string>

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"
#include "stages/developmental_model.hpp"

namespace fspm::stages {
namespace {

// Never equal to a count of children: an edge with an edited branch below never takes its given
// radius as complete, but eq. 5.8 with the given b (Pirk 5.4.1: "the radii of parent branches
// are changed according to Section 5.3.3").
constexpr std::uint32_t kEditedBelow = std::numeric_limits<std::uint32_t>::max();

// Per node of the model beyond its tree (and the stage's tree, counted with it): the analysed
// columns (chains, offsets, bends, radii, headings), the place and radius plans, the work arrays
// of a stage and the copy's map of ids.
constexpr double kModelBytesPerNode = 400.0;

}  // namespace

void DevelopmentalModel::apply_edits() {
  if (params_.edits.empty()) return;
  chain_shift_.assign(chain_rate_.size(), 0.0);
  for (const AgeEdit& a : params_.edits.age) {
    const NodeId base = edited_branch_base(a.branch, "age");
    if (a.delta_t == 0.0) continue;  // nothing to change
    // The whole branch, with the chains it carries, runs ahead by delta_t.
    for (const NodeId i : subtree(base)) {
      if (is_internode(i) && (i == base || chain_base_[i])) chain_shift_[chain_[i]] += a.delta_t;
    }
    mark_edited_ancestors(tree_.parent(base));
  }
  for (const CopyEdit& c : params_.edits.copy) append_branch_copy(c);
}

bool DevelopmentalModel::is_internode(NodeId n) const {
  return tree_.kind(n) == OrganKind::kInternode;
}

// The first edge of the lateral chain holding `node` (an internode of the given tree).
NodeId DevelopmentalModel::edited_branch_base(NodeId node, const char* what) const {
  const std::string head = std::string("branch edit (") + what + "): node " + std::to_string(node);
  if (node >= given_size_) {
    throw ValueError(head + " is not in the given tree (" + std::to_string(given_size_) +
                     " nodes)");
  }
  if (!is_internode(node)) throw ValueError(head + " is an organ; expected an internode");
  if (chain_[node] == 0) {
    throw ValueError(head + " is on the main axis; expected a node of a lateral branch");
  }
  NodeId b = node;
  while (!chain_base_[b]) b = tree_.parent(b);
  return b;
}

// `base` and its descendants below node `end` (all by default), in id order (parents first).
std::vector<NodeId> DevelopmentalModel::subtree(NodeId base, NodeId end) const {
  end = std::min<NodeId>(end, static_cast<NodeId>(tree_.size()));
  std::vector<std::uint8_t> in(end - base, 0);
  std::vector<NodeId> out{base};
  in[0] = 1;
  for (NodeId i = base + 1; i < end; ++i) {
    const NodeId p = tree_.parent(i);
    if (p >= base && in[p - base]) in[i - base] = 1, out.push_back(i);
  }
  return out;
}

void DevelopmentalModel::mark_edited_ancestors(NodeId from) {
  for (NodeId a = from; a != kNoNode; a = a == 0 ? kNoNode : tree_.parent(a)) {
    edge_children_[a] = kEditedBelow;
  }
}

// The copy stands at the end of the target, turned by the rotation that takes the source's
// parent heading to the target's (rigid: the copy meets the target as the source meets its
// parent), and keeps the source's chains, rates and bends on clocks shifted so that it starts
// when its parent chain reaches the target end, at the age the source had at its own start.
double DevelopmentalModel::append_branch_copy(const CopyEdit& edit, double roll_rad,
                                              const std::vector<NodeId>* branch) {
  const NodeId base = edited_branch_base(edit.branch, "copy");
  const NodeId target = edit.target;
  if (target >= given_size_ || !is_internode(target)) {
    throw ValueError("branch edit (copy): target " + std::to_string(target) +
                     " is not an internode of the given tree");
  }
  const NodeId sp = tree_.parent(base);
  const Eigen::Quaterniond q = Eigen::Quaterniond(Eigen::AngleAxisd(roll_rad, heading_[target])) *
                               Eigen::Quaterniond::FromTwoVectors(heading_[sp], heading_[target]);
  const Eigen::Vector3d from = tree_.end(sp), to = tree_.end(target);
  const std::uint32_t cb = chain_[base], ct = chain_[target];
  const double target_reached =
      std::min(reach_time(ct, offset_[target] + tree_.length(target)), 1.0);
  const double shift = (chain_start_[cb] - chain_shift_[cb]) - (target_reached - chain_shift_[ct]);
  const std::vector<NodeId> nodes = branch ? *branch : subtree(base);
  // A copy onto a node of its own branch carries the copies made before it: repeated, the model
  // doubles with each edit, so each is checked against the memory limit before it is made.
  const double after = static_cast<double>(tree_.size() + nodes.size());
  check_memory(after * (2.0 * TreeGraph::bytes_per_node(tree_.attribute_names().size()) +
                        kModelBytesPerNode),
               "branch edit (copy) " + std::to_string(edit.branch) + ":" + std::to_string(target) +
                   ": a model of " + std::to_string(static_cast<std::uint64_t>(after)) + " nodes");
  std::map<NodeId, NodeId> id;
  std::map<std::uint32_t, std::uint32_t> new_chain;
  for (const NodeId k : nodes) {
    NodeData d = tree_.data(k);
    d.start = to + q * (d.start - from);
    d.end = to + q * (d.end - from);
    d.direction = q * d.direction;
    const NodeId j = tree_.add_node_unchecked(k == base ? target : id.at(tree_.parent(k)), d);
    id[k] = j;
    std::uint32_t c = chain_[k];
    if (c != std::numeric_limits<std::uint32_t>::max()) {
      auto [it, added] = new_chain.try_emplace(c, static_cast<std::uint32_t>(chain_rate_.size()));
      if (added) {
        chain_rate_.push_back(chain_rate_[c]);
        chain_length_.push_back(chain_length_[c]);
        chain_profile_.push_back(chain_profile_[c]);
        chain_start_.push_back(chain_start_[c]);
        chain_last_.push_back(chain_last_[c]);  // remapped below
        chain_shift_.push_back(chain_shift_[c] + shift);
      }
      c = it->second;
    }
    level_.push_back(static_cast<std::uint16_t>(level_[target] + 1 + level_[k] - level_[base]));
    chain_.push_back(c);
    offset_.push_back(offset_[k]);
    start_time_.push_back(start_time_[k]);
    chain_base_.push_back(chain_base_[k]);
    bend_axis_.push_back(q * bend_axis_[k]);
    bend_angle_.push_back(bend_angle_[k]);
    bend_end_.push_back(bend_end_[k]);
    radius_coefficient_.push_back(radius_coefficient_[k]);
    radius_pow_.push_back(radius_pow_[k]);
    edge_children_.push_back(edge_children_[k]);
    heading_.push_back(q * heading_[k]);
  }
  for (const auto& [source, copy] : new_chain) chain_last_[copy] = id.at(chain_last_[source]);
  // A former tip carries the copy's pipes alone (b = 1 in eq. 5.8).
  if (radius_coefficient_[target] == 0.0) radius_coefficient_[target] = 1.0;
  mark_edited_ancestors(target);
  return shift;
}

}  // namespace fspm::stages
