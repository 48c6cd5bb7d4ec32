#include "graphics/instanced_mesh.hpp"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "fspm/error.hpp"
#include "fspm/huge_pages.hpp"
#include "fspm/memory_budget.hpp"

namespace fspm::graphics {

Eigen::Matrix4f MeshInstance::matrix() const {
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m.topLeftCorner<3, 3>() = linear;
  m.topRightCorner<3, 1>() = translation;
  return m;
}

InstancedMesh InstancedMesh::single(TriangleMesh mesh) {
  InstancedMesh out;
  out.meshes.push_back(std::move(mesh));
  out.instances.push_back(MeshInstance{});
  return out;
}

std::size_t InstancedMesh::vertex_count() const {
  std::size_t n = 0;
  for (const auto& i : instances) n += meshes[i.mesh].vertex_count();
  return n;
}

std::size_t InstancedMesh::triangle_count() const {
  std::size_t n = 0;
  for (const auto& i : instances) n += meshes[i.mesh].triangle_count();
  return n;
}

std::size_t InstancedMesh::stored_vertex_count() const {
  std::size_t n = 0;
  for (const auto& m : meshes) n += m.vertex_count();
  return n;
}

std::size_t InstancedMesh::stored_triangle_count() const {
  std::size_t n = 0;
  for (const auto& m : meshes) n += m.triangle_count();
  return n;
}

void InstancedMesh::bounds(Eigen::Vector3f& lo, Eigen::Vector3f& hi) const {
  lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::infinity());
  hi = -lo;
  for (const auto& inst : instances) {
    for (const auto& p : meshes[inst.mesh].positions) {
      const Eigen::Vector3f q = inst.linear * p + inst.translation;
      lo = lo.cwiseMin(q);
      hi = hi.cwiseMax(q);
    }
  }
  if (!(lo.x() <= hi.x())) lo = hi = Eigen::Vector3f::Zero();
}

namespace {

// Per mesh, the index of each output attribute column in the mesh's attributes (-1: absent, the
// column holds 0 there).
std::vector<std::vector<int>> attribute_columns(const std::vector<TriangleMesh>& meshes,
                                                const std::vector<std::string>& names) {
  std::vector<std::vector<int>> columns(meshes.size(), std::vector<int>(names.size(), -1));
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    for (std::size_t c = 0; c < names.size(); ++c) {
      for (std::size_t a = 0; a < meshes[m].attributes.size(); ++a) {
        if (meshes[m].attributes[a].name == names[c]) columns[m][c] = static_cast<int>(a);
      }
    }
  }
  return columns;
}

// Appends one instance's placed positions and normals to `out` (its columns reserved).
void append_placed_vertices(const MeshInstance& inst, const TriangleMesh& m, TriangleMesh& out) {
  for (const auto& p : m.positions) out.positions.push_back(inst.linear * p + inst.translation);
  if (out.normals.capacity() > 0) {
    for (const auto& n : m.normals) out.normals.push_back((inst.linear * n).normalized());
  }
}

// Appends one instance's texture coordinates, triangles (its first vertex at `offset`),
// materials and attributes to `out` (its columns reserved); returns the next instance's offset.
std::uint32_t append_instance_rest(const MeshInstance& inst, const TriangleMesh& m,
                                   const std::vector<int>& columns, std::uint32_t offset,
                                   TriangleMesh& out) {
  const auto next = static_cast<std::uint32_t>(offset + m.vertex_count());
  if (out.uvs.capacity() > 0) out.uvs.insert(out.uvs.end(), m.uvs.begin(), m.uvs.end());
  for (const auto& t : m.triangles) {
    out.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  out.materials.insert(out.materials.end(), m.materials.begin(), m.materials.end());
  for (std::size_t c = 0; c < columns.size(); ++c) {
    std::vector<float>& column = out.attributes[c].values;
    if (columns[c] < 0) {
      column.resize(next, 0.0f);
      continue;
    }
    const std::vector<float>& values = m.attributes[columns[c]].values;
    if (out.attributes[c].name == kAttributeOrder) {
      for (float v : values) column.push_back(v + inst.order_offset);
    } else {
      column.insert(column.end(), values.begin(), values.end());
    }
  }
  return next;
}

}  // namespace

