#include "scan_decoding/decoding.hpp"

#include <algorithm>
#include <map>
#include <random>
#include <utility>

#include "fspm/error.hpp"
#include "graphics/stochastic_pruning.hpp"

namespace fspm::scan_decoding {

Decoding decode_clusters(const scans::ClusterModel& model, const DecodeOptions& options) {
  Decoding d;
  d.library = make_species_library(options.species.empty() ? model.species : options.species,
                                   options.library);
  std::mt19937_64 rng(options.seed);
  d.placements = texture_clusters(model, d.library, options.texture, rng);
  return d;
}

double textured_branch_length_m(const Decoding& decoding) {
  double sum = 0.0;
  for (const PlacedPatch& p : decoding.placements) {
    sum += p.scale * decoding.library.patches[p.patch].internode_length_m;
  }
  return sum;
}

namespace {

NodeData copied(const TreeGraph& t, NodeId n) {
  NodeData d;
  d.start = t.start(n);
  d.end = t.end(n);
  d.direction = t.direction(n);
  d.length = t.length(n);
  d.radius = t.radius(n);
  d.birth_time = t.birth_time(n);
  d.physiological_age = t.physiological_age(n);
  d.order = t.order(n);
  d.kind = t.kind(n);
  return d;
}

NodeData placed_node(const TreeGraph& g, NodeId n, const PlacedPatch& p, int base_order) {
  NodeData d = copied(g, n);
  d.start = p.to_world(g.start(n));
  d.end = p.to_world(g.end(n));
  d.direction = p.rotation * g.direction(n);
  d.length = p.scale * g.length(n);
  d.radius = p.scale * g.radius(n);
  d.order = static_cast<std::uint16_t>(std::min(base_order + g.order(n), 65535));
  return d;
}

// Branching order of each placement's base: one above the skeleton node or patch node it docks on.
std::vector<int> base_orders(const scans::ClusterModel& model, const Decoding& decoding) {
  std::vector<int> orders(decoding.placements.size());
  for (std::size_t k = 0; k < orders.size(); ++k) {
    const PlacedPatch& p = decoding.placements[k];
    if (p.parent == kNoPlacement) {
      orders[k] = model.skeleton.order(model.clusters[p.cluster].seed_node) + 1;
    } else {
      orders[k] = orders[p.parent] + 1;
    }
  }
  return orders;
}

}  // namespace

TreeGraph decoded_tree(const scans::ClusterModel& model, const Decoding& decoding) {
  TreeGraph out;
  std::size_t total = model.skeleton.size();
  for (const PlacedPatch& p : decoding.placements) {
    total += decoding.library.patches[p.patch].geometry.size();
  }
  out.reserve(total);
  for (NodeId n = 0; n < model.skeleton.size(); ++n) {
    out.add_node(model.skeleton.parent(n), copied(model.skeleton, n));
  }
  const std::vector<int> orders = base_orders(model, decoding);
  std::vector<NodeId> offsets(decoding.placements.size());
  for (std::size_t k = 0; k < decoding.placements.size(); ++k) {
    const PlacedPatch& p = decoding.placements[k];
    const Patch& patch = decoding.library.patches[p.patch];
    offsets[k] = static_cast<NodeId>(out.size());
    for (NodeId n = 0; n < patch.geometry.size(); ++n) {
      NodeId parent = patch.geometry.parent(n);
      if (parent != kNoNode) {
        parent += offsets[k];
      } else if (p.parent == kNoPlacement) {
        parent = model.clusters[p.cluster].seed_node;
      } else {
        const Patch& up = decoding.library.patches[decoding.placements[p.parent].patch];
        parent = offsets[p.parent] + up.dockings[p.docking].node;
      }
      out.add_node(parent, placed_node(patch.geometry, n, p, orders[k]));
    }
  }
  return out;
}

std::size_t drawn_leaves(std::size_t leaves, double distance_m, double prune_distance_m) {
  return graphics::pruned_leaf_count(leaves,
                                     graphics::pruning_fraction(distance_m, prune_distance_m));
}

namespace {

graphics::MeshOptions patch_mesh_options(const graphics::MeshOptions& bark) {
  graphics::MeshOptions o = bark;
  o.leaves = true;
  o.camera_m.reset();  // a patch's frame is not the world's
  o.max_sides = std::min(o.max_sides, kPatchMaxSides);
  o.min_sides = std::min(o.min_sides, o.max_sides);
  return o;
}

}  // namespace

void DecodeMeshOptions::validate() const {
  if (!(prune_distance_m > 0.0)) {
    throw ValueError(
        "decoded mesh: prune_distance_m (up to which every leaf is drawn) must be positive");
  }
}

graphics::InstancedMesh decoded_mesh(const scans::ClusterModel& model, const Decoding& decoding,
                                     const DecodeMeshOptions& options) {
  options.validate();
  graphics::MeshOptions skeleton_options = options.bark;
  skeleton_options.leaves = false;
  graphics::InstancedMesh out =
      graphics::InstancedMesh::single(graphics::mesh_tree(model.skeleton, skeleton_options));
  const graphics::MeshOptions patch_options = patch_mesh_options(options.bark);
  const std::vector<int> orders = base_orders(model, decoding);
  std::map<std::uint32_t, graphics::LeafBuffer> buffers;
  std::map<std::pair<std::uint32_t, std::size_t>, std::uint32_t> mesh_of;
  for (std::size_t k = 0; k < decoding.placements.size(); ++k) {
    const PlacedPatch& p = decoding.placements[k];
    auto buffer = buffers.find(p.patch);
    if (buffer == buffers.end()) {
      // Pirk 3.5.2: each patch's leaves are stored once, in a seeded random order.
      std::mt19937_64 rng(options.seed * 0x9E3779B97F4A7C15ull + p.patch);
      const graphics::TriangleMesh mesh =
          graphics::mesh_tree(decoding.library.patches[p.patch].geometry, patch_options);
      buffer = buffers.emplace(p.patch, graphics::make_leaf_buffer(mesh, rng)).first;
    }
    const std::size_t leaves = buffer->second.leaf_count();
    const std::size_t drawn = options.camera_m
                                  ? drawn_leaves(leaves, (*options.camera_m - p.translation).norm(),
                                                 options.prune_distance_m)
                                  : leaves;
    auto mesh = mesh_of.find({p.patch, drawn});
    if (mesh == mesh_of.end()) {
      out.meshes.push_back(graphics::pruned_mesh(buffer->second, drawn));
      mesh =
          mesh_of
              .emplace(std::pair{p.patch, drawn}, static_cast<std::uint32_t>(out.meshes.size() - 1))
              .first;
    }
    graphics::MeshInstance instance;
    instance.mesh = mesh->second;
    instance.linear = (p.scale * p.rotation).cast<float>();
    instance.translation = p.translation.cast<float>();
    instance.order_offset = static_cast<float>(orders[k]);
    out.instances.push_back(instance);
  }
  return out;
}

}  // namespace fspm::scan_decoding
