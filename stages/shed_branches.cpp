#include "stages/shed_branches.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "fspm/error.hpp"

namespace fspm::stages {

void ShedBranchesParams::validate() const {
  if (!(min_pipes > 0.0 && min_pipes <= 1e6)) {
    throw ValueError("stages: the pipes that imply a shed branch must be in (0, 1e6], got " +
                     std::to_string(min_pipes));
  }
}

std::vector<ShedSite> find_shed_sites(const TreeGraph& tree, double pipe_exponent,
                                      double tip_radius_m, double min_pipes) {
  std::vector<ShedSite> sites;
  const double tip_pipe = std::pow(tip_radius_m, pipe_exponent);
  if (!(tip_pipe > 0.0)) return sites;
  for (NodeId i = 0; i < tree.size(); ++i) {
    if (tree.kind(i) != OrganKind::kInternode) continue;
    double need = 0.0;
    bool has_edge_child = false;
    for (const NodeId c : tree.children(i)) {
      if (tree.kind(c) != OrganKind::kInternode) continue;
      has_edge_child = true;
      need += std::pow(tree.radius(c), pipe_exponent);
    }
    if (!has_edge_child) continue;
    // Shinozaki et al. 1964: the pipes beyond the children's are those of shed branches.
    const double pipes = (std::pow(tree.radius(i), pipe_exponent) - need) / tip_pipe;
    if (pipes >= min_pipes) sites.push_back({i, pipes});
  }
  return sites;
}

NodeId choose_shed_source(const std::vector<ShedSource>& sources, double pipes, double reached) {
  if (sources.empty()) return kNoNode;
  const auto at = std::lower_bound(sources.begin(), sources.end(), pipes,
                                   [](const ShedSource& s, double p) { return s.pipes < p; });
  const auto mismatch = [pipes](const ShedSource& s) {
    return std::abs(std::log(std::max(s.pipes, 1e-300) / pipes));
  };
  // Outward from the closest in pipes: the first later starter on each side.
  NodeId best = kNoNode;
  double best_mismatch = std::numeric_limits<double>::infinity();
  for (auto it = at; it != sources.end(); ++it) {
    if (it->start > reached) {
      best = it->base, best_mismatch = mismatch(*it);
      break;
    }
  }
  for (auto it = at; it != sources.begin();) {
    --it;
    if (it->start > reached) {
      if (mismatch(*it) < best_mismatch) best = it->base;
      break;
    }
  }
  if (best != kNoNode) return best;
  // None starts later: the closest in pipes.
  if (at == sources.end()) return std::prev(at)->base;
  if (at == sources.begin()) return at->base;
  return mismatch(*at) <= mismatch(*std::prev(at)) ? at->base : std::prev(at)->base;
}

}  // namespace fspm::stages