TriangleMesh InstancedMesh::flatten() const {
  const std::size_t nv = vertex_count(), nt = triangle_count();
  if (nv > std::numeric_limits<std::uint32_t>::max()) {
    throw ValueError("the explicit mesh would have " + std::to_string(nv) +
                     " vertices, more than 32-bit indices allow; use .glb (instanced)");
  }
  std::vector<std::string> names;
  for (const auto& m : meshes) {
    for (const auto& a : m.attributes) {
      if (std::find(names.begin(), names.end(), a.name) == names.end()) names.push_back(a.name);
    }
  }
  check_memory(TriangleMesh::bytes_for(nv, nt, names.size()),
               "the explicit mesh of " + std::to_string(instances.size()) + " instances");
  // Normals and texture coordinates only when every placed mesh has them for every vertex: a
  // column with gaps would put them on the wrong vertices.
  bool normals = true, uvs = true;
  for (const auto& inst : instances) {
    const TriangleMesh& m = meshes[inst.mesh];
    normals = normals && m.normals.size() == m.vertex_count();
    uvs = uvs && m.uvs.size() == m.vertex_count();
  }
  // Columns reserved and backed by huge pages, then appended to (no zero fill): hundreds of
  // megabytes of fresh memory fault in a few hundred times instead of tens of thousands.
  TriangleMesh out;
  auto reserve = [](auto& column, std::size_t n) {
    column.reserve(n);
    advise_huge_pages(column.data(), n * sizeof(column[0]));
  };
  reserve(out.positions, nv);
  if (normals) reserve(out.normals, nv);
  if (uvs) reserve(out.uvs, nv);
  reserve(out.triangles, nt);
  reserve(out.materials, nt);
  for (const auto& name : names) {
    out.attributes.push_back({name, {}});
    reserve(out.attributes.back().values, nv);
  }
  const std::vector<std::vector<int>> columns = attribute_columns(meshes, names);
  // Two tasks on columns of their own, each appending in instance order (the same mesh on any
  // number of threads): the placed positions and normals, and everything else. The columns are
  // memory-bound; two cores write them nearly twice as fast.
  tbb::parallel_invoke(
      [&] {
        for (const auto& inst : instances) append_placed_vertices(inst, meshes[inst.mesh], out);
      },
      [&] {
        std::uint32_t offset = 0;
        for (const auto& inst : instances) {
          offset = append_instance_rest(inst, meshes[inst.mesh], columns[inst.mesh], offset, out);
        }
      });
  return out;
}

namespace {

// The prototype with a zero-length internode stub on every node a child grows from: the mesher
// then ends its tubes there, as it does in the explicit tree where the child's first internode
// is a second child of that node. Stubs have no segment, so they add no geometry.
TreeGraph with_attach_stubs(const InstancedTree& tree, const InstancedTree::Prototype& p) {
  TreeGraph g = p.geometry;
  // A stub is born with the earliest internode-rooted child on its node, so the growth filter
  // (max_birth_time) keeps it exactly when the explicit tree keeps a second child there.
  std::vector<double> birth(g.size(), std::numeric_limits<double>::infinity());
  for (const auto& c : p.children) {
    const TreeGraph& child = tree.prototypes[c.prototype].geometry;
    if (c.attach == kNoNode || child.empty() || child.kind(0) != OrganKind::kInternode) continue;
    birth[c.attach] = std::min(birth[c.attach], child.birth_time(0));
  }
  const auto n = static_cast<NodeId>(g.size());
  for (NodeId a = 0; a < n; ++a) {
    if (std::isinf(birth[a])) continue;
    NodeData d;
    d.start = d.end = g.end(a);
    d.direction = g.direction(a);
    d.length = 0.0;
    d.radius = g.radius(a);
    d.birth_time = std::max(birth[a], g.birth_time(a));
    d.physiological_age = g.physiological_age(a);
    d.order = g.order(a);
    d.kind = OrganKind::kInternode;
    g.add_node(a, d);
  }
  return g;
}

}  // namespace

