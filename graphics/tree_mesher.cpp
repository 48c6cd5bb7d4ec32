#include "graphics/tree_mesher.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"
#include "fspm/tree_traversal.hpp"
#include "graphics/parallel_transport.hpp"

namespace fspm::graphics {
namespace {

constexpr double kMinSegmentM = 1e-9;
constexpr double kTwoPi = 6.283185307179586;

void validate(const MeshOptions& o) {
  if (!(o.edge_length_m > 0.0)) throw ValueError("edge length must be > 0 m");
  if (o.min_sides < 3) throw ValueError("min_sides must be >= 3");
  if (o.max_sides < o.min_sides) throw ValueError("max_sides must be >= min_sides");
  if (!(o.min_radius_m > 0.0)) throw ValueError("min_radius_m must be > 0");
  if (!(o.lod_distance_m > 0.0)) throw ValueError("lod_distance_m must be > 0");
  if (!(o.leaf_width_ratio > 0.0)) throw ValueError("leaf_width_ratio must be > 0");
  if (o.leaf_bend_segments < 1) throw ValueError("leaf_bend_segments must be >= 1");
  if (std::isnan(o.max_birth_time)) throw ValueError("max_birth_time must be a number");
  if (o.leaves) validate_foliage(o.foliage);
}

struct ChainPlan {
  std::size_t first = 0;  // into Plan::segments
  std::size_t count = 0;  // segments (nodes of non-zero length)
  int sides = 0;
  NodeId attach = kNoNode;  // internode the chain grows from (its frame starts the chain)
  NodeId last = kNoNode;    // last internode of the chain (children chains attach here)
};

struct Plan {
  std::vector<NodeId> segments;
  std::vector<ChainPlan> chains;
  std::vector<NodeId> leaves;
  std::vector<NodeId> clusters;  // leaf nodes of length 0 with a radius: foliage
  double reference_time = 0.0;
  MeshCounts counts;
};

Eigen::Vector3d segment_vector(const TreeGraph& tree, NodeId n) {
  return tree.end(n) - tree.start(n);
}

// Leaf blade axis: explicit direction and length when given, else the node's segment.
bool leaf_axis(const TreeGraph& tree, NodeId n, Eigen::Vector3d& dir, double& length) {
  if (tree.length(n) > kMinSegmentM && tree.direction(n).norm() > 1e-12) {
    dir = tree.direction(n).normalized();
    length = tree.length(n);
    return true;
  }
  const Eigen::Vector3d d = segment_vector(tree, n);
  length = d.norm();
  if (length <= kMinSegmentM) return false;
  dir = d / length;
  return true;
}

int leaf_segments(const MeshOptions& o) { return o.leaf_bend > 0.0 ? o.leaf_bend_segments : 1; }

Plan make_plan(const TreeGraph& tree, const MeshOptions& options) {
  validate(options);
  Plan plan;
  const std::size_t n = tree.size();
  if (n == 0) return plan;

  // Nodes born after max_birth_time drop out with their subtrees.
  std::vector<char> kept(n);
  bool all_internodes = true;
  double latest_birth = -std::numeric_limits<double>::infinity();
  for (NodeId id = 0; id < n; ++id) {
    const NodeId p = tree.parent(id);
    kept[id] = tree.birth_time(id) <= options.max_birth_time && (p == kNoNode || kept[p]);
    if (kept[id]) latest_birth = std::max(latest_birth, tree.birth_time(id));
    all_internodes = all_internodes && kept[id] && tree.kind(id) == OrganKind::kInternode;
  }
  plan.reference_time = std::isinf(options.max_birth_time)
                            ? (std::isinf(latest_birth) ? 0.0 : latest_birth)
                            : options.max_birth_time;

  // Chains run over internodes only: organs hanging on a metamer must not cut its axis into
  // pieces, so with organs present the chains come from the internode-only forest.
  std::vector<std::vector<NodeId>> node_chains;
  std::vector<NodeId> nearest(n, kNoNode);  // nearest kept internode at or above each node
  if (all_internodes) {
    node_chains = chains(tree);
    for (NodeId id = 0; id < n; ++id) nearest[id] = id;
  } else {
    TreeGraph forest;
    std::vector<NodeId> to_tree;
    std::vector<NodeId> to_forest(n, kNoNode);
    for (NodeId id = 0; id < n; ++id) {
      const NodeId p = tree.parent(id);
      const NodeId above = p == kNoNode ? kNoNode : nearest[p];
      if (!kept[id] || tree.kind(id) != OrganKind::kInternode) {
        nearest[id] = above;
        continue;
      }
      if (above == kNoNode && !forest.empty()) {
        nearest[id] = kNoNode;  // a second internode root under an organ: not meshable as a tube
        continue;
      }
      nearest[id] = id;
      to_forest[id] = forest.add_node(above == kNoNode ? kNoNode : to_forest[above], NodeData{});
      to_tree.push_back(id);
    }
    node_chains = chains(forest);
    for (auto& c : node_chains) {
      for (NodeId& id : c) id = to_tree[id];
    }
  }

  std::size_t total = 0;
  for (const auto& c : node_chains) total += c.size();
  plan.segments.reserve(total);
  plan.chains.reserve(node_chains.size());
  const int leaf_segs = leaf_segments(options);
  if (!options.bark) node_chains.clear();
  for (const auto& c : node_chains) {
    ChainPlan cp;
    cp.first = plan.segments.size();
    for (NodeId id : c) {
      if (segment_vector(tree, id).norm() > kMinSegmentM) plan.segments.push_back(id);
    }
    cp.count = plan.segments.size() - cp.first;
    cp.last = c.back();
    const NodeId p = tree.parent(c.front());
    cp.attach = p == kNoNode ? kNoNode : nearest[p];
    if (cp.count > 0) {
      const NodeId base = plan.segments[cp.first];
      const double distance =
          options.camera_m ? (tree.start(base) - *options.camera_m).norm() : 0.0;
      cp.sides = sides_for_radius(tree.radius(base), options, distance);
      const auto s = static_cast<std::size_t>(cp.sides);
      plan.counts.vertices += (cp.count + 1) * (s + 1) + (options.caps ? 2 * (s + 1) : 0);
      plan.counts.triangles += 2 * cp.count * s + (options.caps ? 2 * s : 0);
      ++plan.counts.tubes;
    }
    plan.chains.push_back(cp);
  }

  if (options.leaves) {
    Eigen::Vector3d dir;
    double length = 0.0;
    for (NodeId id = 0; id < n; ++id) {
      if (!kept[id] || tree.kind(id) != OrganKind::kLeaf) continue;
      if (leaf_axis(tree, id, dir, length)) {
        plan.leaves.push_back(id);
      } else if (tree.radius(id) > 0.0) {
        plan.clusters.push_back(id);
      }
    }
    const auto segs = static_cast<std::size_t>(leaf_segs);
    const FoliageCounts per_cluster = cluster_counts(options.foliage);
    plan.counts.leaves = plan.leaves.size();
    plan.counts.clusters = plan.clusters.size();
    plan.counts.vertices +=
        plan.leaves.size() * 2 * (segs + 1) + plan.clusters.size() * per_cluster.vertices;
    plan.counts.triangles +=
        plan.leaves.size() * 2 * segs + plan.clusters.size() * per_cluster.triangles;
  }
  if (plan.counts.vertices > std::numeric_limits<std::uint32_t>::max()) {
    throw ValueError("mesh would have " + std::to_string(plan.counts.vertices) +
                     " vertices, more than 32-bit indices allow; raise the edge length");
  }
  return plan;
}

// Writes the per-vertex attribute values of one node over a run of vertices.
class AttributeFiller {
 public:
  AttributeFiller(const TreeGraph& tree, TriangleMesh& mesh, double reference_time, bool bones)
      : tree_(tree), reference_time_(reference_time), bones_(bones) {
    const std::size_t nv = mesh.positions.size();
    auto column = [&](const std::string& name) {
      mesh.attributes.push_back({name, std::vector<float>(nv)});
    };
    column(kAttributeAge);
    column(kAttributeBirthTime);
    column(kAttributeOrder);
    column(kAttributePhysiologicalAge);
    for (const std::string& name : tree.attribute_names()) {
      column(name);
      user_.push_back(tree.attribute(name));
    }
    if (bones_) {
      column("bone0");
      column("weight0");
    }
    for (auto& a : mesh.attributes) columns_.push_back(a.values.data());
    values_.resize(columns_.size());
  }

