// Branches shed before the given tree, reconstructed from the pipe model (Shinozaki et al. 1964;
// stages/shed_branches.hpp): one copy of a lateral of the given tree at each edge whose radius
// holds pipes beyond its children's needs, on a clock that completes it before t = 1.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <unordered_map>
#include <vector>

#include "stages/developmental_model.hpp"

namespace fspm::stages {

void DevelopmentalModel::reconstruct_shed_branches() {
  if (!params_.shed.enabled) return;
  const std::vector<ShedSite> sites =
      find_shed_sites(tree_, params_.pipe_exponent, tip_radius_, params_.shed.min_pipes);
  if (sites.empty()) return;
  // The laterals of the given tree (not the added structures) that a copy may take.
  std::vector<ShedSource> sources;
  for (NodeId i = 1; i < given_size_; ++i) {
    if (!is_internode(i) || !chain_base_[i]) continue;
    const double shift = chain_shift_.empty() ? 0.0 : chain_shift_[chain_[i]];
    sources.push_back({i, radius_pow_[i] / tip_radius_pow_, chain_start_[chain_[i]] - shift});
  }
  std::sort(sources.begin(), sources.end(),
            [](const ShedSource& a, const ShedSource& b) { return a.pipes < b.pipes; });
  if (chain_shift_.empty()) chain_shift_.assign(chain_rate_.size(), 0.0);
  // Copies of one source at several places are turned apart by the golden angle.
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  std::unordered_map<NodeId, std::vector<NodeId>> branches;  // per source, its nodes
  for (std::size_t k = 0; k < sites.size(); ++k) {
    const NodeId target = sites[k].edge;
    if (target >= given_size_) continue;
    const std::uint32_t ct = chain_[target];
    const double reached =
        std::min(reach_time(ct, offset_[target] + tree_.length(target)), 1.0) - chain_shift_[ct];
    const NodeId source = choose_shed_source(sources, sites[k].pipes, reached);
    if (source == kNoNode) break;
    const NodeId root = static_cast<NodeId>(tree_.size());
    const double source_pow = radius_pow_[source];
    // The source as in the given tree (without the shed branches already stood in it).
    auto [it, fresh] = branches.try_emplace(source);
    if (fresh) it->second = subtree(source, given_size_);
    append_branch_copy({source, target}, golden * static_cast<double>(k), &it->second);
    // The copy takes the disused pipes' place in eq. 5.7, so the radii below stay as given.
    if (radius_pow_[target] > 0.0) radius_coefficient_[target] += source_pow / radius_pow_[target];
    shed_root_.push_back(root);
    // Complete, and shed, when its own clock reaches 1.
    shed_time_.push_back(std::clamp(1.0 - chain_shift_[chain_[root]], 0.0, 1.0));
  }
  chain_shed_time_.assign(chain_rate_.size(), std::numeric_limits<double>::infinity());
  chain_shed_end_.assign(chain_rate_.size(), kNoNode);
  for (std::size_t k = 0; k < shed_root_.size(); ++k) {
    chain_shed_time_[chain_[shed_root_[k]]] = shed_time_[k];
    // Each copy's nodes were appended in one run.
    chain_shed_end_[chain_[shed_root_[k]]] =
        k + 1 < shed_root_.size() ? shed_root_[k + 1] : static_cast<NodeId>(tree_.size());
  }
}

}  // namespace fspm::stages
