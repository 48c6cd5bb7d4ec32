#include "fspm/instanced_tree.hpp"

#include <string>

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"

namespace fspm {
namespace {

// One occurrence of a prototype: where it stands and what its base hangs from.
struct Occurrence {
  std::uint32_t prototype = 0;
  NodeId parent = kNoNode;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  double order = 0.0;
};

// Nodes of the explicit tree, counted occurrence by occurrence; throws past `max_nodes` (or
// past as many occurrences, which only a cycle of empty prototypes reaches).
std::size_t explicit_size(const InstancedTree& tree, std::size_t max_nodes) {
  std::size_t nodes = 0, occurrences = 0;
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const auto& p = tree.prototypes[stack.back()];
    stack.pop_back();
    nodes += p.geometry.size();
    if (nodes > max_nodes || ++occurrences > max_nodes + tree.prototypes.size()) {
      throw ValueError("the explicit tree would exceed " + std::to_string(max_nodes) + " nodes");
    }
    for (const auto& c : p.children) stack.push_back(c.prototype);
  }
  return nodes;
}

// Writes one occurrence's geometry into `out` (transformed, orders offset, attributes copied) and
// returns the occurrences of its children; `map` receives the new id of each prototype node.
void write_occurrence(const InstancedTree& tree, const Occurrence& o, TreeGraph& out,
                      std::vector<NodeId>& map) {
  const TreeGraph& g = tree.prototypes[o.prototype].geometry;
  map.assign(g.size(), kNoNode);
  for (NodeId n = 0; n < g.size(); ++n) {
    NodeData d = g.data(n);
    d.start = o.rotation * d.start + o.translation;
    d.end = o.rotation * d.end + o.translation;
    d.direction = o.rotation * d.direction;
    d.order = static_cast<std::uint16_t>(d.order + o.order);
    NodeId parent = n == 0 ? o.parent : map[g.parent(n)];
    if (parent == kNoNode && !out.empty()) parent = 0;  // one root
    map[n] = out.add_node(parent, d);
  }
  for (const auto& name : g.attribute_names()) {
    const auto from = g.attribute(name);
    const auto to = out.attribute(name);
    for (NodeId n = 0; n < g.size(); ++n) to[map[n]] = from[n];
  }
}

Occurrence child_occurrence(const Occurrence& o, const InstancedTree::Child& c,
                            const std::vector<NodeId>& map) {
  return {c.prototype, c.attach == kNoNode ? o.parent : map[c.attach], o.rotation * c.rotation,
          o.rotation * c.translation + o.translation, o.order + c.order};
}

}  // namespace

TreeGraph expand_instanced_tree(const InstancedTree& tree, std::size_t max_nodes,
                                ExpansionOrder order) {
  TreeGraph out;
  if (tree.prototypes.empty()) return out;
  check_instanced_tree(tree);
  const std::size_t nodes = explicit_size(tree, max_nodes);
  for (const auto& p : tree.prototypes) {
    for (const auto& name : p.geometry.attribute_names()) out.add_attribute(name);
  }
  check_memory(static_cast<double>(nodes) * TreeGraph::bytes_per_node(out.attribute_names().size()),
               "the explicit tree of " + std::to_string(nodes) + " nodes");
  out.reserve(nodes);
  std::vector<NodeId> map;
  if (order == ExpansionOrder::kAxisByAxis) {
    // A FIFO of occurrences: children in order after everything met before them.
    std::vector<Occurrence> queue{Occurrence{}};
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const Occurrence o = queue[head];  // copied: the queue grows below
      write_occurrence(tree, o, out, map);
      for (const auto& c : tree.prototypes[o.prototype].children) {
        queue.push_back(child_occurrence(o, c, map));
      }
    }
    return out;
  }
  // Depth first, children pushed in reverse so they come out in order.
  std::vector<Occurrence> stack{Occurrence{}};
  while (!stack.empty()) {
    const Occurrence o = stack.back();
    stack.pop_back();
    write_occurrence(tree, o, out, map);
    const auto& children = tree.prototypes[o.prototype].children;
    for (std::size_t k = children.size(); k-- > 0;) {
      stack.push_back(child_occurrence(o, children[k], map));
    }
  }
  return out;
}

void check_instanced_tree(const InstancedTree& tree) {
  const std::size_t np = tree.prototypes.size();
  for (const auto& p : tree.prototypes) {
    for (const auto& c : p.children) {
      if (c.prototype >= np) {
        throw ValueError("instanced tree: child refers to prototype " +
                         std::to_string(c.prototype) + " of " + std::to_string(np));
      }
      if (c.attach != kNoNode && c.attach >= p.geometry.size()) {
        throw ValueError("instanced tree: child attached to node " + std::to_string(c.attach) +
                         " of a prototype with " + std::to_string(p.geometry.size()) + " nodes");
      }
    }
  }
}

}  // namespace fspm