  void fill(NodeId node, std::size_t first_vertex, std::size_t count) {
    const double birth = tree_.birth_time(node);
    values_[0] = static_cast<float>(reference_time_ - birth);
    values_[1] = static_cast<float>(birth);
    values_[2] = static_cast<float>(tree_.order(node));
    values_[3] = static_cast<float>(tree_.physiological_age(node));
    for (std::size_t i = 0; i < user_.size(); ++i) {
      values_[4 + i] = static_cast<float>(user_[i][node]);
    }
    if (bones_) {
      // A leaf or cluster moves with the nearest internode at or above it (1.0, Reynolds' end
      // weight); none: no bone.
      NodeId bone = node;
      while (bone != kNoNode && tree_.kind(bone) != OrganKind::kInternode) {
        bone = tree_.parent(bone);
      }
      values_[4 + user_.size()] = bone == kNoNode ? -1.0f : static_cast<float>(bone);
      values_[5 + user_.size()] = bone == kNoNode ? 0.0f : 1.0f;
    }
    for (std::size_t c = 0; c < columns_.size(); ++c) {
      std::fill_n(columns_[c] + first_vertex, count, values_[c]);
    }
  }

 private:
  const TreeGraph& tree_;
  double reference_time_;
  bool bones_;
  std::vector<std::span<const double>> user_;
  std::vector<float*> columns_;
  std::vector<float> values_;
};

struct RingTable {
  std::vector<float> cos, sin;
};

const RingTable& ring_table(std::vector<RingTable>& tables, int sides) {
  if (tables.size() <= static_cast<std::size_t>(sides)) tables.resize(sides + 1);
  RingTable& t = tables[sides];
  if (t.cos.empty()) {
    for (int k = 0; k <= sides; ++k) {
      const double a = kTwoPi * (k == sides ? 0 : k) / sides;  // the seam repeats angle 0 exactly
      t.cos.push_back(static_cast<float>(std::cos(a)));
      t.sin.push_back(static_cast<float>(std::sin(a)));
    }
  }
  return t;
}

}  // namespace

int sides_for_radius(double radius_m, const MeshOptions& options, double distance_m) {
  const double r = std::max(radius_m, options.min_radius_m);
  const double edge = options.edge_length_m * std::max(1.0, distance_m / options.lod_distance_m);
  const double wanted = std::ceil(kTwoPi * r / edge);
  return static_cast<int>(std::clamp(wanted, static_cast<double>(options.min_sides),
                                     static_cast<double>(options.max_sides)));
}

namespace {

// Bytes of the mesh mesh_tree fills: the four node columns of AttributeFiller and the tree's own
// attributes per vertex.
double mesh_bytes(const MeshCounts& counts, std::size_t user_attributes) {
  return TriangleMesh::bytes_for(counts.vertices, counts.triangles, 4 + user_attributes);
}

}  // namespace

MeshCounts count_mesh(const TreeGraph& tree, const MeshOptions& options) {
  if (options.junctions == JunctionMode::kContinuous) {
    const TriangleMesh mesh = mesh_tree_continuous(tree, options);
    const MeshCounts organs = make_plan(tree, options).counts;
    return {mesh.vertex_count(), mesh.triangle_count(), 0, organs.leaves, organs.clusters};
  }
  return make_plan(tree, options).counts;
}

TriangleMesh mesh_tree(const TreeGraph& tree, const MeshOptions& options) {
  if (options.junctions == JunctionMode::kContinuous) return mesh_tree_continuous(tree, options);
  const Plan plan = make_plan(tree, options);
  check_memory(mesh_bytes(plan.counts, tree.attribute_names().size()),
               "a mesh of " + std::to_string(plan.counts.triangles) + " triangles");
  TriangleMesh mesh;
  mesh.positions.resize(plan.counts.vertices);
  mesh.normals.resize(plan.counts.vertices);
  mesh.uvs.resize(plan.counts.vertices);
  mesh.triangles.resize(plan.counts.triangles);
  mesh.materials.resize(plan.counts.triangles, Material::kBark);
  AttributeFiller attributes(tree, mesh, plan.reference_time, options.leaf_bones);

  Eigen::Vector3f* pos = mesh.positions.data();
  Eigen::Vector3f* nor = mesh.normals.data();
  Eigen::Vector2f* uv = mesh.uvs.data();
  TriangleMesh::Triangle* tri = mesh.triangles.data();
  std::uint32_t v = 0;  // next vertex
  std::size_t t = 0;    // next triangle

  // Frame (V, T) at the tip ring of each chain, so child chains start from their parent's
  // frame transported onto their own tangent: frames stay continuous through the whole tree.
  std::vector<Eigen::Vector3d> tip_v(tree.size()), tip_t(tree.size());
  std::vector<char> has_tip(tree.size(), 0);
  std::vector<RingTable> tables;
  std::vector<Eigen::Vector3d> tangents, normals_v;

  for (const ChainPlan& cp : plan.chains) {
    if (cp.count == 0) continue;
    const NodeId* seg = plan.segments.data() + cp.first;
    const std::size_t m = cp.count;
    const int s = cp.sides;
    const RingTable& table = ring_table(tables, s);

    // Ring tangents: segment directions at the ends, bisectors at the joints.
    tangents.resize(m + 1);
    tangents[0] = segment_vector(tree, seg[0]).normalized();
    for (std::size_t j = 1; j < m; ++j) {
      const Eigen::Vector3d a = segment_vector(tree, seg[j - 1]).normalized();
      const Eigen::Vector3d b = segment_vector(tree, seg[j]).normalized();
      const Eigen::Vector3d bis = a + b;
      tangents[j] = bis.norm() > 1e-9 ? bis.normalized() : b;
    }
    tangents[m] = segment_vector(tree, seg[m - 1]).normalized();
    Eigen::Vector3d v0;
    if (cp.attach != kNoNode && has_tip[cp.attach]) {
      v0 = transport(tip_v[cp.attach], tip_t[cp.attach], tangents[0]);
    } else {
      v0 = any_perpendicular(tangents[0]);
    }
    normals_v = parallel_transport_normals(tangents, v0);  // Pirk Algorithm 1
    tip_v[cp.last] = normals_v[m];
    tip_t[cp.last] = tangents[m];
    has_tip[cp.last] = 1;

    const double base_radius = std::max(tree.radius(seg[0]), options.min_radius_m);
    const double v_scale = 1.0 / (kTwoPi * base_radius);  // square texels on the bark
    double along = 0.0;
    const std::uint32_t first_ring = v;
    for (std::size_t j = 0; j <= m; ++j) {
      const NodeId node = seg[std::min(j, m - 1)];
      const Eigen::Vector3d center = j < m ? tree.start(node) : tree.end(node);
      if (j > 0) along += segment_vector(tree, seg[j - 1]).norm();
      const double r = std::max(tree.radius(node), options.min_radius_m);
      const Eigen::Vector3f c = center.cast<float>();
      const Eigen::Vector3f vv = normals_v[j].cast<float>();
      const Eigen::Vector3f ww = tangents[j].cross(normals_v[j]).cast<float>();
      const auto rf = static_cast<float>(r);
      const auto vcoord = static_cast<float>(along * v_scale);
      for (int k = 0; k <= s; ++k) {
        const Eigen::Vector3f dir = table.cos[k] * vv + table.sin[k] * ww;
        pos[v + k] = c + rf * dir;
        nor[v + k] = dir;
        uv[v + k] = {static_cast<float>(k) / static_cast<float>(s), vcoord};
      }
      attributes.fill(node, v, s + 1);
      v += s + 1;
    }
    // Side walls: (a, b, d) and (a, d, c) face outwards for W = T x V.
    for (std::size_t j = 0; j < m; ++j) {
      const std::uint32_t r0 = first_ring + static_cast<std::uint32_t>(j * (s + 1));
      const std::uint32_t r1 = r0 + s + 1;
      for (int k = 0; k < s; ++k) {
        const std::uint32_t a = r0 + k, b = r0 + k + 1, c = r1 + k, d = r1 + k + 1;
        tri[t++] = {a, b, d};
        tri[t++] = {a, d, c};
      }
    }
    if (options.caps) {
      for (int end = 0; end < 2; ++end) {
        const std::uint32_t ring =
            end == 0 ? first_ring : first_ring + static_cast<std::uint32_t>(m * (s + 1));
        const NodeId node = end == 0 ? seg[0] : seg[m - 1];
        const Eigen::Vector3d center = end == 0 ? tree.start(node) : tree.end(node);
        const Eigen::Vector3f n =
            (end == 0 ? -tangents[0] : tangents[m]).cast<float>().normalized();
        const std::uint32_t hub = v;
        pos[hub] = center.cast<float>();
        nor[hub] = n;
        uv[hub] = {0.5f, 0.5f};
        for (int k = 0; k < s; ++k) {
          pos[hub + 1 + k] = pos[ring + k];
          nor[hub + 1 + k] = n;
          uv[hub + 1 + k] = {0.5f + 0.5f * table.cos[k], 0.5f + 0.5f * table.sin[k]};
        }
        attributes.fill(node, hub, s + 1);
        for (int k = 0; k < s; ++k) {
          const std::uint32_t a = hub + 1 + k;
          const std::uint32_t b = hub + 1 + (k + 1) % s;
          tri[t++] =
              end == 0 ? TriangleMesh::Triangle{hub, b, a} : TriangleMesh::Triangle{hub, a, b};
        }
        v += s + 1;
      }
    }
  }

  if (!plan.leaves.empty()) {
    const int segs = leaf_segments(options);
    const Eigen::Vector3d down(0.0, 0.0, -1.0);
    for (NodeId id : plan.leaves) {
      Eigen::Vector3d d;
      double length = 0.0;
      leaf_axis(tree, id, d, length);
      Eigen::Vector3d side = d.cross(Eigen::Vector3d::UnitZ());
      if (side.norm() < 1e-9) side = d.cross(Eigen::Vector3d::UnitX());
      side.normalize();
      const Eigen::Vector3d face = side.cross(d);  // blade normal for counter-clockwise quads
      // Droop towards the ground, perpendicular to the blade axis (Jaeger 3.1.3 bent leaves).
      Eigen::Vector3d droop = down - down.dot(d) * d;
      droop = droop.norm() > 1e-9 ? droop.normalized() : Eigen::Vector3d(-face);
      const double half_width = 0.5 * options.leaf_width_ratio * length;
      const std::uint32_t first = v;
      for (int i = 0; i <= segs; ++i) {
        const double u = static_cast<double>(i) / segs;
        const Eigen::Vector3d center =
            tree.start(id) + u * length * d + options.leaf_bend * length * u * u * droop;
        const Eigen::Vector3d axis_tangent = d + 2.0 * options.leaf_bend * u * droop;
        const Eigen::Vector3f n = side.cross(axis_tangent).normalized().cast<float>();
        pos[v] = (center - half_width * side).cast<float>();
        pos[v + 1] = (center + half_width * side).cast<float>();
        nor[v] = n;
        nor[v + 1] = n;
        uv[v] = {0.0f, static_cast<float>(u)};
        uv[v + 1] = {1.0f, static_cast<float>(u)};
        v += 2;
      }
      attributes.fill(id, first, v - first);
      for (int i = 0; i < segs; ++i) {
        const std::uint32_t a = first + 2 * i, b = a + 1, c = a + 3, d2 = a + 2;
        mesh.materials[t] = Material::kLeaf;
        tri[t++] = {a, b, c};
        mesh.materials[t] = Material::kLeaf;
        tri[t++] = {a, c, d2};
      }
    }
  }
  std::mt19937_64 rng(options.foliage_seed);
  for (NodeId id : plan.clusters) {
    const std::uint32_t first = v;
    write_cluster(tree.start(id), tree.radius(id), options.foliage, rng, mesh, v, t);
    attributes.fill(id, first, v - first);
  }
  return mesh;
}

}  // namespace fspm::graphics
