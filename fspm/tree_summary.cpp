#include "fspm/tree_summary.hpp"

#include <algorithm>
#include <vector>

namespace fspm {

TreeSummary summarize(const TreeGraph& tree) {
  TreeSummary s;
  s.nodes = tree.size();
  if (tree.empty()) return s;
  s.bbox_min = tree.start(0);
  s.bbox_max = tree.start(0);
  std::vector<std::size_t> depth(tree.size(), 0);
  double max_z = tree.start(0).z();
  for (NodeId n = 0; n < tree.size(); ++n) {
    switch (tree.kind(n)) {
      case OrganKind::kInternode:
        ++s.internodes;
        s.total_length_m += tree.length(n);
        break;
      case OrganKind::kLeaf:
        ++s.leaves;
        break;
      case OrganKind::kFlower:
        ++s.flowers;
        break;
      case OrganKind::kBud:
        ++s.buds;
        break;
    }
    if (tree.is_tip(n)) ++s.tips;
    s.max_order = std::max<std::size_t>(s.max_order, tree.order(n));
    if (tree.parent(n) != kNoNode) depth[n] = depth[tree.parent(n)] + 1;
    s.max_depth = std::max(s.max_depth, depth[n]);
    for (const Eigen::Vector3d& p : {tree.start(n), tree.end(n)}) {
      s.bbox_min = s.bbox_min.cwiseMin(p);
      s.bbox_max = s.bbox_max.cwiseMax(p);
    }
    max_z = std::max(max_z, tree.end(n).z());
  }
  s.height_m = max_z - tree.start(0).z();
  return s;
}

}  // namespace fspm
