#include "graphics/tree_mesher.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "fspm/error.hpp"
#include "fspm/finite_geometry.hpp"
#include "fspm/memory_budget.hpp"
#include "fspm/name_table.hpp"
#include "fspm/tree_traversal.hpp"
#include "graphics/bspline_refinement.hpp"
#include "graphics/parallel_transport.hpp"

namespace fspm::graphics {
std::string_view junction_mode_name(JunctionMode mode) { return kJunctionModeNames.name(mode); }

JunctionMode junction_mode_from_name(std::string_view name) {
  return kJunctionModeNames.from_name(name);
}

void MeshOptions::validate() const {
  if (!(edge_length_m > 0.0)) throw ValueError("mesh: edge_length_m must be > 0");
  if (min_sides < 3) throw ValueError("mesh: min_sides must be >= 3");
  if (max_sides < min_sides) throw ValueError("mesh: max_sides must be >= min_sides");
  if (!(min_radius_m > 0.0)) throw ValueError("mesh: min_radius_m must be > 0");
  if (!(lod_distance_m > 0.0)) throw ValueError("mesh: lod_distance_m must be > 0");
  if (!(leaf_width_ratio > 0.0)) throw ValueError("mesh: leaf_width_ratio must be > 0");
  if (leaf_bend_segments < 1) throw ValueError("mesh: leaf_bend_segments must be >= 1");
  if (std::isnan(max_birth_time)) throw ValueError("mesh: max_birth_time must be a number");
  if (leaves) foliage.validate();
  if (axis_subdivisions < 1 || axis_subdivisions > kMaxAxisSubdivisions) {
    throw ValueError("mesh: axis_subdivisions must be 1 to " +
                     std::to_string(kMaxAxisSubdivisions) + ", got " +
                     std::to_string(axis_subdivisions));
  }
  if (axis_subdivisions > 1 && junctions == JunctionMode::kContinuous) {
    throw ValueError(
        "mesh: axis_subdivisions > 1 (B-spline axis refinement) needs separate junctions "
        "(continuous tubes keep "
        "their joints for the laterals' holes)");
  }
}

namespace {

constexpr double kMinSegmentM = 1e-9;
constexpr double kTwoPi = 6.283185307179586;

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

// Nodes born after max_birth_time drop out with their subtrees; sets the plan's reference time
// (the latest kept birth) and says whether every node is a kept internode.
std::vector<char> kept_nodes(const TreeGraph& tree, const MeshOptions& options, Plan& plan,
                             bool& all_internodes) {
  const std::size_t n = tree.size();
  std::vector<char> kept(n);
  all_internodes = true;
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
  return kept;
}

// Chains run over internodes only: organs hanging on a metamer must not cut its axis into
// pieces, so with organs present the chains come from the internode-only forest. `nearest` gets
// the nearest kept internode at or above each node.
std::vector<std::vector<NodeId>> internode_chains(const TreeGraph& tree,
                                                  const std::vector<char>& kept,
                                                  bool all_internodes,
                                                  std::vector<NodeId>& nearest) {
  const std::size_t n = tree.size();
  nearest.assign(n, kNoNode);
  if (all_internodes) {
    for (NodeId id = 0; id < n; ++id) nearest[id] = id;
    return chains(tree);
  }
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
  std::vector<std::vector<NodeId>> result = chains(forest);
  for (auto& c : result) {
    for (NodeId& id : c) id = to_tree[id];
  }
  return result;
}

// One tube per chain: its segments of non-zero length, its ring sides and its counts.
void plan_tubes(const TreeGraph& tree, const MeshOptions& options,
                const std::vector<std::vector<NodeId>>& node_chains,
                const std::vector<NodeId>& nearest, Plan& plan) {
  std::size_t total = 0;
  for (const auto& c : node_chains) total += c.size();
  plan.segments.reserve(total);
  plan.chains.reserve(node_chains.size());
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
      const std::size_t walls = cp.count * static_cast<std::size_t>(options.axis_subdivisions);
      plan.counts.vertices += (walls + 1) * (s + 1) + (options.caps ? 2 * (s + 1) : 0);
      plan.counts.triangles += 2 * walls * s + (options.caps ? 2 * s : 0);
      ++plan.counts.tubes;
    }
    plan.chains.push_back(cp);
  }
}

