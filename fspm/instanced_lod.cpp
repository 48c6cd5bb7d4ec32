#include "fspm/instanced_lod.hpp"

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "fspm/error.hpp"
#include "fspm/saturating.hpp"

namespace fspm {
namespace {

constexpr double kCosineTolerance = 1e-9;
constexpr std::uint32_t kNoPrototypeIndex = 0xFFFFFFFFu;

// Two points are one junction when they agree to 1e-9 of their distance from the origin (and
// 1e-9 absolutely near it): transforms of integer coordinates up to 10^9 stay exact enough.
bool same_point(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return (a - b).norm() <= 1e-9 * (1.0 + std::max(a.norm(), b.norm()));
}

// Whether p is the end point of internode x or on its surface there (within its radius).
bool at_joint(const Eigen::Vector3d& p, const NodeData& x) {
  return same_point(p, x.end) || (p - x.end).norm() <= x.radius * (1.0 + 1e-9);
}

// A reduced prototype being assembled: its nodes (parents before children), their user
// attributes (one column per name of the whole tree) and the substructures it still places.
struct Draft {
  std::vector<NodeData> nodes;
  std::vector<NodeId> parent;
  std::vector<std::vector<double>> attributes;  // [attribute][node]
  std::vector<InstancedTree::Child> children;

  NodeId add(NodeId at, const NodeData& d) {
    nodes.push_back(d);
    parent.push_back(at);
    for (auto& column : attributes) column.push_back(0.0);
    return static_cast<NodeId>(nodes.size() - 1);
  }
};

// Merges collinear internode chains of a draft (LevelOfDetail::merge_collinear). Returns, per
// node, the node it was merged into (itself when kept). Nodes are visited parents first, so a
// chain of any length folds into its first internode.
std::vector<NodeId> merge_collinear(Draft& d) {
  const std::size_t n = d.nodes.size();
  std::vector<NodeId> into(n);
  for (NodeId i = 0; i < n; ++i) into[i] = i;
  std::vector<std::vector<NodeId>> kids(n);
  for (NodeId i = 1; i < n; ++i) {
    if (d.parent[i] != kNoNode) kids[d.parent[i]].push_back(i);
  }
  std::vector<std::uint32_t> placed_at(n, 0);
  std::vector<Eigen::Vector3d> loose;  // bases of substructures that hang from no node here
  for (const auto& c : d.children) {
    if (c.attach != kNoNode) {
      ++placed_at[c.attach];
    } else {
      loose.push_back(c.translation);
    }
  }
  const auto mergeable = [&](NodeId a, NodeId b) {
    const NodeData& x = d.nodes[a];
    const NodeData& y = d.nodes[b];
    if (x.kind != OrganKind::kInternode || y.kind != OrganKind::kInternode) return false;
    if (x.physiological_age != y.physiological_age || x.order != y.order) return false;
    if (x.direction.dot(y.direction) < 1.0 - kCosineTolerance) return false;
    if (!same_point(y.start, x.end) || placed_at[a] > 0) return false;
    for (const auto& column : d.attributes) {
      if (column[a] != column[b]) return false;
    }
    for (const NodeId c : kids[a]) {
      // A child grows at the joint when it starts there or on the axis surface around it
      // (leaves pushed to the surface, Jaeger 3.1.3).
      if (c != b && into[c] == c && at_joint(d.nodes[c].start, x)) return false;
    }
    for (const auto& t : loose) {
      if (same_point(t, x.end)) return false;
    }
    return true;
  };
  for (NodeId b = 1; b < n; ++b) {
    if (d.parent[b] == kNoNode) continue;
    const NodeId a = into[d.parent[b]];
    if (!mergeable(a, b)) continue;
    NodeData& x = d.nodes[a];
    const NodeData& y = d.nodes[b];
    const double length = x.length + y.length;
    if (length > 0.0) x.radius = (x.radius * x.length + y.radius * y.length) / length;
    x.length = length;
    x.end = y.end;
    into[b] = a;
    placed_at[a] += placed_at[b];
    kids[a].insert(kids[a].end(), kids[b].begin(), kids[b].end());
    kids[b].clear();
  }
  return into;
}

// The prototypes reachable from the root, renumbered in the order met: substructures drawn
// in their referrers are not meshed again.
InstancedTree reachable(InstancedTree tree) {
  std::vector<std::uint32_t> index(tree.prototypes.size(), kNoPrototypeIndex);
  std::vector<std::uint32_t> order{0};
  index[0] = 0;
  for (std::size_t head = 0; head < order.size(); ++head) {
    for (auto& c : tree.prototypes[order[head]].children) {
      if (index[c.prototype] == kNoPrototypeIndex) {
        index[c.prototype] = static_cast<std::uint32_t>(order.size());
        order.push_back(c.prototype);
      }
      c.prototype = index[c.prototype];
    }
  }
  InstancedTree out;
  out.prototypes.reserve(order.size());
  for (const std::uint32_t p : order) out.prototypes.push_back(std::move(tree.prototypes[p]));
  return out;
}

class Reducer {
 public:
  Reducer(const InstancedTree& tree, const LevelOfDetail& lod) : tree_(tree), lod_(lod) {
    std::set<std::string> names;
    for (const auto& p : tree.prototypes) {
      for (const auto& name : p.geometry.attribute_names()) names.insert(name);
    }
    names_.assign(names.begin(), names.end());
  }