InstancedMesh mesh_instanced(const InstancedTree& tree, const MeshOptions& options) {
  InstancedMesh out;
  const std::size_t np = tree.prototypes.size();
  if (np == 0) return out;
  check_instanced_tree(tree);
  MeshOptions o = options;
  o.camera_m.reset();
  if (std::isinf(o.max_birth_time)) {
    // The "age" attribute is measured from the latest birth of the whole plant, as in the
    // explicit mesh, not of each prototype.
    double latest = -std::numeric_limits<double>::infinity();
    for (const auto& p : tree.prototypes) {
      for (double b : p.geometry.birth_times()) latest = std::max(latest, b);
    }
    if (!std::isinf(latest)) o.max_birth_time = latest;
  }
  const bool stubs = o.junctions == JunctionMode::kSeparate;
  out.meshes.reserve(np);
  for (const auto& p : tree.prototypes) {
    out.meshes.push_back(stubs && !p.children.empty() ? mesh_tree(with_attach_stubs(tree, p), o)
                                                      : mesh_tree(p.geometry, o));
  }

  // Occurrences, parents first; the root prototype stands at the origin.
  struct Item {
    std::uint32_t prototype;
    Eigen::Matrix3d rotation;
    Eigen::Vector3d translation;
    float order;
  };
  std::vector<Item> queue{{0, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), 0.0f}};
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const Item item = queue[head];
    const auto& p = tree.prototypes[item.prototype];
    // Children of a node born after max_birth_time are filtered with it in the explicit tree.
    if (!out.meshes[item.prototype].empty()) {
      MeshInstance inst;
      inst.mesh = item.prototype;
      inst.linear = item.rotation.cast<float>();
      inst.translation = item.translation.cast<float>();
      inst.order_offset = item.order;
      out.instances.push_back(inst);
    }
    if (queue.size() + p.children.size() > kMaxInstances) {
      throw ValueError("instanced tree has more than " + std::to_string(kMaxInstances) +
                       " substructure occurrences");
    }
    for (const auto& c : p.children) {
      if (c.attach != kNoNode && p.geometry.birth_time(c.attach) > o.max_birth_time) continue;
      queue.push_back({c.prototype, item.rotation * c.rotation,
                       item.rotation * c.translation + item.translation,
                       item.order + static_cast<float>(c.order)});
    }
  }
  return out;
}

InstancedMesh place_parts(const std::vector<InstancedMesh>& parts,
                          const std::vector<PartPlacement>& placements) {
  InstancedMesh out;
  std::vector<std::uint32_t> first_mesh;
  for (const auto& part : parts) {
    first_mesh.push_back(static_cast<std::uint32_t>(out.meshes.size()));
    out.meshes.insert(out.meshes.end(), part.meshes.begin(), part.meshes.end());
  }
  std::size_t total = 0;
  for (const auto& pl : placements) {
    if (pl.part >= parts.size()) {
      throw ValueError("placement refers to part " + std::to_string(pl.part) + " of " +
                       std::to_string(parts.size()));
    }
    total += parts[pl.part].instances.size();
  }
  if (total > kMaxInstances) {
    throw ValueError("scene has " + std::to_string(total) + " instances, more than " +
                     std::to_string(kMaxInstances));
  }
  out.instances.reserve(total);
  for (const auto& pl : placements) {
    for (const auto& inst : parts[pl.part].instances) {
      MeshInstance placed = inst;
      placed.mesh = inst.mesh + first_mesh[pl.part];
      placed.linear = pl.linear * inst.linear;
      placed.translation = pl.linear * inst.translation + pl.translation;
      out.instances.push_back(placed);
    }
  }
  return out;
}

}  // namespace fspm::graphics
