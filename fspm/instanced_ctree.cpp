#include "fspm/instanced_ctree.hpp"

#include <set>
#include <string>
#include <vector>

#include "fspm/error.hpp"
#include "fspm/saturating.hpp"

namespace fspm {
namespace {

// Record ids of the prototypes: the group of prototype p at base[p], its node n at base[p] + 1 + n.
std::vector<RecordId> record_bases(const InstancedTree& tree) {
  std::vector<RecordId> base(tree.prototypes.size());
  std::uint64_t total = 0;
  for (std::size_t p = 0; p < tree.prototypes.size(); ++p) {
    base[p] = static_cast<RecordId>(total);
    total += 1 + tree.prototypes[p].geometry.size();
    if (total >= kNoRecord) {
      throw ValueError("the instanced tree has more than 2^32 - 2 prototypes and nodes");
    }
  }
  return base;
}

RecordGeometry record_geometry(const TreeGraph& g, NodeId n) {
  const NodeData d = g.data(n);
  RecordGeometry r;
  r.kind = d.kind;
  r.order = d.order;
  r.start = d.start;
  r.end = d.end;
  r.direction = d.direction;
  r.length = d.length;
  r.radius = d.radius;
  return r;
}

// Adds one record with its references and their placements, and its geometry.
void add_with_geometry(CompressedTreeGraph& graph, RecordId successor,
                       const std::vector<RecordId>& refs, const std::vector<std::uint32_t>& places,
                       const RecordGeometry& geometry) {
  CompressedRecord record;
  record.successor = successor;
  graph.add_record(record, refs);
  auto& g = graph.geometry;
  g.axillary_placements.insert(g.axillary_placements.end(), places.begin(), places.end());
  g.records.push_back(geometry);
}

// Per-record attribute columns: the union of the prototypes' attributes, 0 where absent (as
// expand_instanced_tree leaves them).
void copy_attributes(const InstancedTree& tree, const std::vector<RecordId>& base,
                     CompressedTreeGraph& graph) {
  std::set<std::string> names;
  for (const auto& p : tree.prototypes) {
    for (const auto& name : p.geometry.attribute_names()) names.insert(name);
  }
  for (const auto& name : names) {
    std::vector<double>& column = graph.geometry.attributes[name];
    column.assign(graph.size(), 0.0);
    for (std::size_t p = 0; p < tree.prototypes.size(); ++p) {
      const TreeGraph& g = tree.prototypes[p].geometry;
      if (!g.has_attribute(name)) continue;
      const auto values = g.attribute(name);
      for (NodeId n = 0; n < g.size(); ++n) column[base[p] + 1 + n] = values[n];
    }
  }
}

}  // namespace

CompressedTreeGraph compress_instanced_tree(const InstancedTree& tree) {
  CompressedTreeGraph graph;
  if (tree.prototypes.empty()) return graph;
  check_instanced_tree(tree);
  const std::vector<RecordId> base = record_bases(tree);
  std::vector<RecordId> refs;
  std::vector<std::uint32_t> places;
  auto place = [&](const InstancedTree::Child& c) {
    graph.geometry.placements.push_back({c.rotation, c.translation, c.order});
    refs.push_back(base[c.prototype]);
    places.push_back(static_cast<std::uint32_t>(graph.geometry.placements.size() - 1));
  };
  RecordGeometry group;
  group.group = true;
  std::vector<std::vector<std::size_t>> placed_at;  // per node of a prototype: its children
  for (std::size_t p = 0; p < tree.prototypes.size(); ++p) {
    const auto& proto = tree.prototypes[p];
    const TreeGraph& g = proto.geometry;
    refs.clear();
    places.clear();
    if (!g.empty()) {
      refs.push_back(base[p] + 1);
      places.push_back(kNoPlacement);
    }
    placed_at.assign(g.size(), {});
    for (std::size_t k = 0; k < proto.children.size(); ++k) {
      const auto& c = proto.children[k];
      if (c.attach == kNoNode) {
        place(c);
      } else {
        placed_at[c.attach].push_back(k);
      }
    }
    add_with_geometry(graph, kNoRecord, refs, places, group);
    for (NodeId n = 0; n < g.size(); ++n) {
      refs.clear();
      places.clear();
      RecordId successor = kNoRecord;
      for (const NodeId child : g.children(n)) {
        if (successor == kNoRecord) {
          successor = base[p] + 1 + child;
        } else {
          refs.push_back(base[p] + 1 + child);
          places.push_back(kNoPlacement);
        }
      }
      for (const std::size_t k : placed_at[n]) place(proto.children[k]);
      add_with_geometry(graph, successor, refs, places, record_geometry(g, n));
    }
  }
  copy_attributes(tree, base, graph);
  graph.set_root(base[0]);
  graph.compute_multiplicities();
  return graph;
}

namespace {

class Instancer {
 public:
  Instancer(const CompressedTreeGraph& graph, const CtreeInstancingOptions& options)
      : graph_(graph), geo_(graph.geometry), options_(options) {}