  InstancedTree run() {
    if (tree_.prototypes.empty()) return {};
    reduce(0, lod_.max_order);
    return reachable(std::move(out_));
  }

 private:
  // The reduced form of `prototype` when `budget` more orders may be drawn; built once.
  std::uint32_t reduce(std::uint32_t prototype, double budget) {
    const auto key = std::make_pair(prototype, budget);
    if (const auto it = memo_.find(key); it != memo_.end()) return it->second;
    const auto index = static_cast<std::uint32_t>(out_.prototypes.size());
    memo_.emplace(key, index);
    out_.prototypes.emplace_back();
    Draft d;
    d.attributes.resize(names_.size());
    const std::vector<NodeId> kept = copy_own_nodes(tree_.prototypes[prototype], budget, d);
    // Copied: reduce() below appends to the tree being read.
    const std::vector<InstancedTree::Child> children = tree_.prototypes[prototype].children;
    for (const auto& c : children) {
      if (c.order > budget) continue;
      const NodeId attach = c.attach == kNoNode ? kNoNode : kept[c.attach];
      if (c.attach != kNoNode && attach == kNoNode) continue;
      const std::uint32_t r = reduce(c.prototype, budget - c.order);
      const InstancedTree::Prototype& q = out_.prototypes[r];
      if (q.geometry.empty() && q.children.empty()) continue;  // draws nothing
      // Inlined into a referrer with no node yet, it would become the base every later node
      // and substructure hangs from: only when nothing was placed before it (else a branch
      // drawn after the first piece of an axis would be the root of that axis).
      const bool becomes_base = attach == kNoNode && d.nodes.empty() && !d.children.empty();
      if (q.geometry.size() == 1 && q.children.empty() && !becomes_base) {
        inline_node(q.geometry, c, attach, d);
      } else {
        InstancedTree::Child placed = c;
        placed.prototype = r;
        placed.attach = attach;
        d.children.push_back(placed);
      }
    }
    out_.prototypes[index] = finish(d);
    return index;
  }

  // Nodes of the prototype within the order budget (a node left out takes its subtree);
  // returns the map from the prototype's nodes to the draft's (kNoNode: left out).
  std::vector<NodeId> copy_own_nodes(const InstancedTree::Prototype& p, double budget,
                                     Draft& d) const {
    const TreeGraph& g = p.geometry;
    std::vector<NodeId> kept(g.size(), kNoNode);
    std::vector<std::span<const double>> columns;
    for (const auto& name : names_) {
      columns.push_back(g.has_attribute(name) ? g.attribute(name) : std::span<const double>());
    }
    for (NodeId n = 0; n < g.size(); ++n) {
      const NodeId parent = g.parent(n) == kNoNode ? kNoNode : kept[g.parent(n)];
      if (static_cast<double>(g.order(n)) > budget) continue;
      if (g.parent(n) != kNoNode && parent == kNoNode) continue;
      kept[n] = d.add(parent, g.data(n));
      for (std::size_t a = 0; a < columns.size(); ++a) {
        if (!columns[a].empty()) d.attributes[a].back() = columns[a][n];
      }
    }
    return kept;
  }