// Leaf blades (leaves with an axis) and clusters (leaves of length 0 with a radius).
void plan_foliage(const TreeGraph& tree, const MeshOptions& options, const std::vector<char>& kept,
                  Plan& plan) {
  Eigen::Vector3d dir;
  double length = 0.0;
  for (NodeId id = 0; id < tree.size(); ++id) {
    if (!kept[id] || tree.kind(id) != OrganKind::kLeaf) continue;
    if (leaf_axis(tree, id, dir, length)) {
      plan.leaves.push_back(id);
    } else if (tree.radius(id) > 0.0) {
      plan.clusters.push_back(id);
    }
  }
  const auto segs = static_cast<std::size_t>(leaf_segments(options));
  const FoliageCounts per_cluster = cluster_counts(options.foliage);
  plan.counts.leaves = plan.leaves.size();
  plan.counts.clusters = plan.clusters.size();
  plan.counts.vertices +=
      plan.leaves.size() * 2 * (segs + 1) + plan.clusters.size() * per_cluster.vertices;
  plan.counts.triangles +=
      plan.leaves.size() * 2 * segs + plan.clusters.size() * per_cluster.triangles;
}

// A nan radius made the ring count a cast of nan ("mesh would have 18446744065119617028
// vertices"), a nan or infinite end a tube left out without a word: the geometry is refused,
// as the tree writers refuse it (fspm/finite_geometry.hpp).
void require_finite(const TreeGraph& tree) {
  for (NodeId id = 0; id < tree.size(); ++id) {
    if (const char* field = non_finite_geometry(tree, id)) {
      throw ValueError("cannot mesh node " + std::to_string(id) + ": its " + field +
                       " is nan or infinite (a mesh holds finite geometry only)");
    }
  }
}

