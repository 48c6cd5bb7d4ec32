#pragma once
// Decoding a cluster-based tree (Pirk sec. 3.4): the species library of the model's species, its
// clusters textured with patches (cluster_texturing.hpp), and the result as an explicit tree
// graph (skeleton, then every placed patch) or as an instanced mesh: the skeleton's generalized
// cylinders once, each patch's mesh stored once and placed by a rotation, uniform scale and
// translation. With a camera, each placed patch draws only a prefix of its leaves, stored in a
// seeded random order (stochastic pruning, Pirk sec. 3.5.2; Cook et al. 2007).
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "fspm/tree_graph.hpp"
#include "graphics/instanced_mesh.hpp"
#include "graphics/tree_mesher.hpp"
#include "scan_decoding/cluster_texturing.hpp"
#include "scan_decoding/species_library.hpp"
#include "scans/cluster_model.hpp"

namespace fspm::scan_decoding {

struct DecodeOptions {
  std::string species;  // empty: the model's species
  LibraryOptions library;
  TextureOptions texture;
  std::uint64_t seed = 1;  // patch choice among equally fitting ones, and its roll
};

struct Decoding {
  SpeciesLibrary library;
  std::vector<PlacedPatch> placements;  // cluster by cluster, parents before children
};

// Throws ValueError for an unknown species, bad options or a cluster hanging at no skeleton node.
Decoding decode_clusters(const scans::ClusterModel& model, const DecodeOptions& options = {});

// Summed internode length of the placed patches (scale x Patch::internode_length_m), m: what
// texturing put where the scan showed ClusterHull::branch_length_m.
double textured_branch_length_m(const Decoding& decoding);

// The skeleton (same node ids) followed by every placed patch transformed: a patch's base hangs
// from its seed node or from the node of its parent patch the docking point belongs to; radii
// and lengths scaled with the patch; branching orders continue the parent's.
TreeGraph decoded_tree(const scans::ClusterModel& model, const Decoding& decoding);

struct DecodeMeshOptions {
  // The skeleton's tubes. Patches use the same options with leaves on and at most
  // kPatchMaxSides sides: their tubes are twigs.
  graphics::MeshOptions bark;
  std::optional<Eigen::Vector3d> camera_m;  // stochastic pruning of patch leaves from here
  double prune_distance_m = 20.0;           // every leaf drawn up to this distance
  std::uint64_t seed = 1;                   // order of the leaves in each patch's buffer

  // Throws ValueError naming the first field out of range.
  void validate() const;
};

inline constexpr int kPatchMaxSides = 6;

// Leaves of a patch with `leaves` leaves drawn at `distance_m` from the camera: the share
// (prune_distance / distance)^2, rounded up, at most all (graphics/stochastic_pruning.hpp).
std::size_t drawn_leaves(std::size_t leaves, double distance_m, double prune_distance_m);

// meshes[0] is the skeleton placed once at the origin; then one mesh per (patch, drawn leaf
// count) in use, each placed by its patches' transforms. Throws ValueError for bad options.
graphics::InstancedMesh decoded_mesh(const scans::ClusterModel& model, const Decoding& decoding,
                                     const DecodeMeshOptions& options = {});

}  // namespace fspm::scan_decoding