  // A substructure reduced to one node, drawn in its referrer: placed by the child's transform,
  // hanging from its attach node, or from the referrer's first node (its base when it has none).
  void inline_node(const TreeGraph& g, const InstancedTree::Child& c, NodeId attach,
                   Draft& d) const {
    NodeData x = g.data(0);
    x.start = c.rotation * x.start + c.translation;
    x.end = c.rotation * x.end + c.translation;
    x.direction = c.rotation * x.direction;
    x.order = static_cast<std::uint16_t>(x.order + c.order);
    const NodeId at = attach != kNoNode ? attach : (d.nodes.empty() ? kNoNode : NodeId{0});
    d.add(at, x);
    for (std::size_t a = 0; a < names_.size(); ++a) {
      if (g.has_attribute(names_[a])) d.attributes[a].back() = g.attribute(names_[a])[0];
    }
  }

  InstancedTree::Prototype finish(Draft& d) const {
    std::vector<NodeId> into(d.nodes.size());
    for (NodeId i = 0; i < into.size(); ++i) into[i] = i;
    if (lod_.merge_collinear) into = merge_collinear(d);
    InstancedTree::Prototype p;
    for (const auto& name : names_) p.geometry.add_attribute(name);
    std::vector<NodeId> id(d.nodes.size(), kNoNode);
    for (NodeId i = 0; i < d.nodes.size(); ++i) {
      if (into[i] != i) continue;
      const NodeId parent = d.parent[i] == kNoNode ? kNoNode : id[into[d.parent[i]]];
      id[i] = p.geometry.add_node(parent, d.nodes[i]);
      for (std::size_t a = 0; a < names_.size(); ++a) {
        p.geometry.attribute(names_[a])[id[i]] = d.attributes[a][i];
      }
    }
    for (auto c : d.children) {
      if (c.attach != kNoNode) c.attach = id[into[c.attach]];
      p.children.push_back(c);
    }
    return p;
  }

  const InstancedTree& tree_;
  LevelOfDetail lod_;
  std::vector<std::string> names_;
  std::map<std::pair<std::uint32_t, double>, std::uint32_t> memo_;
  InstancedTree out_;
};

}  // namespace

InstancedTree reduce_instanced_tree(const InstancedTree& tree, const LevelOfDetail& lod) {
  check_instanced_tree(tree);
  return Reducer(tree, lod).run();
}

InstancedCounts count_instanced_tree(const InstancedTree& tree) {
  const std::size_t n = tree.prototypes.size();
  if (n == 0) return {};
  check_instanced_tree(tree);
  // Depth first over the prototype DAG, totals after all children; 1 = on the path (a cycle).
  std::vector<InstancedCounts> total(n);
  std::vector<std::uint8_t> state(n, 0);  // 0 new, 1 open, 2 done
  std::vector<std::pair<std::uint32_t, std::size_t>> stack{{0, 0}};
  state[0] = 1;
  while (!stack.empty()) {
    auto& [p, next] = stack.back();
    const auto& proto = tree.prototypes[p];
    if (next < proto.children.size()) {
      const std::uint32_t c = proto.children[next++].prototype;
      if (state[c] == 1) throw ValueError("instanced tree: a prototype contains itself");
      if (state[c] == 0) {
        state[c] = 1;
        stack.push_back({c, 0});
      }
      continue;
    }
    InstancedCounts t{proto.geometry.size(), 1};
    for (const auto& c : proto.children) {
      t.nodes = add_saturating(t.nodes, total[c.prototype].nodes);
      t.occurrences = add_saturating(t.occurrences, total[c.prototype].occurrences);
    }
    total[p] = t;
    state[p] = 2;
    stack.pop_back();
  }
  return total[0];
}

TreeGraph reduce_tree(const TreeGraph& tree, const LevelOfDetail& lod) {
  InstancedTree single;
  single.prototypes.push_back({tree, {}});
  InstancedTree reduced = reduce_instanced_tree(single, lod);
  return std::move(reduced.prototypes[0].geometry);
}

}  // namespace fspm