  InstancedTree run() {
    InstancedTree out;
    prototype_of_.assign(graph_.size(), kNone);
    if (graph_.root() == kNoRecord || !kept(graph_.root())) return out;
    prototype_for(graph_.root());
    for (std::size_t head = 0; head < pending_.size(); ++head) {
      InstancedTree::Prototype p = build(pending_[head]);
      out.prototypes.resize(std::max(out.prototypes.size(), head + 1));
      out.prototypes[head] = std::move(p);
    }
    return out;
  }

 private:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;

  struct Item {
    RecordId record;
    NodeId parent;
    std::uint32_t placement;
  };

  bool kept(RecordId id) const {
    const CompressedRecord& r = graph_.record(id);
    const RecordGeometry& g = geo_.records[id];
    if (r.birth > options_.max_birth) return false;
    if (g.group) return true;
    if (!options_.leaves && g.kind == OrganKind::kLeaf) return false;
    return options_.flowers || g.kind != OrganKind::kFlower;
  }

  std::uint32_t prototype_for(RecordId group) {
    if (prototype_of_[group] == kNone) {
      prototype_of_[group] = static_cast<std::uint32_t>(pending_.size());
      pending_.push_back(group);
    }
    return prototype_of_[group];
  }

  // The successor and the axillaries of `id`, pushed in reverse so they come out in order.
  void push_members(RecordId id, NodeId parent, std::vector<Item>& stack) const {
    const auto ax = graph_.axillaries(id);
    const CompressedRecord& r = graph_.record(id);
    for (std::size_t k = ax.size(); k-- > 0;) {
      stack.push_back({ax[k], parent, geo_.axillary_placements[r.axillary_begin + k]});
    }
    if (r.successor != kNoRecord) stack.push_back({r.successor, parent, kNoPlacement});
  }

  // The organs a group bears in its own frame, and the groups it places.
  InstancedTree::Prototype build(RecordId group) {
    InstancedTree::Prototype p;
    for (const auto& [name, column] : geo_.attributes) p.geometry.add_attribute(name);
    std::vector<Item> stack;
    push_members(group, kNoNode, stack);
    while (!stack.empty()) {
      const Item item = stack.back();
      stack.pop_back();
      if (!kept(item.record)) continue;
      const RecordGeometry& g = geo_.records[item.record];
      if (g.group) {
        InstancedTree::Child c;
        c.prototype = prototype_for(item.record);
        c.attach = item.parent;
        c.order = 0.0;
        if (item.placement != kNoPlacement) {
          const Placement& pl = geo_.placements[item.placement];
          c.rotation = pl.rotation;
          c.translation = pl.translation;
          c.order = pl.order;
        }
        p.children.push_back(c);
        continue;
      }
      const CompressedRecord& r = graph_.record(item.record);
      NodeData d;
      d.start = g.start;
      d.end = g.end;
      d.direction = g.direction;
      d.length = g.length;
      d.radius = g.radius;
      d.birth_time = r.birth;
      d.physiological_age = r.physiological_age;
      d.order = g.order;
      d.kind = g.kind;
      const NodeId n = p.geometry.add_node(item.parent, d);
      for (const auto& [name, column] : geo_.attributes) {
        p.geometry.attribute(name)[n] = column[item.record];
      }
      push_members(item.record, n, stack);
    }
    return p;
  }

  const CompressedTreeGraph& graph_;
  const CtreeGeometry& geo_;
  const CtreeInstancingOptions& options_;
  std::vector<std::uint32_t> prototype_of_;  // per group record
  std::vector<RecordId> pending_;            // group records, in prototype order
};

}  // namespace

InstancedTree instanced_tree_of(const CompressedTreeGraph& graph,
                                const CtreeInstancingOptions& options) {
  if (!graph.has_geometry()) {
    throw ValueError(
        "the compressed tree graph has no turtle geometry: its geometry comes from the "
        "per-physiological-age numbers of GreenLab's reconstruction");
  }
  graph.validate();
  return Instancer(graph, options).run();
}

std::uint64_t geometry_organ_count(const CompressedTreeGraph& graph) {
  std::uint64_t total = 0;
  for (std::size_t i = 0; i < graph.size(); ++i) {
    if (i < graph.geometry.records.size() && graph.geometry.records[i].group) continue;
    total = add_saturating(total, graph.record(static_cast<RecordId>(i)).multiplicity);
  }
  return total;
}

}  // namespace fspm