Plan make_plan(const TreeGraph& tree, const MeshOptions& options) {
  options.validate();
  Plan plan;
  if (tree.size() == 0) return plan;
  require_finite(tree);
  bool all_internodes = true;
  const std::vector<char> kept = kept_nodes(tree, options, plan, all_internodes);
  std::vector<NodeId> nearest;
  std::vector<std::vector<NodeId>> node_chains =
      internode_chains(tree, kept, all_internodes, nearest);
  if (!options.bark) node_chains.clear();
  plan_tubes(tree, options, node_chains, nearest, plan);
  if (options.leaves) plan_foliage(tree, options, kept, plan);
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

// Writes the parts of a tree's mesh into the buffers the plan sized: chains of rings, blades and
// clusters, in the plan's order, so vertex and triangle indices follow from the counts.
class BranchMeshWriter {
 public:
  BranchMeshWriter(const TreeGraph& tree, const MeshOptions& options, const Plan& plan,
                   TriangleMesh& mesh)
      : tree_(tree),
        options_(options),
        mesh_(mesh),
        attributes_(tree, mesh, plan.reference_time, options.leaf_bones),
        tip_v_(tree.size()),
        tip_t_(tree.size()),
        has_tip_(tree.size(), 0) {}

  void write_chain(const NodeId* seg, const ChainPlan& cp);
  void write_leaf(NodeId id);
  void write_cluster_of(NodeId id, std::mt19937_64& rng) {
    const std::uint32_t first = v_;
    write_cluster(tree_.start(id), tree_.radius(id), options_.foliage, rng, mesh_, v_, t_);
    attributes_.fill(id, first, v_ - first);
  }

 private:
  void ring_path(const NodeId* seg, std::size_t m);
  void chain_frames(const ChainPlan& cp);
  void write_rings(int s, const RingTable& table);
  void write_walls(std::uint32_t first_ring, std::size_t walls, int s);
  void write_cap(int s, const RingTable& table, std::uint32_t first_ring, int end);

  const TreeGraph& tree_;
  const MeshOptions& options_;
  TriangleMesh& mesh_;
  AttributeFiller attributes_;
  std::uint32_t v_ = 0;  // next vertex
  std::size_t t_ = 0;    // next triangle
  // Frame (V, T) at the tip ring of each chain, so child chains start from their parent's
  // frame transported onto their own tangent: frames stay continuous through the whole tree.
  std::vector<Eigen::Vector3d> tip_v_, tip_t_;
  std::vector<char> has_tip_;
  std::vector<RingTable> tables_;
  // The chain being written: its joints, then its rings' centres, radii and nodes, tangents and
  // transported normals.
  std::vector<Eigen::Vector3d> joints_, centres_;
  std::vector<double> radii_;
  std::vector<NodeId> ring_nodes_;
  std::vector<Eigen::Vector3d> tangents_, normals_v_;
};

void BranchMeshWriter::write_chain(const NodeId* seg, const ChainPlan& cp) {
  const int s = cp.sides;
  const RingTable& table = ring_table(tables_, s);
  ring_path(seg, cp.count);
  chain_frames(cp);
  const std::uint32_t first_ring = v_;
  write_rings(s, table);
  write_walls(first_ring, centres_.size() - 1, s);
  if (options_.caps) {
    for (int end = 0; end < 2; ++end) write_cap(s, table, first_ring, end);
  }
}

// One ring at every joint of the chain's m segments with the radius of the node that starts
// there (the last node's at the tip); with axis_subdivisions s > 1, the joints refined by uniform
// cubic B-splines into s rings per segment (Pirk eq. 6.7, bspline_refinement.hpp), the radii
// interpolated linearly between the joints'.
void BranchMeshWriter::ring_path(const NodeId* seg, std::size_t m) {
  joints_.resize(m + 1);
  std::vector<double>& joint_radii = radii_;
  joint_radii.resize(m + 1);
  for (std::size_t j = 0; j <= m; ++j) {
    const NodeId node = seg[std::min(j, m - 1)];
    joints_[j] = j < m ? tree_.start(node) : tree_.end(node);
    joint_radii[j] = std::max(tree_.radius(node), options_.min_radius_m);
  }
  const auto s = static_cast<std::size_t>(options_.axis_subdivisions);
  ring_nodes_.resize(m * s + 1);
  for (std::size_t i = 0; i <= m * s; ++i) ring_nodes_[i] = seg[std::min(i / s, m - 1)];
  if (s == 1) {
    centres_ = joints_;
    return;
  }
  centres_ = refine_chain(joints_, static_cast<int>(s));
  std::vector<double> refined(m * s + 1);
  for (std::size_t i = 0; i <= m * s; ++i) {
    const std::size_t j = std::min(i / s, m - 1);
    const double t = static_cast<double>(i - j * s) / static_cast<double>(s);
    refined[i] = (1.0 - t) * joint_radii[j] + t * joint_radii[j + 1];
  }
  radii_ = std::move(refined);
}

void BranchMeshWriter::chain_frames(const ChainPlan& cp) {
  // Ring tangents: the directions of the first and last pieces at the ends, bisectors between.
  const std::size_t m = centres_.size() - 1;
  tangents_.resize(m + 1);
  tangents_[0] = (centres_[1] - centres_[0]).normalized();
  for (std::size_t j = 1; j < m; ++j) {
    const Eigen::Vector3d a = (centres_[j] - centres_[j - 1]).normalized();
    const Eigen::Vector3d b = (centres_[j + 1] - centres_[j]).normalized();
    const Eigen::Vector3d bis = a + b;
    tangents_[j] = bis.norm() > 1e-9 ? bis.normalized() : b;
  }
  tangents_[m] = (centres_[m] - centres_[m - 1]).normalized();
  Eigen::Vector3d v0;
  if (cp.attach != kNoNode && has_tip_[cp.attach]) {
    v0 = transport(tip_v_[cp.attach], tip_t_[cp.attach], tangents_[0]);
  } else {
    v0 = any_perpendicular(tangents_[0]);
  }
  normals_v_ = parallel_transport_normals(tangents_, v0);  // Pirk Algorithm 1
  tip_v_[cp.last] = normals_v_[m];
  tip_t_[cp.last] = tangents_[m];
  has_tip_[cp.last] = 1;
}

void BranchMeshWriter::write_rings(int s, const RingTable& table) {
  const double v_scale = 1.0 / (kTwoPi * radii_[0]);  // square texels on the bark
  double along = 0.0;
  for (std::size_t j = 0; j < centres_.size(); ++j) {
    if (j > 0) along += (centres_[j] - centres_[j - 1]).norm();
    const Eigen::Vector3f c = centres_[j].cast<float>();
    const Eigen::Vector3f vv = normals_v_[j].cast<float>();
    const Eigen::Vector3f ww = tangents_[j].cross(normals_v_[j]).cast<float>();
    const auto rf = static_cast<float>(radii_[j]);
    const auto vcoord = static_cast<float>(along * v_scale);
    for (int k = 0; k <= s; ++k) {
      const Eigen::Vector3f dir = table.cos[k] * vv + table.sin[k] * ww;
      mesh_.positions[v_ + k] = c + rf * dir;
      mesh_.normals[v_ + k] = dir;
      mesh_.uvs[v_ + k] = {static_cast<float>(k) / static_cast<float>(s), vcoord};
    }
    attributes_.fill(ring_nodes_[j], v_, s + 1);
    v_ += s + 1;
  }
}

void BranchMeshWriter::write_walls(std::uint32_t first_ring, std::size_t walls, int s) {
  // Side walls: (a, b, d) and (a, d, c) face outwards for W = T x V.
  for (std::size_t j = 0; j < walls; ++j) {
    const std::uint32_t r0 = first_ring + static_cast<std::uint32_t>(j * (s + 1));
    const std::uint32_t r1 = r0 + s + 1;
    for (int k = 0; k < s; ++k) {
      const std::uint32_t a = r0 + k, b = r0 + k + 1, c = r1 + k, d = r1 + k + 1;
      mesh_.triangles[t_++] = {a, b, d};
      mesh_.triangles[t_++] = {a, d, c};
    }
  }
}

void BranchMeshWriter::write_cap(int s, const RingTable& table, std::uint32_t first_ring, int end) {
  const std::size_t last = centres_.size() - 1;
  const std::uint32_t ring =
      end == 0 ? first_ring : first_ring + static_cast<std::uint32_t>(last * (s + 1));
  const NodeId node = end == 0 ? ring_nodes_.front() : ring_nodes_.back();
  const Eigen::Vector3d center = end == 0 ? centres_.front() : centres_.back();
  const Eigen::Vector3f n = (end == 0 ? -tangents_[0] : tangents_[last]).cast<float>().normalized();
  const std::uint32_t hub = v_;
  mesh_.positions[hub] = center.cast<float>();
  mesh_.normals[hub] = n;
  mesh_.uvs[hub] = {0.5f, 0.5f};
  for (int k = 0; k < s; ++k) {
    mesh_.positions[hub + 1 + k] = mesh_.positions[ring + k];
    mesh_.normals[hub + 1 + k] = n;
    mesh_.uvs[hub + 1 + k] = {0.5f + 0.5f * table.cos[k], 0.5f + 0.5f * table.sin[k]};
  }
  attributes_.fill(node, hub, s + 1);
  for (int k = 0; k < s; ++k) {
    const std::uint32_t a = hub + 1 + k;
    const std::uint32_t b = hub + 1 + (k + 1) % s;
    mesh_.triangles[t_++] =
        end == 0 ? TriangleMesh::Triangle{hub, b, a} : TriangleMesh::Triangle{hub, a, b};
  }
  v_ += s + 1;
}

void BranchMeshWriter::write_leaf(NodeId id) {
  const int segs = leaf_segments(options_);
  const Eigen::Vector3d down(0.0, 0.0, -1.0);
  Eigen::Vector3d d;
  double length = 0.0;
  leaf_axis(tree_, id, d, length);
  Eigen::Vector3d side = d.cross(Eigen::Vector3d::UnitZ());
  if (side.norm() < 1e-9) side = d.cross(Eigen::Vector3d::UnitX());
  side.normalize();
  const Eigen::Vector3d face = side.cross(d);  // blade normal for counter-clockwise quads
  // Droop towards the ground, perpendicular to the blade axis (Jaeger 3.1.3 bent leaves).
  Eigen::Vector3d droop = down - down.dot(d) * d;
  droop = droop.norm() > 1e-9 ? droop.normalized() : Eigen::Vector3d(-face);
  const double half_width = 0.5 * options_.leaf_width_ratio * length;
  const std::uint32_t first = v_;
  for (int i = 0; i <= segs; ++i) {
    const double u = static_cast<double>(i) / segs;
    const Eigen::Vector3d center =
        tree_.start(id) + u * length * d + options_.leaf_bend * length * u * u * droop;
    const Eigen::Vector3d axis_tangent = d + 2.0 * options_.leaf_bend * u * droop;
    const Eigen::Vector3f n = side.cross(axis_tangent).normalized().cast<float>();
    mesh_.positions[v_] = (center - half_width * side).cast<float>();
    mesh_.positions[v_ + 1] = (center + half_width * side).cast<float>();
    mesh_.normals[v_] = n;
    mesh_.normals[v_ + 1] = n;
    mesh_.uvs[v_] = {0.0f, static_cast<float>(u)};
    mesh_.uvs[v_ + 1] = {1.0f, static_cast<float>(u)};
    v_ += 2;
  }
  attributes_.fill(id, first, v_ - first);
  for (int i = 0; i < segs; ++i) {
    const std::uint32_t a = first + 2 * i, b = a + 1, c = a + 3, d2 = a + 2;
    mesh_.materials[t_] = Material::kLeaf;
    mesh_.triangles[t_++] = {a, b, c};
    mesh_.materials[t_] = Material::kLeaf;
    mesh_.triangles[t_++] = {a, c, d2};
  }
}

}  // namespace

MeshCounts count_mesh(const TreeGraph& tree, const MeshOptions& options) {
  options.validate();
  if (options.junctions == JunctionMode::kContinuous) {
    const TriangleMesh mesh = mesh_tree_continuous(tree, options);
    const MeshCounts organs = make_plan(tree, options).counts;
    return {mesh.vertex_count(), mesh.triangle_count(), 0, organs.leaves, organs.clusters};
  }
  return make_plan(tree, options).counts;
}

TriangleMesh mesh_tree(const TreeGraph& tree, const MeshOptions& options) {
  options.validate();
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
  BranchMeshWriter writer(tree, options, plan, mesh);
  for (const ChainPlan& cp : plan.chains) {
    if (cp.count > 0) writer.write_chain(plan.segments.data() + cp.first, cp);
  }
  for (const NodeId id : plan.leaves) writer.write_leaf(id);
  std::mt19937_64 rng(options.foliage_seed);
  for (const NodeId id : plan.clusters) writer.write_cluster_of(id, rng);
  return mesh;
}

}  // namespace fspm::graphics
